using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Bsp;

/// <summary>
/// One GfxObj's collision geometry, flattened: the physics polygons with their retail planes, the
/// vertices they use, and the PhysicsBSP as a preorder node list (root at index 0). This is the model
/// behind the BSP JSON file and what the collision reference queries, whether it came from a dat or
/// from a dump on disk.
/// </summary>
public sealed record BspDump(
    uint GfxObjId,
    Sphere BoundingSphere,
    IReadOnlyList<BspVertex> Vertices,
    IReadOnlyList<BspPolygon> Polygons,
    IReadOnlyList<BspNode> Nodes,
    BspStats Stats,
    IReadOnlyList<string> Diagnostics);

public readonly record struct BspVertex(int Id, Vector3 Position);

/// <summary>A physics polygon. <see cref="Plane"/> is null when the polygon is degenerate (no normal).</summary>
public sealed record BspPolygon(int Id, IReadOnlyList<int> VertexIds, Plane? Plane, SidesType SidesType, Stippling Stippling);

/// <summary>
/// A BSP node. Internal: <see cref="Plane"/>, <see cref="Pos"/>/<see cref="Neg"/> (null when absent).
/// Leaf: <see cref="LeafIndex"/>, <see cref="Solid"/>, <see cref="PolygonIds"/>.
/// </summary>
public sealed record BspNode(
    int Index,
    BspNodeType Type,
    Plane? Plane,
    Sphere Sphere,
    int? Pos,
    int? Neg,
    int LeafIndex,
    bool Solid,
    IReadOnlyList<int> PolygonIds)
{
    public bool IsLeaf => Type == BspNodeType.Leaf;
}

public sealed record BspStats(
    int VertexCount,
    int PolygonCount,
    int NodeCount,
    int LeafCount,
    int SolidLeafCount,
    int MaxDepth,
    IReadOnlyList<int> DegeneratePolygons,
    IReadOnlyList<int> NonPlanarPolygons);
