using System.CommandLine;
using System.Diagnostics;
using AcShadow.Cli.Infrastructure;
using AcShadow.Cli.Output;
using AcShadow.Core.Batch;
using AcShadow.Core.Catalog;
using AcShadow.Core.Export;
using AcShadow.Core.Movement;
using AcShadow.Core.Poses;
using AcShadow.Forging;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Movement;

namespace AcShadow.Cli.Commands;

/// <summary>
/// `acshadow move --setup ID [--mover ID] [--state closed|open] --out DIR` (or --doors, --setups FILE): each
/// object Setup's golden movement cases (docs/movement.md), one movement file per Setup plus the BSP dumps its
/// shapes name. On the sample the mover defaults to its forged person; a real dat needs --mover.
/// </summary>
public static class MoveCommand
{
    public static Command Create(CliConsole console)
    {
        var setup = new Option<string?>("--setup") { Description = "the object's Setup id, e.g. 0x020019FF", HelpName = "ID" };
        var doors = new Option<bool>("--doors") { Description = "every Setup of the built-in door catalog the dat has" };
        var setups = new Option<string?>("--setups") { Description = "a file of Setup ids, one a line, '#' comments", HelpName = "FILE" };
        var mover = MoverOption();
        var state = new Option<string?>("--state") { Description = "a door's state: closed or open (default: both)", HelpName = "closed|open" };
        var dat = CommonOptions.Dat();
        var outDir = CommonOptions.Out(DumpCommand.DefaultOut);
        var jobs = SelectionOptions.Jobs();
        var command = new Command("move", "Write golden movement cases: a mover walking against an object, as retail's transition moves it")
        {
            setup, doors, setups, mover, state, dat, outDir, jobs,
        };
        command.SetAction(parse => Run(console, parse.GetValue(setup), parse.GetValue(doors), parse.GetValue(setups), parse.GetValue(mover),
            States(parse.GetValue(state)), parse.GetValue(dat), parse.GetValue(outDir)!, SelectionOptions.ParseJobs(parse.GetValue(jobs))));
        return command;
    }

    public static Option<string?> MoverOption() => new("--mover") { Description = "the mover's Setup id (default on the sample: its forged person 0x02001100; required on a real dat)", HelpName = "ID" };

    /// <summary>batch's `--movement IDS`: the object Setups whose movement cases a batch adds.</summary>
    public static Option<string?> MovementOption() => new("--movement")
    {
        Description = "also write these objects' movement cases (comma-separated Setup ids, e.g. 0x020019FF) into movement/, listed in index.json",
        HelpName = "IDS",
    };

    /// <summary>What `--movement IDS [--mover ID]` selects (null without --movement); the mover must be in the dat.</summary>
    public static MovementSelection? Selection(string? ids, string? moverText, OpenedDat dat)
    {
        if (ids is null)
        {
            if (moverText is not null) throw new CliException(ExitCodes.Usage, "--mover applies to --movement: add --movement IDS");
            return null;
        }
        var setups = ids.Split(',', StringSplitOptions.TrimEntries | StringSplitOptions.RemoveEmptyEntries)
            .Select(t => ArgumentParsing.SetupId(t, "--movement")).Distinct().Order().ToArray();
        if (setups.Length == 0) throw new CliException(ExitCodes.Usage, "--movement: give one or more Setup ids, comma-separated, e.g. 0x020019FF");
        var mover = MoverId(moverText, dat);
        if (MoverSetup.Read(dat.Portal, mover) is null)
            throw new CliException(ExitCodes.NotInDat, $"--mover: Setup {JsonIds.Format(mover)} is not in {dat.Description}: check the id");
        return new MovementSelection(setups, mover);
    }

    private static uint MoverId(string? text, OpenedDat dat) => text is not null ? ArgumentParsing.SetupId(text, "--mover")
        : dat.IsSample ? SampleSpecAuthor.MoverSetup
        : throw new CliException(ExitCodes.Usage, "pass --mover ID, the Setup of the character that walks (a real dat has no default mover: docs/movement.md)");

    private static IReadOnlyList<DoorState>? States(string? text) => text switch
    {
        null => null,
        "closed" => [DoorState.Closed],
        "open" => [DoorState.Open],
        _ => throw new CliException(ExitCodes.Usage, $"--state: '{text}' is not a door state: use closed or open"),
    };

    private static int Run(CliConsole console, string? setupText, bool doors, string? setupsFile, string? moverText,
        IReadOnlyList<DoorState>? states, string? datPath, string outDir, int jobs)
    {
        var clock = Stopwatch.StartNew();
        if ((setupText is null ? 0 : 1) + (doors ? 1 : 0) + (setupsFile is null ? 0 : 1) != 1)
            throw new CliException(ExitCodes.Usage, "move: give exactly one of --setup ID, --doors and --setups FILE");
        var single = setupText is null ? (uint?)null : ArgumentParsing.SetupId(setupText);
        if (moverText is not null) ArgumentParsing.SetupId(moverText, "--mover");
        var list = setupsFile is null ? null : SelectionOptions.ReadSetupList(setupsFile);
        OutputPaths.RequireNamed(outDir);
        using var dat = DatLocator.Open(datPath, null, console);
        var moverSetup = MoverId(moverText, dat);
        var walker = MoverSetup.Read(dat.Portal, moverSetup)
            ?? throw new CliException(ExitCodes.NotInDat, $"--mover: Setup {JsonIds.Format(moverSetup)} is not in {dat.Description}: check the id");
        IReadOnlyList<uint> ids;
        if (single is { } id)
        {
            if (dat.Portal.ReadSetup(id) is null)
                throw new CliException(ExitCodes.NotInDat, $"Setup {JsonIds.Format(id)} is not in {dat.Description}: check the id (`acshadow audit --all` lists every Setup the dat has)");
            ids = [id];
        }
        else
        {
            var plan = BatchPlanner.Plan(new BatchSelection(doors, false, list, null), dat.Portal, null, DoorCatalog.SetupIds);
            foreach (var skipped in plan.Skipped) console.Error.WriteLine($"acshadow: skipped {JsonIds.Format(skipped.Id)}: {skipped.Reason}");
            ids = plan.Setups.Select(s => s.Id).ToArray();
        }

        long bytes = 0;
        var cases = 0;
        foreach (var objectId in ids)
        {
            console.Interrupted.ThrowIfCancellationRequested();
            var generated = MovementSuiteBuilder.Build(dat.Portal, objectId, moverSetup, walker, DoorCatalog.Find(objectId) is not null, states, jobs, console.Interrupted);
            bytes += DumpCommand.Write(console, outDir, MovementExport.Files(generated));
            cases += generated.Suite.Cases.Count;
            console.Out.WriteLine($"move {JsonIds.Format(objectId)}: {Summary(generated.Suite)}");
        }
        console.Out.WriteLine($"move: {ids.Count} object(s), {cases} case(s), mover {JsonIds.Format(moverSetup)}, {bytes} bytes in {clock.Elapsed.TotalSeconds:0.000} s");
        return ExitCodes.Ok;
    }

    /// <summary>"616 case(s): 300 blocked, 316 reached; 4 fragile".</summary>
    private static string Summary(MovementSuite suite)
    {
        var classes = suite.Cases.GroupBy(c => c.Outcome.Class).OrderBy(g => g.Key, StringComparer.Ordinal).Select(g => $"{g.Count()} {g.Key}");
        return $"{suite.Cases.Count} case(s) in {string.Join(", ", suite.Objects.Keys)}: {string.Join(", ", classes)}; {suite.Cases.Count(c => c.Fragile)} fragile";
    }
}
