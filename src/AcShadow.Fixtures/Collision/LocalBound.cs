using System.Numerics;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// The part-local sphere (C, ρ) a part query keeps to: it blocks a sphere (c, r) only when
/// |c − C| ≤ (1 + τ)(ρ + r) + τ|C|, τ = 1e-5, its own float rounding included (each is a few 2⁻²⁴); null for a
/// query it does not know, which is then asked without a bound (<see cref="PartReach.Everywhere"/>).
/// </summary>
internal static class LocalBound
{
    /// <summary>sqrt(ε): the root test passes |Δ|² − (R + r)² &lt; ε, so |Δ| &lt; R + r + sqrt(ε).</summary>
    private static readonly float RootSlack = MathF.Sqrt(PhysicsEpsilon.Value) * 1.0001f;

    public static (Vector3 Center, float Radius)? Of(ISphereOverlap query) => query switch
    {
        BspSphereQuery tree => OfTree(tree.Bsp),
        IndexedBspQuery indexed => OfTree(indexed.Tree.Bsp),
        BoxSphereQuery box => OfBox(box.Box),
        ConvexPolytope hull => hull.Bound,
        _ => null,
    };

    /// <summary>A tree answers nothing outside its root's sphere (CGfxObj::find_obj_collisions' broad phase, ε included).</summary>
    public static (Vector3 Center, float Radius)? OfTree(CompiledBsp bsp) =>
        bsp.Nodes.Length == 0 ? null : (bsp.Nodes[0].SphereCenter, bsp.Nodes[0].SphereRadius + RootSlack);

    /// <summary>
    /// A box blocks only within r − ε of it, so within |half extents| + r of its centre; its axes turn by the plain
    /// rotation, near enough a rotation only for a quaternion within 2e-6 of unit length (a fitted box's are unit).
    /// </summary>
    public static (Vector3 Center, float Radius)? OfBox(OrientedBox box)
    {
        var q = box.Axes;
        var n = (double)q.X * q.X + (double)q.Y * q.Y + (double)q.Z * q.Z + (double)q.W * q.W;
        if (!(Math.Abs(n - 1) <= 2e-6)) return null;
        var h = box.HalfExtents;
        return (box.Center, (float)(Math.Sqrt((double)h.X * h.X + (double)h.Y * h.Y + (double)h.Z * h.Z) * (1 + 1e-6)));
    }
}
