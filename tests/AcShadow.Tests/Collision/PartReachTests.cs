using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Fixtures.Collision;
using static AcShadow.Tests.Support.Records;

namespace AcShadow.Tests.Collision;

/// <summary>
/// A posed part's reach in the entity frame (<see cref="PartReach"/>), which <see cref="PosedQuery"/> tests before it
/// turns the sphere into the part: it never refuses a sphere the part-local test passes — spheres tangent to the
/// root sphere found by bisection on the turned test itself, under unit and non-unit stored quaternions and scales
/// — and it refuses far spheres, so the posed query answers exactly as the turned test alone.
/// </summary>
public class PartReachTests
{
    private static readonly CompiledBsp Quad = CompiledBsp.Compile(BspExtractor.Extract(BoxGfxObj(0x01000001, half: 1.3f))!);

    /// <summary>Part poses: turned, shifted, scaled, some with a stored quaternion well off unit length.</summary>
    public static TheoryData<float, float, float> Poses() => new()
    {
        { 1f, 0f, 1f },
        { 1f, 0.9f, 0.25f },
        { 1.0008f, 2.1f, 3.7f },
        { 0.9991f, -1.3f, 1f },
        { 1.05f, 0.4f, 0.6f },
        { 0.93f, 2.8f, 12f },
    };

    private static PartPose Pose(float length, float angle, float scale)
    {
        var axis = Vector3.Normalize(new Vector3(0.3f, -0.7f, 0.65f));
        var q = Quaternion.CreateFromAxisAngle(axis, angle);
        // Stored as read, not normalised: the client's matrix of it is not a rotation.
        return new PartPose(new Vector3(4.25f, -17.5f, 2.125f), new Quaternion(q.X * length, q.Y * length, q.Z * length, q.W * length), scale);
    }

    private static bool RootPasses(PartPose pose, Vector3 center, float radius)
    {
        var (local, r) = pose.ToLocal(center, radius);
        return SphereBounds.BroadPhaseHits(Quad.Nodes[0], local, r);
    }

    [Theory]
    [MemberData(nameof(Poses))]
    public void A_sphere_the_root_test_passes_is_always_within_reach_even_tangent(float length, float angle, float scale)
    {
        var pose = Pose(length, angle, scale);
        var reach = PartReach.Of(pose, LocalBound.OfTree(Quad));
        Assert.True(reach.IsBounded);
        var random = new Random(30);
        var tangent = 0;
        for (var i = 0; i < 3000; i++)
        {
            var u = Vector3.Normalize(new Vector3(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f));
            var r = i % 3 == 0 ? 0f : random.NextSingle() * 2f * scale;
            // Bisect along the ray from the reach's centre for the last float sphere the root test passes.
            float inside = 0f, outside = (reach.Radius + r * reach.Stretch) * 4f + 10f;
            if (!RootPasses(pose, reach.Center + inside * u, r)) continue;
            Assert.False(RootPasses(pose, reach.Center + outside * u, r));
            for (var k = 0; k < 80; k++)
            {
                var mid = (inside + outside) * 0.5f;
                if (mid == inside || mid == outside) break;
                if (RootPasses(pose, reach.Center + mid * u, r)) inside = mid; else outside = mid;
            }
            var last = reach.Center + inside * u;
            Assert.True(RootPasses(pose, last, r));
            Assert.True(reach.Reaches(last, r), $"pose {pose}, tangent sphere at {last} r {r} passes the root test but is refused");
            tangent++;
            // Near a rotation the reach is tight: a sphere 2 % beyond the tangent one (plus 2 cm) is refused.
            if (MathF.Abs(length - 1f) < 0.01f)
                Assert.False(reach.Reaches(reach.Center + (inside * 1.02f + 0.02f + 0.03f * r) * u, r));
        }
        Assert.True(tangent > 2500, $"{tangent} tangent spheres");
    }

    [Fact]
    public void A_pose_whose_matrix_is_far_from_a_rotation_reaches_everywhere_and_still_answers()
    {
        var pose = Pose(2f, 0.3f, 1f);
        Assert.False(PartReach.Of(pose, LocalBound.OfTree(Quad)).IsBounded);
        var posed = new PosedQuery(pose, new BspSphereQuery(Quad));
        var (local, r) = pose.ToLocal(new Vector3(40f, 0f, 0f), 0.5f);
        Assert.Equal(new BspSphereQuery(Quad).Overlaps(local, r), posed.Overlaps(new Vector3(40f, 0f, 0f), 0.5f));
        Assert.True(posed.Overlaps(pose.Position, 0.5f));
    }

    [Theory]
    [MemberData(nameof(Poses))]
    public void A_posed_tree_box_and_hull_answer_as_the_turned_test_alone_and_refuse_far_spheres_unturned(float length, float angle, float scale)
    {
        var pose = Pose(length, angle, scale);
        var box = new OrientedBox(new Vector3(0.2f, -0.1f, 0.4f), Quaternion.Normalize(new Quaternion(0.1f, 0.2f, -0.3f, 0.9f)), new Vector3(0.8f, 0.3f, 0.55f));
        ISphereOverlap[] parts = [new BspSphereQuery(Quad), new BoxSphereQuery(box), box.ToPolytope()];
        var random = new Random(31);
        foreach (var part in parts)
        {
            var posed = new PosedQuery(pose, part);
            Assert.True(posed.Reach.IsBounded);
            int blocked = 0, refused = 0;
            for (var i = 0; i < 20000; i++)
            {
                // Around the part, out to four times its reach, many of them near its surface.
                var u = Vector3.Normalize(new Vector3(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f));
                var at = posed.Reach.Center + u * (posed.Reach.Radius * 4f * random.NextSingle() * random.NextSingle());
                var r = random.NextSingle() * scale;
                var (local, localRadius) = pose.ToLocal(at, r);
                var expected = part.Overlaps(local, localRadius);
                Assert.True(expected == posed.Overlaps(at, r), $"{part.GetType().Name} at {at} r {r}: turned test {expected}");
                if (expected) blocked++;
                if (!posed.Reach.Reaches(at, r)) refused++;
            }
            Assert.True(blocked > 200, $"{part.GetType().Name}: {blocked} blocked");
            Assert.True(refused > 2000, $"{part.GetType().Name}: {refused} refused before the turn");
        }
    }
}
