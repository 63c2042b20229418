using System.Numerics;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Tests.Collision;

/// <summary>
/// Random probes aimed where a tree and a brute force could part ways: anywhere around the part, at
/// r ± 1e-4 and at the contact threshold r − ε ± 1e-5 from polygon faces, edges and vertices, and on and
/// beside splitting planes. Seeded: every run draws the same probes.
/// </summary>
internal static class StressProbes
{
    public static List<(Vector3 Center, float Radius, string Kind)> For(CompiledBsp bsp, int count, int seed)
    {
        var random = new Random(seed);
        var probes = new List<(Vector3, float, string)>(count);
        var root = bsp.Nodes.Length > 0 ? bsp.Nodes[0] : default;
        var reach = float.IsFinite(root.SphereRadius) && root.SphereRadius > 0 ? root.SphereRadius : 1f;
        var internals = Enumerable.Range(0, bsp.Nodes.Length).Where(i => !bsp.Nodes[i].IsLeaf).ToArray();
        while (probes.Count < count)
        {
            var radius = RandomRadius(random);
            var pick = random.Next(bsp.Polygons.Length == 0 ? 1 : 6);
            switch (pick)
            {
                case 0:
                    probes.Add((root.SphereCenter + RandomInBall(random) * (reach + radius + 0.25f), radius, "anywhere"));
                    break;
                case 1:
                {
                    var polygon = bsp.Polygons[random.Next(bsp.Polygons.Length)];
                    var point = PointIn(polygon, random);
                    var side = random.Next(2) == 0 ? 1f : -1f;
                    probes.Add((point + polygon.Normal * (side * Offset(random, radius)), radius, "face"));
                    break;
                }
                case 2:
                {
                    var polygon = bsp.Polygons[random.Next(bsp.Polygons.Length)];
                    var k = random.Next(polygon.Vertices.Length);
                    var a = polygon.Vertices[k];
                    var b = polygon.Vertices[(k + 1) % polygon.Vertices.Length];
                    var point = Vector3.Lerp(a, b, (float)random.NextDouble());
                    probes.Add((point + RandomUnit(random) * Offset(random, radius), radius, "edge"));
                    break;
                }
                case 3:
                {
                    var polygon = bsp.Polygons[random.Next(bsp.Polygons.Length)];
                    var point = polygon.Vertices[random.Next(polygon.Vertices.Length)];
                    probes.Add((point + RandomUnit(random) * Offset(random, radius), radius, "vertex"));
                    break;
                }
                default:
                {
                    if (internals.Length == 0) goto case 0;
                    var node = bsp.Nodes[internals[random.Next(internals.Length)]];
                    var inBall = node.SphereCenter + RandomInBall(random) * MathF.Min(node.SphereRadius, 1e3f);
                    var onPlane = inBall - node.Normal * (Vector3.Dot(node.Normal, inBall) + node.D);
                    var shift = random.Next(4) switch
                    {
                        0 => 0f,
                        1 => radius - PhysicsEpsilon.Value,
                        2 => -(radius - PhysicsEpsilon.Value),
                        _ => (float)(random.NextDouble() * 2 - 1) * 1e-5f,
                    };
                    probes.Add((onPlane + node.Normal * shift, radius, "plane"));
                    break;
                }
            }
        }
        return probes;
    }

    private static float RandomRadius(Random random) => random.Next(10) switch
    {
        0 => 0f,
        1 => PhysicsEpsilon.Value,
        2 => (float)random.NextDouble() * 0.01f,
        _ => 0.05f + (float)random.NextDouble() * 0.95f,
    };

    /// <summary>The distance to put a probe from a feature: r ± 1e-4, or the contact threshold r − ε ± 1e-5, or anywhere inside.</summary>
    private static float Offset(Random random, float radius) => random.Next(5) switch
    {
        0 => radius + 1e-4f,
        1 => MathF.Max(0f, radius - 1e-4f),
        2 => MathF.Max(0f, radius - PhysicsEpsilon.Value + 1e-5f),
        3 => MathF.Max(0f, radius - PhysicsEpsilon.Value - 1e-5f),
        _ => (float)random.NextDouble() * (radius + 0.1f),
    };

    private static Vector3 PointIn(CompiledPolygon polygon, Random random)
    {
        var weights = polygon.Vertices.Select(_ => (float)random.NextDouble() + 1e-3f).ToArray();
        var sum = weights.Sum();
        var point = Vector3.Zero;
        for (var i = 0; i < weights.Length; i++) point += polygon.Vertices[i] * (weights[i] / sum);
        return point;
    }

    public static Vector3 RandomUnit(Random random)
    {
        while (true)
        {
            var v = new Vector3((float)random.NextDouble() * 2 - 1, (float)random.NextDouble() * 2 - 1, (float)random.NextDouble() * 2 - 1);
            var l = v.Length();
            if (l > 1e-3f && l <= 1f) return v / l;
        }
    }

    private static Vector3 RandomInBall(Random random)
    {
        while (true)
        {
            var v = new Vector3((float)random.NextDouble() * 2 - 1, (float)random.NextDouble() * 2 - 1, (float)random.NextDouble() * 2 - 1);
            if (v.LengthSquared() <= 1f) return v;
        }
    }
}
