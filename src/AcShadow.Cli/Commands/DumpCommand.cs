using System.CommandLine;
using System.Diagnostics;
using AcShadow.Cli.Infrastructure;
using AcShadow.Core.Export;
using AcShadow.Core.Json;
using AcShadow.Core.Shapes;

namespace AcShadow.Cli.Commands;

/// <summary>`acshadow dump --setup ID`: one Setup's shadow file and the BSP dumps its shapes reference.</summary>
public static class DumpCommand
{
    public const string DefaultOut = "acshadow-out";

    public static Command Create(CliConsole console)
    {
        var setup = new Option<string>("--setup") { Description = "Setup id, e.g. 0x020019FF", HelpName = "ID", Required = true };
        var dat = CommonOptions.Dat();
        var outDir = CommonOptions.Out(DefaultOut);
        var policy = CommonOptions.Policy();
        var scale = CommonOptions.Scale();
        var format = FormatOption.Create();
        var pose = new PoseOptions();
        var command = new Command("dump", "Write one Setup's ShadowShape JSON and the BSP polygon dumps its shapes use")
        {
            setup, dat, outDir, policy, scale, format,
        };
        foreach (var option in pose.All) command.Options.Add(option);
        command.SetAction(parse => Run(console,
            ArgumentParsing.SetupId(parse.GetValue(setup)!),
            parse.GetValue(dat),
            parse.GetValue(outDir)!,
            pose.Apply(parse, new ShapeBuildOptions(ArgumentParsing.Policy(parse.GetValue(policy)), ArgumentParsing.Scale(parse.GetValue(scale)))),
            FormatOption.Parse(parse.GetValue(format))));
        return command;
    }

    private static int Run(CliConsole console, uint setupId, string? datPath, string outDir, ShapeBuildOptions options, OutputFormats formats)
    {
        var clock = Stopwatch.StartNew();
        using var dat = DatLocator.Open(datPath, null, console);
        var engine = new ExportEngine(dat.Portal, options);
        var export = engine.ExportSetup(setupId)
            ?? throw new CliException(ExitCodes.NotInDat, $"Setup {JsonIds.Format(setupId)} is not in {dat.Description}: check the id (`acshadow audit --all` lists every Setup the dat has)");

        DiagnosticPrinter.Print(console.Error, JsonIds.Format(setupId), export.Diagnostics);
        var files = OutputFormatSelection.Apply(export.Files, formats).ToArray();
        OutputFolder.Prepare(outDir);
        OutputFolder.RefuseForeignFiles(outDir, files.Select(f => (f.RelativePath, f.Content)));
        long bytes = 0;
        foreach (var file in files)
        {
            // A file already holding these exact bytes is left alone: no rewrite, its timestamp kept (build
            // tools and git see no change), and no replace-by-rename (a new inode, the old one freed).
            if (OutputFolder.IsUnchanged(outDir, file.RelativePath, file.Content.Span))
                console.Out.WriteLine($"unchanged {Path.Combine(outDir, file.RelativePath)} ({file.Content.Length} bytes, already these bytes)");
            else
            {
                OutputFolder.WriteAtomically(outDir, file);
                console.Out.WriteLine($"wrote {Path.Combine(outDir, file.RelativePath)} ({file.Content.Length} bytes)");
            }
            bytes += file.Content.Length;
        }
        var set = export.Set;
        console.Out.WriteLine(
            $"dump {JsonIds.Format(setupId)}: {set.Shapes.Count} shape(s) under {set.Policy.Name()} " +
            $"({PoseSummary.Describe(set)}), {export.BspFiles.Count} BSP dump(s){(formats == OutputFormats.Canonical ? "" : $" (--format {formats.Name()})")}, {export.Diagnostics.Count} diagnostic(s), " +
            $"{bytes} bytes in {clock.Elapsed.TotalSeconds:0.000} s");
        return ExitCodes.Ok;
    }
}
