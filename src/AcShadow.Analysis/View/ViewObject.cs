using AcShadow.Fixtures.Geometry;

namespace AcShadow.Analysis.View;

/// <summary>
/// One placed object in a group: its name ("#3 Setup 0x020019FF" in a landblock, "cell 0xA9B40100" for an
/// indoor cell, "Setup 0x020019FF" in a Setup view), its frame in the view and its shapes. Objects placed
/// more than once share their shape list. <see cref="Key"/> is the label every drawing of a landblock gives
/// it: the scene's object index ("3") or the cell's number in the landblock ("c0" for 0x…0100).
/// </summary>
public sealed record ViewObject(string Name, Frame Frame, IReadOnlyList<ViewShape> Shapes)
{
    public string? Key { get; init; }
}
