using System.Globalization;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// Checks that the tree's pruning can never hide a contact the brute force would see, and names what
/// breaks it. The pruning is safe when (a) every node's bounding sphere contains the polygons below it, to
/// within the ε the contact test gives away, (b) a polygon reaching past an ancestor's splitting plane also
/// sits in a leaf on that side, and (c) every physics polygon is in some reachable leaf. A dump failing one
/// is still queried as retail would; the diagnostic explains any disagreement with the brute force.
/// </summary>
internal static class BspConsistency
{
    /// <summary>A vertex may lie this far outside a node's sphere before pruning can miss it (half of ε).</summary>
    public const double SphereSlack = PhysicsEpsilon.Value / 2;

    /// <summary>A vertex this far past a splitting plane (metres) is across it; less is float noise of a coplanar polygon.</summary>
    public const float CrossingTolerance = 1e-5f;

    public static bool Check(string name, CompiledPolygon[] polygons, CompiledBspNode[] nodes, int[] leafPolygons, bool[] reachable, DiagnosticLog log)
    {
        var conservative = true;
        var parent = new int[nodes.Length];
        var parentTakesPos = new bool[nodes.Length];
        Array.Fill(parent, -1);
        for (var i = 0; i < nodes.Length; i++)
        {
            if (nodes[i].IsLeaf) continue;
            if (nodes[i].Pos >= 0) { parent[nodes[i].Pos] = i; parentTakesPos[nodes[i].Pos] = true; }
            if (nodes[i].Neg >= 0) { parent[nodes[i].Neg] = i; parentTakesPos[nodes[i].Neg] = false; }
        }

        var leavesOf = new List<int>[polygons.Length];
        for (var i = 0; i < nodes.Length; i++)
        {
            if (!nodes[i].IsLeaf || !reachable[i]) continue;
            for (var k = 0; k < nodes[i].PolygonCount; k++)
                (leavesOf[leafPolygons[nodes[i].PolygonStart + k]] ??= []).Add(i);
        }

        for (var p = 0; p < polygons.Length; p++)
        {
            var polygon = polygons[p];
            if (leavesOf[p] is not { } leaves)
            {
                conservative = false;
                log.Add(CollisionDiagnosticCodes.UnreferencedPolygon, $"{name} polygon {polygon.Id}: in no reachable BSP leaf; retail never tests it, the brute force does");
                continue;
            }
            var reportedSphere = new HashSet<int>();
            var reportedPlane = new HashSet<int>();
            foreach (var leaf in leaves)
            {
                for (var node = leaf; node >= 0; node = parent[node])
                {
                    var excess = SphereExcess(nodes[node], polygon);
                    if (excess > SphereSlack && reportedSphere.Add(node))
                    {
                        conservative = false;
                        log.Add(CollisionDiagnosticCodes.SphereMissesPolygon,
                            $"{name} BSP node {node}: its bounding sphere leaves polygon {polygon.Id} {Metres(excess)} outside; the tree can miss contacts there");
                    }
                    var up = parent[node];
                    if (up < 0) continue;
                    var across = Across(nodes[up], polygon, parentTakesPos[node]);
                    if (across > CrossingTolerance && !HeldOnSide(leaves, up, !parentTakesPos[node], parent, parentTakesPos) && reportedPlane.Add(up))
                    {
                        conservative = false;
                        log.Add(CollisionDiagnosticCodes.PolygonCrossesPlane,
                            $"{name} BSP node {up}: polygon {polygon.Id} reaches {Metres(across)} past its splitting plane but no leaf on that side holds it; the tree can miss contacts there");
                    }
                }
            }
        }
        return conservative;
    }

    /// <summary>How far the polygon's farthest vertex lies outside the node's sphere (≤ 0: inside).</summary>
    private static double SphereExcess(CompiledBspNode node, CompiledPolygon polygon)
    {
        if (float.IsPositiveInfinity(node.SphereRadius)) return double.NegativeInfinity;
        var worst = double.NegativeInfinity;
        foreach (var v in polygon.Vertices)
        {
            double dx = v.X - node.SphereCenter.X, dy = v.Y - node.SphereCenter.Y, dz = v.Z - node.SphereCenter.Z;
            worst = Math.Max(worst, Math.Sqrt(dx * dx + dy * dy + dz * dz) - node.SphereRadius);
        }
        return worst;
    }

    /// <summary>How far the polygon reaches onto the side of the node's plane its subtree is not on.</summary>
    private static float Across(CompiledBspNode node, CompiledPolygon polygon, bool onPosSide)
    {
        var worst = float.NegativeInfinity;
        foreach (var v in polygon.Vertices)
        {
            var d = PolygonPlane.Dot(node.Normal, v) + node.D;
            worst = MathF.Max(worst, onPosSide ? -d : d);
        }
        return worst;
    }

    private static bool HeldOnSide(List<int> leaves, int ancestor, bool posSide, int[] parent, bool[] parentTakesPos)
    {
        foreach (var leaf in leaves)
            for (var node = leaf; parent[node] >= 0; node = parent[node])
                if (parent[node] == ancestor && parentTakesPos[node] == posSide) return true;
        return false;
    }

    private static string Metres(double m) => m.ToString("0.######", CultureInfo.InvariantCulture) + " m";
}
