using System.CommandLine;
using AcShadow.Core.Catalog;
using AcShadow.Core.Dat;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Json;
using AcShadow.Core.Poses;
using AcShadow.Core.Shapes;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// The pose options dump, batch, audit and chart share (--pose, --state, --motion-table), spelled once,
/// with their parsing onto <see cref="ShapeBuildOptions"/>.
/// </summary>
public sealed class PoseOptions
{
    public Option<PosePolicy?> Pose { get; } = ValueOptions.Single("--pose", "retail|placement",
        "retail (default: parts where the object's animation puts them once created) or placement (the Setup's placement frame)", ParsePose);

    public Option<DoorState?> State { get; } = ValueOptions.Single("--state", "closed|open",
        "for doors: closed (default) or open (retail makes an open door ethereal; the file says so)", ParseState);

    public Option<uint?> MotionTable { get; } = ValueOptions.Single("--motion-table", "ID",
        "pose by this MotionTable (e.g. 0x09000202) instead of the door catalog's, after the Setup's own", ParseMotionTable);

    public IEnumerable<Option> All => [Pose, State, MotionTable];

    public ShapeBuildOptions Apply(ParseResult parse, ShapeBuildOptions options)
    {
        var pose = parse.GetValue(Pose) ?? PosePolicy.Retail;
        // A door's state is a motion of the retail pose: the placement frame has none to take.
        if (pose == PosePolicy.Placement && parse.GetValue(State) is { } state)
            throw new CliException(ExitCodes.Usage, $"--state {state.Name()} poses a door by its motion table, which --pose placement does not use: drop --state or --pose placement");
        if (pose == PosePolicy.Placement && parse.GetValue(MotionTable) is { } table)
            throw new CliException(ExitCodes.Usage, $"--motion-table {JsonIds.Format(table)} poses by a motion table, which --pose placement does not use: drop --motion-table or --pose placement");
        return options with
        {
            Pose = pose,
            DoorState = parse.GetValue(State) ?? DoorState.Closed,
            MotionTable = parse.GetValue(MotionTable),
        };
    }

    /// <summary>
    /// Once the dat is open and the Setups chosen: a --motion-table the dat lacks is exit 4 (as any id not in
    /// the dat), and --state open with no door among the Setups would change nothing, so it is a usage error.
    /// </summary>
    public static void RequireUsable(ShapeBuildOptions options, IDatSource portal, IReadOnlyCollection<uint> setups)
    {
        if (options.MotionTable is { } table && portal.ReadMotionTable(table) is null)
            throw new CliException(ExitCodes.NotInDat, $"--motion-table: MotionTable {JsonIds.Format(table)} is not in {portal.Info.FileName}: check the id (a Setup's own table is its DefaultMotionTable)");
        if (options.DoorState == DoorState.Open && setups.Count > 0 && !setups.Any(id => DoorCatalog.Find(id) is not null))
            throw new CliException(ExitCodes.Usage, setups.Count == 1
                ? $"--state open: Setup {JsonIds.Format(setups.First())} is not a door (the door catalog does not list it), so it has no open state: drop --state"
                : $"--state open: none of the {setups.Count} selected Setups is a door (the door catalog lists none of them): drop --state, or select doors (--doors)");
    }

    private static PosePolicy ParsePose(string text) =>
        PoseNames.TryParse(text, out PosePolicy pose) ? pose
            : throw new CliException(ExitCodes.Usage, $"--pose: '{text}' is not a pose: use retail (the default) or placement");

    private static DoorState ParseState(string text) =>
        PoseNames.TryParse(text, out DoorState state) ? state
            : throw new CliException(ExitCodes.Usage, $"--state: '{text}' is not a door state: use closed (the default) or open");

    private static uint ParseMotionTable(string text)
    {
        if (!JsonIds.TryParse(text, out var id))
            throw new CliException(ExitCodes.Usage, $"--motion-table: '{text}' is not a MotionTable id: write it in hex, e.g. 0x09000202");
        if (!DatObjectKind.MotionTable.Contains(id))
            throw new CliException(ExitCodes.Usage, $"--motion-table: 0x{id:X8} is outside the MotionTable range {DatObjectKind.MotionTable.RangeText()}");
        return id;
    }
}
