using System.Collections.Immutable;
using System.Runtime.InteropServices;
using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// A physics polygon ready for sphere tests: its retail plane, its vertices in order, and per edge
/// (previous vertex → vertex, as CPolygon walks them) the edge vector and cross(normal, edge), which
/// points into the polygon for the winding the plane was made from. Precomputing them changes no bits:
/// the same float operations run once instead of per query.
/// </summary>
internal sealed class CompiledPolygon
{
    public int Id { get; }
    public Vector3 Normal { get; }
    public float D { get; }
    public ImmutableArray<Vector3> Vertices { get; }

    /// <summary>The edges in CPolygon's order, each in one piece (<see cref="PolygonEdge"/>).</summary>
    internal readonly PolygonEdge[] Edges;

    public CompiledPolygon(int id, Plane plane, Vector3[] vertices)
    {
        Id = id;
        Normal = plane.Normal;
        D = plane.D;
        // Copied: the caller keeps its array, and the edges below are computed from this copy.
        vertices = [.. vertices];
        Vertices = ImmutableCollectionsMarshal.AsImmutableArray(vertices);
        var n = vertices.Length;
        Edges = new PolygonEdge[n];
        for (var i = 0; i < n; i++)
        {
            var previous = vertices[i == 0 ? n - 1 : i - 1];
            var edge = Vec.Sub(vertices[i], previous);
            var inward = Vec.Cross(plane.Normal, edge);
            Edges[i] = new PolygonEdge(previous, edge, PolygonPlane.Dot(edge, edge), inward, PolygonPlane.Dot(inward, inward));
        }
    }

    /// <summary>Signed distance of a point from the polygon's plane (dot then + d, fixed order).</summary>
    public float Distance(Vector3 p) => PolygonPlane.Dot(Normal, p) + D;
}
