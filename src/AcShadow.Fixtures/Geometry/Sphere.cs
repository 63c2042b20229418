using System.Numerics;

namespace AcShadow.Fixtures.Geometry;

/// <summary>A centre and a radius. The dat layout (centre, then radius) lives with the dat layer: <c>SphereLayout</c>.</summary>
public readonly record struct Sphere(Vector3 Center, float Radius);
