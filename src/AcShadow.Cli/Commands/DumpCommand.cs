using System.CommandLine;
using System.Diagnostics;
using AcShadow.Cli.Infrastructure;
using AcShadow.Cli.Output;
using AcShadow.Core.Batch;
using AcShadow.Core.Cells;
using AcShadow.Core.Dat;
using AcShadow.Core.Export;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Core.Scenes;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Cli.Commands;

/// <summary>
/// `acshadow dump --setup ID`: one Setup's shadow file and the BSP dumps its shapes reference.
/// `acshadow dump --cell ID`: one indoor cell's file, with the files of the objects placed in it.
/// </summary>
public static class DumpCommand
{
    public const string DefaultOut = "acshadow-out";

    public static Command Create(CliConsole console)
    {
        var setup = ValueOptions.Single("--setup", "ID", "Setup id, e.g. 0x020019FF", text => ArgumentParsing.SetupId(text));
        var cell = ValueOptions.Single("--cell", "ID", "an indoor cell (EnvCell) id instead, e.g. 0xA9B40100 (needs the cell dat)", CellId);
        var cellDat = new Option<string?>("--cell-dat") { Description = "client_cell_1.dat (or its folder) for --cell", HelpName = "PATH" };
        var dat = CommonOptions.Dat();
        var outDir = CommonOptions.Out(DefaultOut);
        var policy = CommonOptions.Policy();
        var scale = CommonOptions.Scale();
        var format = FormatOption.Create();
        var pose = new PoseOptions();
        var command = new Command("dump", "Write one Setup's ShadowShape JSON and the BSP polygon dumps its shapes use (or one indoor cell's file)")
        {
            setup, cell, dat, cellDat, outDir, policy, scale, format,
        };
        foreach (var option in pose.All) command.Options.Add(option);
        command.SetAction(parse =>
        {
            var options = pose.Apply(parse, new ShapeBuildOptions(parse.GetValue(policy) ?? ShapePolicy.Retail, parse.GetValue(scale) ?? 1f));
            var formats = parse.GetValue(format) ?? OutputFormats.Canonical;
            var (setupId, cellId) = (parse.GetValue(setup), parse.GetValue(cell));
            if ((setupId is null) == (cellId is null))
                throw new CliException(ExitCodes.Usage, "dump: give exactly one of --setup ID and --cell ID");
            return setupId is { } id
                ? Run(console, id, parse.GetValue(dat), parse.GetValue(outDir)!, options, formats)
                : RunCell(console, cellId!.Value, parse.GetValue(dat), parse.GetValue(cellDat), parse.GetValue(outDir)!, options, formats);
        });
        return command;
    }

    private static uint CellId(string text)
    {
        if (!JsonIds.TryParse(text, out var id))
            throw new CliException(ExitCodes.Usage, $"--cell: '{text}' is not a cell id: write it in hex, e.g. 0xA9B40100");
        // A bare 0xXXYY is a landblock: its indoor cells are 0xXXYY0100 and up.
        if (id is > 0 and <= 0xFFFF)
            throw new CliException(ExitCodes.Usage, $"--cell: {text} is a landblock id (0xXXYY), not a cell's: its indoor cells are 0x{id:X4}0100 and up (e.g. --cell 0x{id:X4}0100); for the whole landblock use batch, scene or view --landblock 0x{id:X4}");
        if (!DatObjectKind.EnvCell.Contains(id))
            throw new CliException(ExitCodes.Usage, $"--cell: 0x{id:X8} is not an indoor cell id: indoor cells are {DatObjectKind.EnvCell.RangeText()} (0xXXYY0001-0xXXYY0040 are outdoor land cells, which have no EnvCell)");
        return id;
    }

