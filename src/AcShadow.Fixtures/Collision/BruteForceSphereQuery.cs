using System.Runtime.InteropServices;
using System.Numerics;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// The oracle: the same predicate as <see cref="BspSphereQuery"/> computed without descending the tree.
/// Blocked when the broad phase against the root's sphere passes (as in the reference) and
/// <list type="number">
/// <item>the sphere touches any physics polygon (<see cref="PolygonSphereTest"/>; every usable polygon, no
/// sphere or plane pruning), or</item>
/// <item>the centre lies in a solid cell: for some solid leaf listing at least one polygon, at every
/// internal ancestor the query sphere hits the ancestor's bounding sphere and the centre is on the side the
/// path takes — positive when dist ≥ min(0, r − ε). (That is where the reference's centre check travels:
/// its own sphere rejection gates it, so an open mesh's unbounded solid half-space counts only near the
/// part.)</item>
/// </list>
/// It agrees with the reference exactly when <see cref="CompiledBsp.PruningIsConservative"/> holds,
/// barring a float tie at dist = r − ε on a plane a polygon lies in.
/// </summary>
internal sealed class BruteForceSphereQuery : ISphereOverlap
{
    private readonly CompiledPolygon[] _polygons;
    private readonly CompiledBspNode[] _nodes;
    private readonly int[][] _cellAncestors;
    private readonly bool[][] _cellTakesPos;

    public CompiledBsp Bsp { get; }

    public BruteForceSphereQuery(CompiledBsp bsp)
    {
        Bsp = bsp;
        _polygons = ImmutableCollectionsMarshal.AsArray(bsp.Polygons)!;
        _nodes = ImmutableCollectionsMarshal.AsArray(bsp.Nodes)!;
        _cellAncestors = bsp.SolidCells.Select(c => c.Ancestors.ToArray()).ToArray();
        _cellTakesPos = bsp.SolidCells.Select(c => c.TakesPos.ToArray()).ToArray();
    }

    public static BruteForceSphereQuery From(BspDump dump) => new(CompiledBsp.Compile(dump));

    public bool Overlaps(Vector3 center, float radius)
    {
        if (!SphereBounds.IsValidProbe(center, radius) || _nodes.Length == 0) return false;
        if (!SphereBounds.BroadPhaseHits(_nodes[0], center, radius)) return false;
        foreach (var polygon in _polygons)
            if (PolygonSphereTest.Touches(polygon, center, radius)) return true;

        var threshold = MathF.Min(0f, radius - PhysicsEpsilon.Value);
        for (var c = 0; c < _cellAncestors.Length; c++)
        {
            var ancestors = _cellAncestors[c];
            var takesPos = _cellTakesPos[c];
            var inside = true;
            for (var k = 0; k < ancestors.Length && inside; k++)
            {
                ref readonly var node = ref _nodes[ancestors[k]];
                if (!SphereBounds.NodeSphereHits(node, center, radius)) { inside = false; break; }
                var dist = PolygonPlane.Dot(node.Normal, center) + node.D;
                inside = !(dist < threshold) == takesPos[k];
            }
            if (inside) return true;
        }
        return false;
    }
}
