using System.CommandLine;
using System.Diagnostics;
using System.Reflection;
using AcShadow.Analysis.Doctor;
using AcShadow.Cli.Infrastructure;
using AcShadow.Cli.Output;
using AcShadow.Fixtures.Formats;

namespace AcShadow.Cli.Commands;

/// <summary>
/// `acshadow doctor`: checks, on the user's own dat, every assumption acshadow rests on, and prints a
/// verdict per check; `--out` writes the JSON report. Both hold ids, counts, hashes and verdicts only, so
/// they can be pasted into a bug report. Exit 0 whatever the verdicts: a check that differs is a finding,
/// not a failure of the run.
/// </summary>
public static class DoctorCommand
{
    private const string Example = "doctor.json";

    public static Command Create(CliConsole console)
    {
        var dat = CommonOptions.Dat();
        var cellDat = new Option<string?>("--cell-dat") { Description = "client_cell_1.dat (or its folder): its LandBlockInfos are read too", HelpName = "PATH" };
        var outFile = new Option<string?>("--out") { Description = "write the JSON report (acshadow.doctor/1) to FILE", HelpName = "FILE" };
        var jobs = SelectionOptions.Jobs();
        var command = new Command("doctor", "Check every assumption acshadow makes on your dat: a report of ids, counts and verdicts to share")
        {
            dat, cellDat, outFile, jobs,
        };
        command.SetAction(parse => Run(console, parse.GetValue(dat), parse.GetValue(cellDat), parse.GetValue(outFile),
            SelectionOptions.WorkersOrAllCores(parse, jobs)));
        return command;
    }

    private static int Run(CliConsole console, string? datPath, string? cellPath, string? output, int jobs)
    {
        if (output is not null) ExplicitOutputFile.Check(output, Example);
        using var dat = DatLocator.Open(datPath, cellPath, console, wholeDirectory: true);
        if (output is not null) ExplicitOutputFile.RefuseInput(output, dat, Example);
        var options = new DoctorOptions(jobs, ToolVersion(), PeakMemory);
        var report = DoctorRunner.Run(dat.Portal.Archive, dat.Cell?.Archive, options);
        console.Out.Write(DoctorReportWriter.Summary(report, dat.IsSample ? "the built-in synthetic sample" : "your dat"));
        if (output is null) return ExitCodes.Ok;
        ExplicitOutputFile.Write(output, DoctorReportWriter.Json(report), Example);
        console.Out.WriteLine($"wrote {output} ({FileFormats.Doctor.Format}: ids, counts, hashes and verdicts only)");
        return ExitCodes.Ok;
    }

    /// <summary>The process's peak resident memory so far (Linux VmHWM, the Windows peak working set).</summary>
    private static long PeakMemory()
    {
        using var process = Process.GetCurrentProcess();
        return process.PeakWorkingSet64;
    }

    private static string ToolVersion()
    {
        var informational = typeof(DoctorCommand).Assembly.GetCustomAttribute<AssemblyInformationalVersionAttribute>()?.InformationalVersion ?? "unknown";
        var plus = informational.IndexOf('+');
        return plus < 0 ? informational : informational[..plus];
    }
}