    /// <summary>The cell's file, and the shadow files and BSP dumps of what is placed inside it, so its references resolve.</summary>
    private static int RunCell(CliConsole console, uint cellId, string? datPath, string? cellDatPath, string outDir, ShapeBuildOptions options, OutputFormats formats)
    {
        var clock = Stopwatch.StartNew();
        OutputFolder.Check(outDir);
        using var dat = DatLocator.Open(datPath, cellDatPath, console);
        var cells = dat.Cell ?? throw new CliException(ExitCodes.Usage, $"--cell {JsonIds.Format(cellId)}: pass --cell-dat PATH (client_cell_1.dat) with --dat");
        var envCell = cells.ReadEnvCell(cellId)
            ?? throw new CliException(ExitCodes.NotInDat, $"EnvCell {JsonIds.Format(cellId)} is not in {cells.Info.FileName}: check the id (a landblock's cells are 0xXXYY0100 up to its LandBlockInfo's cell count)");
        var engine = new ExportEngine(dat.Portal, options);
        var files = new List<OutputFile>();
        var setupFiles = new Dictionary<uint, string>();
        var problems = new Dictionary<uint, string>();
        foreach (var id in envCell.StaticObjects.Select(s => s.Id).Where(id => DatObjectKind.Setup.Contains(id)).Distinct().Order())
        {
            var export = engine.ExportSetup(id);
            if (export is null) { problems[id] = SkippedItem.NotInDat; continue; }
            files.AddRange(export.Files);
            setupFiles[id] = FileFormats.Shadow.PathFor(id);
        }
        var scene = new LandblockScene((cellId & 0xFFFF0000u) | 0xFFFE, []);
        var cellExport = new CellExporter(engine).Export(envCell, scene, setupFiles, problems);
        var cellFile = cellExport.File
            ?? throw new CliException(ExitCodes.NotInDat, cellExport.Diagnostics[0].Message);
        DiagnosticPrinter.Print(console.Error, JsonIds.Format(cellId), cellExport.Diagnostics);
        files.Add(cellFile);
        files.AddRange(cellExport.BspFiles);
        var bytes = Write(console, outDir, dat, OutputFormatSelection.Apply(files.DistinctBy(f => f.RelativePath), formats).ToArray());
        console.Out.WriteLine(
            $"dump {JsonIds.Format(cellId)}: cell structure {envCell.CellStructure} of {JsonIds.Format(envCell.EnvironmentFileId)}, {cellFile.Listing!.PolygonCount} physics polygon(s), " +
            $"{envCell.Portals.Count} portal(s), {envCell.StaticObjects.Count} object(s) inside{(formats == OutputFormats.Canonical ? "" : $" (--format {formats.Name()})")}, " +
            $"{cellExport.Diagnostics.Count} diagnostic(s), {bytes} bytes in {clock.Elapsed.TotalSeconds:0.000} s");
        return ExitCodes.Ok;
    }

    private static int Run(CliConsole console, uint setupId, string? datPath, string outDir, ShapeBuildOptions options, OutputFormats formats)
    {
        var clock = Stopwatch.StartNew();
        OutputFolder.Check(outDir);
        using var dat = DatLocator.Open(datPath, null, console);
        var engine = new ExportEngine(dat.Portal, options);
        var export = engine.ExportSetup(setupId)
            ?? throw new CliException(ExitCodes.NotInDat, $"Setup {JsonIds.Format(setupId)} is not in {dat.Description}: check the id (`acshadow audit --all` lists every Setup the dat has)");
        PoseOptions.RequireUsable(options, dat.Portal, [setupId]);

        DiagnosticPrinter.Print(console.Error, JsonIds.Format(setupId), export.Diagnostics);
        var bytes = Write(console, outDir, dat, OutputFormatSelection.Apply(export.Files, formats).ToArray());
        var set = export.Set;
        console.Out.WriteLine(
            $"dump {JsonIds.Format(setupId)}: {set.Shapes.Count} shape(s) under {set.Policy.Name()} " +
            $"({PoseSummary.Describe(set)}), {export.BspFiles.Count} BSP dump(s){(formats == OutputFormats.Canonical ? "" : $" (--format {formats.Name()})")}, {export.Diagnostics.Count} diagnostic(s), " +
            $"{bytes} bytes in {clock.Elapsed.TotalSeconds:0.000} s");
        return ExitCodes.Ok;
    }

    private static long Write(CliConsole console, string outDir, OpenedDat dat, IReadOnlyList<OutputFile> files)
    {
        using var folder = OutputFolder.Open(outDir, dat);
        folder.RefuseForeign(files);
        var bytes = folder.WriteEach(files, console.Out, console.Interrupted);
        folder.RequireStillInPlace();
        return bytes;
    }
}
