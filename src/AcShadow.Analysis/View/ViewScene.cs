using System.Numerics;

namespace AcShadow.Analysis.View;

/// <summary>
/// Everything one view file shows: a name (the file stem, e.g. "0x020019FF"), a title line, the world
/// position of the view's origin (the landblock's corner for a landblock, zero for a Setup in its own frame)
/// and the groups, in a fixed order.
/// </summary>
public sealed record ViewScene(string Name, string Title, Vector3 WorldOrigin, IReadOnlyList<ViewGroup> Groups, IReadOnlyList<string> Notes);
