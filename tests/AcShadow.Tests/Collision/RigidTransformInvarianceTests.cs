using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Tests.Collision;

/// <summary>
/// Turning and moving a part's pose and its probes together changes no answer. Float rounding of the
/// transform moves a probe by ~1e-6 m, so probes within 1e-5 m of a threshold are left out: the stress
/// probes put many exactly on one on purpose (r − ε ± 1e-5, centres on splitting planes); the r ± 1e-4,
/// edge, vertex and random probes stay in.
/// </summary>
public class RigidTransformInvarianceTests
{
    [Fact]
    public void Moving_a_part_and_its_probes_together_changes_no_answer()
    {
        var random = new Random(11);
        var parts = CollisionCorpus.Sample.Select(d => CompiledBsp.Compile(d))
            .Concat(CollisionCorpus.Forged().Select(f => CompiledBsp.Compile(f.Dump))).ToArray();
        var compared = 0;
        var skipped = 0;
        foreach (var bsp in parts)
        {
            var lookup = (uint id) => id == bsp.GfxObjId ? bsp : null;
            var pose = RandomPose(random);
            var moved = Compose(RandomPose(random), pose);
            var before = Query(bsp, pose, lookup);
            var after = Query(bsp, moved.Pose, lookup);
            foreach (var (local, radius, _) in StressProbes.For(bsp, 2500, random.Next()))
            {
                if (NearThreshold(bsp, local, radius)) { skipped++; continue; }
                var center = pose.ToEntity(local);
                var movedCenter = moved.Apply(center);
                Assert.True(before.Overlaps(center, radius * pose.Scale) == after.Overlaps(movedCenter, radius * pose.Scale),
                    $"GfxObj 0x{bsp.GfxObjId:X8}: local probe ({local.X:R}, {local.Y:R}, {local.Z:R}) r={radius:R} changed its answer when moved");
                compared++;
            }
        }
        Assert.True(compared > 30_000, $"{compared} compared");
        Assert.True(skipped < compared, $"{skipped} probes skipped as too close to a threshold, {compared} compared");
    }

    private static ObjectOverlapQuery Query(CompiledBsp bsp, PartPose pose, Func<uint, CompiledBsp?> lookup) =>
        ObjectOverlapQuery.Create([new ShadowShape(ShapeSource.Part, 0, bsp.GfxObjId, CollisionType.Bsp, pose.Position, pose.Rotation, pose.Scale, 1f, 0f, null)], lookup);

    /// <summary>Within 1e-5 m of a polygon contact threshold (r − ε), or of a splitting-plane reach, in part space.</summary>
    private static bool NearThreshold(CompiledBsp bsp, Vector3 center, float radius)
    {
        const float band = 1e-5f;
        var rad = radius - PhysicsEpsilon.Value;
        foreach (var polygon in bsp.Polygons)
        {
            var d = MathF.Abs(polygon.Distance(center));
            if (MathF.Abs(d - rad) < band) return true;
            if (d <= rad + band)
            {
                // Close to the plane: the edge and vertex rules decide, so measure to the polygon itself.
                var gap = SurfaceDistance.ToPolygon(polygon, center);
                if (MathF.Abs(gap - rad) < band) return true;
            }
        }
        foreach (var node in bsp.Nodes)
        {
            var toSphere = Vector3.Distance(center, node.SphereCenter) - node.SphereRadius - radius;
            if (MathF.Abs(toSphere) < band) return true;
            if (node.IsLeaf) continue;
            var d = Vector3.Dot(node.Normal, center) + node.D;
            if (MathF.Abs(MathF.Abs(d) - MathF.Abs(rad)) < band || MathF.Abs(d) < band) return true;
        }
        return false;
    }

    private static PartPose RandomPose(Random random)
    {
        var axis = StressProbes.RandomUnit(random);
        var rotation = Quaternion.CreateFromAxisAngle(axis, (float)(random.NextDouble() * Math.PI * 2));
        var position = new Vector3((float)random.NextDouble() * 20 - 10, (float)random.NextDouble() * 20 - 10, (float)random.NextDouble() * 4 - 2);
        return new PartPose(position, rotation, random.Next(3) == 0 ? 1.5f : 1f);
    }

    private sealed record Rigid(PartPose Transform, PartPose Pose)
    {
        public Vector3 Apply(Vector3 p) => Vector3.Transform(p, Transform.Rotation) + Transform.Position;
    }

    /// <summary>The rigid transform t applied to the pose: position t(p), rotation t.R ∘ R, same scale.</summary>
    private static Rigid Compose(PartPose t, PartPose pose)
    {
        var transform = t with { Scale = 1f };
        var position = Vector3.Transform(pose.Position, transform.Rotation) + transform.Position;
        return new Rigid(transform, new PartPose(position, Quaternion.Normalize(transform.Rotation * pose.Rotation), pose.Scale));
    }
}
