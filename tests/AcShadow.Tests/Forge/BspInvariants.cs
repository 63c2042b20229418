using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;
using AcShadow.Forging.Bsp;

namespace AcShadow.Tests.Forge;

/// <summary>What every forged PhysicsBSP must satisfy; returns the violations (empty when sound).</summary>
public static class BspInvariants
{
    public const float SphereSlack = 1e-4f;

    public static List<string> Check(GfxObj gfx)
    {
        var problems = new List<string>();
        if (gfx.PhysicsBsp is not { } root) { problems.Add("no PhysicsBSP"); return problems; }
        var polygons = gfx.PhysicsPolygons.ToDictionary(p => p.Key, p => p.Value);
        var planes = polygons.Values
            .Select(p => PolygonPlane.Compute(p.VertexIds.Select(v => gfx.Vertices[(ushort)v]).ToArray()))
            .Where(p => p is not null).Select(p => p!.Value).ToHashSet();
        var inLeaves = new HashSet<ushort>();
        var leafIndices = new List<int>();
        var maxDepth = 0;
        Visit(root, 0);

        foreach (var id in polygons.Keys.Where(id => !inLeaves.Contains(id))) problems.Add($"polygon {id} is in no leaf");
        if (leafIndices.Distinct().Count() != leafIndices.Count) problems.Add("leaf indices repeat");
        if (!leafIndices.Order().SequenceEqual(Enumerable.Range(0, leafIndices.Count))) problems.Add("leaf indices are not 0..n-1");
        if (maxDepth > PhysicsBspBuilder.MaxDepth) problems.Add($"depth {maxDepth} exceeds {PhysicsBspBuilder.MaxDepth}");
        return problems;

        // Returns the polygon ids in the subtree.
        HashSet<ushort> Visit(PhysicsBspNode node, int depth)
        {
            maxDepth = Math.Max(maxDepth, depth);
            HashSet<ushort> below;
            if (node.IsLeaf)
            {
                leafIndices.Add(node.LeafIndex);
                below = [.. node.Polygons];
                foreach (var id in below)
                    if (!polygons.ContainsKey(id)) problems.Add($"leaf {node.LeafIndex} names polygon {id}, which does not exist");
                inLeaves.UnionWith(below);
                // Retail: BSPLEAF::sphere_intersects_solid returns on NumPolys == 0 before its centre check, so
                // a solid leaf must hold polygons to block anything.
                if (node.Solid != 0 && node.Polygons.Count == 0) problems.Add($"leaf {node.LeafIndex} is solid but holds no polygons");
            }
            else
            {
                if (node.Type != BspNodeTypes.ForChildren(node.Pos is not null, node.Neg is not null))
                    problems.Add($"node tag {node.Type.Tag()} does not match its children");
                // Real physics BSPs give every internal node both children (retail's solid query follows both unchecked).
                if (node.Pos is null || node.Neg is null) problems.Add($"internal node {node.Type.Tag()} has only one child");
                if (!planes.Contains(node.SplittingPlane)) problems.Add($"node plane {node.SplittingPlane} is no polygon's retail plane");
                below = [];
                if (node.Pos is not null) below.UnionWith(Visit(node.Pos, depth + 1));
                if (node.Neg is not null) below.UnionWith(Visit(node.Neg, depth + 1));
            }
            foreach (var id in below)
            {
                if (!polygons.TryGetValue(id, out var poly)) continue;
                foreach (var v in poly.VertexIds)
                {
                    var p = gfx.Vertices[(ushort)v];
                    var distance = Vector3.Distance(p, node.BoundingSphere.Center);
                    if (distance > node.BoundingSphere.Radius + SphereSlack)
                        problems.Add($"vertex {v} of polygon {id} lies {distance - node.BoundingSphere.Radius:0.######} m outside a node sphere");
                }
            }
            return below;
        }
    }

    public static int Depth(PhysicsBspNode node) =>
        node.IsLeaf ? 0 : 1 + Math.Max(node.Pos is null ? 0 : Depth(node.Pos), node.Neg is null ? 0 : Depth(node.Neg));

    public static IEnumerable<PhysicsBspNode> Leaves(PhysicsBspNode node) =>
        node.IsLeaf ? [node] : (node.Pos is null ? [] : Leaves(node.Pos)).Concat(node.Neg is null ? [] : Leaves(node.Neg));
}
