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
        var setup = ValueOptions.Single("--setup", "ID", "the object's Setup id, e.g. 0x020019FF", text => ArgumentParsing.SetupId(text));
        var doors = new Option<bool>("--doors") { Description = "every Setup of the built-in door catalog the dat has" };
        var setups = new Option<string?>("--setups") { Description = "a file of Setup ids, one a line, '#' comments", HelpName = "FILE" };
        var mover = MoverOption();
        var state = new PoseOptions().State;
        state.Description = "a door's state: closed or open (default: both)";
        var dat = CommonOptions.Dat();
        var outDir = CommonOptions.Out(DumpCommand.DefaultOut);
        var jobs = SelectionOptions.Jobs();
        var command = new Command("move", "Write golden movement cases: a mover walking against an object, as retail's transition moves it")
        {
            setup, doors, setups, mover, state, dat, outDir, jobs,
        };
        command.SetAction(parse => Run(console, parse.GetValue(setup), parse.GetValue(doors), parse.GetValue(setups), parse.GetValue(mover),
            parse.GetValue(state) is { } one ? [one] : null, parse.GetValue(dat), parse.GetValue(outDir)!, SelectionOptions.WorkersOrAllCores(parse, jobs)));
        return command;
    }

    public static Option<uint?> MoverOption() => ValueOptions.Single("--mover", "ID",
        "the mover's Setup id (default on the sample: its forged person 0x02001100; required on a real dat)", text => ArgumentParsing.SetupId(text, "--mover"));

    /// <summary>batch's `--movement ID` (repeatable): the object Setups whose movement cases a batch adds.</summary>
    public static Option<uint[]> MovementOption() => ValueOptions.Repeated("--movement", "ID",
        "also write this object's movement cases into movement/, listed in index.json (repeatable)", text => ArgumentParsing.SetupId(text, "--movement"));

    /// <summary>What `--movement ID… [--mover ID]` selects (null without --movement); the mover must be in the dat.</summary>
    public static MovementSelection? Selection(IReadOnlyList<uint> setups, uint? moverId, OpenedDat dat)
    {
        if (setups.Count == 0)
        {
            if (moverId is not null) throw new CliException(ExitCodes.Usage, "--mover applies to --movement: add --movement ID");
            return null;
        }
        var mover = MoverId(moverId, dat);
        RequireMover(mover, dat);
        return new MovementSelection([.. setups.Distinct().Order()], mover);
    }

    /// <summary>The mover `--mover ID` names (on the sample, its forged person by default), read from the dat.</summary>
    public static (uint Id, Mover Mover) Mover(uint? id, OpenedDat dat)
    {
        var setup = MoverId(id, dat);
        return (setup, RequireMover(setup, dat));
    }

    /// <summary>The mover --mover names, the sample's person on the sample, else (Id null) the standard human (MoverSetup.StandardHuman).</summary>
    public static (uint? Id, Mover Mover) MoverOrStandard(uint? id, OpenedDat dat) =>
        id is null && !dat.IsSample ? (null, MoverSetup.StandardHuman) : Mover(id, dat);

    private static uint MoverId(uint? id, OpenedDat dat) => id ?? (dat.IsSample ? SampleDats.MoverSetup
        : throw new CliException(ExitCodes.Usage, "pass --mover ID, the Setup of the character that walks (a real dat has no default mover: docs/movement.md)"));

    private static Mover RequireMover(uint id, OpenedDat dat) => MoverSetup.Read(dat.Portal, id)
        ?? throw new CliException(ExitCodes.NotInDat, $"--mover: Setup {JsonIds.Format(id)} is not in {dat.Description}: check the id");

    private static int Run(CliConsole console, uint? single, bool doors, string? setupsFile, uint? moverId,
        IReadOnlyList<DoorState>? states, string? datPath, string outDir, int jobs)
    {
        var clock = Stopwatch.StartNew();
        if ((single is null ? 0 : 1) + (doors ? 1 : 0) + (setupsFile is null ? 0 : 1) != 1)
            throw new CliException(ExitCodes.Usage, "move: give exactly one of --setup ID, --doors and --setups FILE");
        var list = setupsFile is null ? null : SelectionOptions.ReadSetupList(setupsFile);
        OutputFolder.Check(outDir);
        using var dat = DatLocator.Open(datPath, null, console);
        var moverSetup = MoverId(moverId, dat);
        var walker = RequireMover(moverSetup, dat);
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

        using var folder = OutputFolder.Open(outDir, dat);
        long bytes = 0;
        var cases = 0;
        foreach (var objectId in ids)
        {
            console.Interrupted.ThrowIfCancellationRequested();
            var generated = MovementSuiteBuilder.Build(dat.Portal, objectId, moverSetup, walker, DoorCatalog.Find(objectId) is not null, states, jobs, console.Interrupted);
            var files = MovementExport.Files(generated).ToArray();
            folder.RefuseForeign(files);
            bytes += folder.WriteEach(files, console.Out, console.Interrupted);
            cases += generated.Suite.Cases.Count;
            console.Out.WriteLine($"move {JsonIds.Format(objectId)}: {Summary(generated.Suite)}");
        }
        folder.RequireStillInPlace();
        console.Out.WriteLine($"move: {ids.Count} object(s), {cases} case(s), mover {JsonIds.Format(moverSetup)}, {bytes} bytes in {clock.Elapsed.TotalSeconds:0.000} s");
        return ExitCodes.Ok;
    }

    /// <summary>"616 case(s) in closed, open: 44 blocked, 396 reached, 176 slid; 0 fragile".</summary>
    private static string Summary(MovementSuite suite)
    {
        var classes = suite.Cases.GroupBy(c => c.Outcome.Class).OrderBy(g => g.Key, StringComparer.Ordinal).Select(g => $"{g.Count()} {g.Key}");
        return $"{suite.Cases.Count} case(s) in {string.Join(", ", suite.Objects.Keys)}: {string.Join(", ", classes)}; {suite.Cases.Count(c => c.Fragile)} fragile";
    }
}
