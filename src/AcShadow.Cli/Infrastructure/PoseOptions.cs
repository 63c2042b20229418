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
    public Option<string?> Pose { get; } = new("--pose")
    {
        Description = "retail (default: parts where the object's animation puts them once created) or placement (the Setup's placement frame)",
        HelpName = "retail|placement",
    };

    public Option<string?> State { get; } = new("--state")
    {
        Description = "for doors: closed (default) or open (retail makes an open door ethereal; the file says so)",
        HelpName = "closed|open",
    };

    public Option<string?> MotionTable { get; } = new("--motion-table")
    {
        Description = "pose by this MotionTable (e.g. 0x09000202) instead of the door catalog's, after the Setup's own",
        HelpName = "ID",
    };

    public IEnumerable<Option> All => [Pose, State, MotionTable];

    public ShapeBuildOptions Apply(ParseResult parse, ShapeBuildOptions options) => options with
    {
        Pose = ParsePose(parse.GetValue(Pose)),
        DoorState = ParseState(parse.GetValue(State)),
        MotionTable = ParseMotionTable(parse.GetValue(MotionTable)),
    };

    private static PosePolicy ParsePose(string? text)
    {
        if (text is null) return PosePolicy.Retail;
        if (PoseNames.TryParse(text, out PosePolicy pose)) return pose;
        throw new CliException(ExitCodes.Usage, $"--pose: '{text}' is not a pose: use retail (the default) or placement");
    }

    private static DoorState ParseState(string? text)
    {
        if (text is null) return DoorState.Closed;
        if (PoseNames.TryParse(text, out DoorState state)) return state;
        throw new CliException(ExitCodes.Usage, $"--state: '{text}' is not a door state: use closed (the default) or open");
    }

    private static uint? ParseMotionTable(string? text)
    {
        if (text is null) return null;
        if (!JsonIds.TryParse(text, out var id))
            throw new CliException(ExitCodes.Usage, $"--motion-table: '{text}' is not a MotionTable id: write it in hex, e.g. 0x09000202");
        if (!DatObjectKind.MotionTable.Contains(id))
            throw new CliException(ExitCodes.Usage, $"--motion-table: 0x{id:X8} is outside the MotionTable range {DatObjectKind.MotionTable.RangeText()}");
        return id;
    }
}
