using System.CommandLine;
using System.Text;
using AcShadow.Analysis.Audit;
using AcShadow.Analysis.Chart;
using AcShadow.Cli.Infrastructure;
using AcShadow.Cli.Output;
using AcShadow.Cli.Terminal;

namespace AcShadow.Cli.Commands;

/// <summary>
/// `acshadow audit [selection]`: one row per Setup saying which shape family retail uses, whether the
/// HasPhysicsBSP flag agrees with the parts, and how badly the Radius×Height fallback covers a BSP
/// footprint. Default selection: every Setup in the dat.
/// </summary>
public static class AuditCommand
{
    public static Command Create(CliConsole console)
    {
        var selection = new SelectionOptions();
        var dat = CommonOptions.Dat();
        var format = ValueOptions.Single("--format", "table|csv|json|md", "table (default on stdout), csv, json or md (default for --out: from its extension)", ParseFormat);
        var outFile = new Option<string?>("--out") { Description = "write the report to FILE instead of stdout", HelpName = "FILE" };
        var onlyBsp = new Option<bool>("--only-bsp") { Description = "only Setups with a BSP-bearing part" };
        var flagMismatch = new Option<bool>("--flag-mismatch") { Description = "only Setups whose HasPhysicsBSP flag disagrees with their parts" };
        var maxCoverage = new NumberRule<double>("a fraction", "use a number from 0 to 1, e.g. 0.1") { From = 0, To = 1 }
            .Option("--max-coverage", "X", "only Setups whose fallback cylinder covers at most X (0..1) of the BSP footprint");
        var sort = ValueOptions.Text("--sort", "FIELD", $"sort by a column ({string.Join(", ", AuditColumns.WithChart.Select(c => c.Key))}); prefix - for descending", ParseSort);
        var chart = new Option<bool>("--chart") { Description = "also run the collision chart per Setup: which shape models are exact, and the cheapest (slow)" };
        var jobs = SelectionOptions.Jobs();
        var pose = new PoseOptions();
        var poseDiffers = new Option<bool>("--pose-differs") { Description = "only Setups whose retail pose differs from their placement pose (a part moved more than 1 mm or 0.1 deg)" };
        var command = new Command("audit", "Which Setups have BSP-bearing parts, and where a simpler shape model lies")
        {
            dat, selection.CellDat, selection.Doors, selection.All, selection.Setups, selection.Landblock,
            format, outFile, onlyBsp, flagMismatch, maxCoverage, sort, chart, jobs, poseDiffers,
        };
        foreach (var option in pose.All) command.Options.Add(option);
        command.SetAction(parse =>
        {
            var query = new AuditQuery(parse.GetValue(onlyBsp), parse.GetValue(flagMismatch),
                parse.GetValue(maxCoverage), parse.GetValue(sort) ?? "id") { PoseDiffers = parse.GetValue(poseDiffers) };
            var poseOptions = pose.Apply(parse, new Core.Shapes.ShapeBuildOptions(Fixtures.Shapes.ShapePolicy.Retail));
            var output = parse.GetValue(outFile);
            return Run(console, selection.Parse(parse, defaultToAll: true), parse.GetValue(dat), parse.GetValue(selection.CellDat),
                query, parse.GetValue(format) ?? DefaultFormat(output), output, SelectionOptions.WorkersOrAllCores(parse, jobs), parse.GetValue(chart), poseOptions);
        });
        return command;
    }

    private static int Run(CliConsole console, Core.Batch.BatchSelection selection, string? datPath, string? cellPath,
        AuditQuery query, AuditFormat format, string? output, int jobs, bool chart, Core.Shapes.ShapeBuildOptions pose)
    {
        if (output is not null) ExplicitOutputFile.Check(output, "audit.csv");
        using var dat = DatLocator.Open(datPath, cellPath, console, wholeDirectory: true);
        if (output is not null) ExplicitOutputFile.RefuseInput(output, dat, "audit.csv");
        var plan = SelectionOptions.Plan(selection, dat);
        PoseOptions.RequireUsable(pose, dat.Portal, plan.Setups.Select(s => s.Id).ToArray());
        var progress = new ProgressReporter(console.Error, console.IsTerminal, quiet: !chart, "setups charted", "audit");
        AuditReport report;
        try
        {
            report = AuditRunner.Run(dat.Portal, plan, query, jobs, chart ? new ChartOptions() : null, progress.Report, pose);
        }
        finally
        {
            progress.Finish();
        }
        var text = AuditWriter.Write(report, format, dat.Portal.Info, selection);
        if (output is null)
        {
            console.Out.Write(text);
            if (format == AuditFormat.Csv) console.Error.Write(AuditWriter.SummaryText(report));
            return ExitCodes.Ok;
        }
        dat.RequireUnchanged();
        ExplicitOutputFile.Write(output, new UTF8Encoding(false).GetBytes(text));
        console.Out.Write(AuditWriter.SummaryText(report));
        console.Out.WriteLine($"wrote {output} ({format.ToString().ToLowerInvariant()}, {report.Rows.Count} row(s))");
        return ExitCodes.Ok;
    }

    /// <summary>With no --format: a table on stdout, else the --out file's extension says.</summary>
    private static AuditFormat DefaultFormat(string? output) =>
        output is null ? AuditFormat.Table : AuditFormats.FromExtension(output) ?? AuditFormat.Table;

    private static AuditFormat ParseFormat(string text) =>
        AuditFormats.TryParse(text, out var format) ? format
            : throw new CliException(ExitCodes.Usage, $"--format: '{text}' is not a format: use table, csv, json or md");

    private static string ParseSort(string text) =>
        AuditColumns.Find(text.TrimStart('-', '+')) is not null ? text
            : throw new CliException(ExitCodes.Usage, $"--sort: '{text}' is not a column: use one of {string.Join(", ", AuditColumns.WithChart.Select(c => c.Key))} (prefix - for descending)");
}
