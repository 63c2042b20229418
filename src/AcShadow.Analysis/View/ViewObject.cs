using AcShadow.Fixtures.Geometry;

namespace AcShadow.Analysis.View;

/// <summary>
/// One placed object in a group: its name ("#3 Setup 0x020019FF" in a landblock, the Setup's id alone in a
/// Setup view), its frame in the view and its shapes. Objects placed more than once share their shape list.
/// </summary>
public sealed record ViewObject(string Name, Frame Frame, IReadOnlyList<ViewShape> Shapes);
