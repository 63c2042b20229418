using System.Numerics;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// A solid convex polytope in a part's own space: its vertices and its faces as convex polygons, outward
/// wound, each with its plane. A sphere overlaps it by true distance and retail's conventions (the ones a
/// BSP of the same solid answers with): reach = r − ε; any face plane the centre is reach or more in
/// front of separates it (BSPNODE::sphere_intersects_solid sends dist ≥ reach to the positive side alone,
/// so a face only touched is clear); a centre behind every face plane is inside (the solid leaf's centre
/// check); otherwise the sphere blocks when it touches a face it is in front of
/// (<see cref="PolygonSphereTest"/>, CPolygon::polygon_hits_sphere_precise: edges and corners touched count).
/// A flat polytope (one polygon wound both ways) is never entered, only touched.
/// </summary>
internal sealed class ConvexPolytope : ISphereOverlap
{
    private readonly CompiledPolygon[] _faces;
    private readonly Vector3 _boundCenter;
    private readonly float _boundRadius;

    public IReadOnlyList<Vector3> Vertices { get; }
    public IReadOnlyList<CompiledPolygon> Faces => _faces;

    /// <summary>The sphere <see cref="Overlaps"/> rejects by first (null: no faces, nothing is blocked).</summary>
    public (Vector3 Center, float Radius)? Bound => _faces.Length == 0 ? null : (_boundCenter, _boundRadius);

    /// <summary>
    /// The solid as a one-leaf BSP whose leaf sphere is this polytope's bounding sphere (<see cref="CompiledBsp.SolidLeaf"/>),
    /// its faces in <paramref name="order"/> (default: <see cref="Faces"/>' order).
    /// </summary>
    internal CompiledBsp ToSolidLeaf(uint id, IReadOnlyList<CompiledPolygon>? order = null) => CompiledBsp.SolidLeaf(id, order ?? _faces, _boundCenter, _boundRadius);

    private NearestPolygonIndex? _nearest;

    /// <summary>Built on first use and kept, as <see cref="CompiledBsp"/>'s (no delegate per call: it is asked once per ranked probe).</summary>
    internal NearestPolygonIndex Nearest => Volatile.Read(ref _nearest) ?? (Interlocked.CompareExchange(ref _nearest, NearestPolygonIndex.Build([.. _faces]), null) ?? _nearest);

    public ConvexPolytope(IReadOnlyList<Vector3> vertices, IReadOnlyList<CompiledPolygon> faces)
    {
        Vertices = vertices;
        _faces = [.. faces];
        var min = new Vector3(float.PositiveInfinity);
        var max = new Vector3(float.NegativeInfinity);
        foreach (var v in vertices) { min = Vector3.Min(min, v); max = Vector3.Max(max, v); }
        _boundCenter = vertices.Count == 0 ? Vector3.Zero : (min + max) * 0.5f;
        var far = 0f;
        foreach (var v in vertices) far = MathF.Max(far, Vec.DistanceSquared(v, _boundCenter));
        // Padded so float rounding of the centre can never let the sphere reject a touching query.
        _boundRadius = MathF.Sqrt(far) * 1.0001f + 1e-5f;
    }

    public bool Overlaps(Vector3 center, float radius)
    {
        if (!SphereBounds.IsValidProbe(center, radius) || _faces.Length == 0) return false;
        var sum = _boundRadius + radius;
        if (Vec.DistanceSquared(center, _boundCenter) > sum * sum) return false;
        var reach = radius - PhysicsEpsilon.Value;
        var deepest = float.NegativeInfinity;
        foreach (var face in _faces)
        {
            var dist = face.Distance(center);
            if (dist >= reach) return false;
            deepest = MathF.Max(deepest, dist);
        }
        if (deepest < 0f) return true;
        foreach (var face in _faces)
            if (face.Distance(center) >= 0f && PolygonSphereTest.Touches(face, center, radius)) return true;
        return false;
    }
}
