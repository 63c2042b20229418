using System.Numerics;

namespace AcShadow.Analysis.View;

/// <summary>What a drawing (the three-view SVG) needs of a shape, in its object's frame: exact, not tessellated.</summary>
public abstract record ShapeOutline;

/// <summary>A BSP part's physics polygons, each a loop of vertices.</summary>
public sealed record PolygonOutline(IReadOnlyList<Vector3[]> Polygons) : ShapeOutline;

/// <summary>A vertical cylinder standing on <paramref name="Base"/>.</summary>
public sealed record CylinderOutline(Vector3 Base, float Radius, float Height) : ShapeOutline;

public sealed record SphereOutline(Vector3 Center, float Radius) : ShapeOutline;

/// <summary>Marked points (chart probes): diamonds for false passes, squares for false blocks.</summary>
public sealed record PointsOutline(IReadOnlyList<Vector3> Points, bool FalsePass) : ShapeOutline;
