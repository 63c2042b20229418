using System.Numerics;

namespace AcShadow.Analysis.View;

/// <summary>
/// One drawable shape: its name (what it came from, e.g. "part 0 GfxObj 0x010044B5"), its triangles split by
/// whether a face is seen from both sides, its outline for drawings, and where a label for it goes (a part's
/// origin at the height of its middle, a primitive's centre); all in its object's frame.
/// </summary>
public sealed record ViewShape(string Name, TriangleMesh OneSided, TriangleMesh TwoSided, ShapeOutline Outline, Vector3 Anchor)
{
    public int TriangleCount => OneSided.TriangleCount + TwoSided.TriangleCount;
}
