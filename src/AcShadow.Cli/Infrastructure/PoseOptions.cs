using System.CommandLine;
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

    public ShapeBuildOptions Apply(ParseResult parse, ShapeBuildOptions options) => options with
    {
        Pose = parse.GetValue(Pose) ?? PosePolicy.Retail,
        DoorState = parse.GetValue(State) ?? DoorState.Closed,
        MotionTable = parse.GetValue(MotionTable),
    };

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
