using System.Numerics;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// One node of a <see cref="CompiledBsp"/>. Internal nodes: splitting plane and children (−1 = absent).
/// Leaves: the solid flag, how many polygon ids the dat lists (retail's NumPolys, which gates the centre
/// check), and the range of usable polygons in <see cref="CompiledBsp.LeafPolygons"/>.
/// </summary>
internal readonly record struct CompiledBspNode(
    bool IsLeaf,
    Vector3 SphereCenter,
    float SphereRadius,
    Vector3 Normal,
    float D,
    int Pos,
    int Neg,
    bool Solid,
    int ListedPolygonCount,
    int PolygonStart,
    int PolygonCount,
    int LeafIndex);
