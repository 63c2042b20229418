using System.Numerics;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// One edge of a <see cref="CompiledPolygon"/> (previous vertex → vertex, as CPolygon walks them): where it starts, its
/// vector and squared length, and cross(normal, edge), pointing into the polygon, with its squared length. Kept
/// together so a sphere test reads one edge from one place.
/// </summary>
internal readonly record struct PolygonEdge(Vector3 Start, Vector3 Vector, float LengthSquared, Vector3 Inward, float InwardLengthSquared);
