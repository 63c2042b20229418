using System.Numerics;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Analysis.Compile;
using AcShadow.Core.Scenes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Scenes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Tests.Scenes;

/// <summary>
/// A CylSphere blocks a box in profile (CCylSphere::collides_with_sphere: horizontal distance ≤ R − ε + r and
/// |h/2 − dz| ≤ r − ε + h/2), so a mover's centre is blocked up to the rim corners, (R + r, h/2 + r) from the
/// cylinder's middle: further than the object's sphere plus r. The scene's broad phase (each entry's sphere, the
/// land cells) must still ask the cylinder there, so the scene answers what the cylinder's own test answers, for
/// any radius, height, mover radius, rotation and place in the landblock.
/// </summary>
public sealed class CylinderBroadPhaseTests
{
    [Theory]
    [InlineData(0.3f, 1.8f, 0.5f)]
    [InlineData(0.3f, 1.8f, 1.5f)]
    [InlineData(1.0f, 0.4f, 0.5f)]
    [InlineData(2.0f, 6.0f, 0.25f)]
    [InlineData(0.1f, 0.1f, 1.5f)]
    [InlineData(0.5f, 1.0f, 0.48f)]
    public void A_mover_at_a_rim_corner_is_blocked_by_the_scene_as_by_the_cylinder(float radius, float height, float mover)
    {
        foreach (var rotation in new[] { Quaternion.Identity, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.7f) })
        {
            var scenes = Scenes(radius, height, new Vector3(100f, 100f, 10f), rotation);
            var blocked = 0;
            foreach (var local in Corners(radius, height, mover))
                blocked += AssertSceneAnswersAsTheCylinder(scenes, local, mover) ? 1 : 0;
            Assert.Equal(Corners(radius, height, mover).Count(), blocked);
        }
    }

    [Fact]
    public void The_reported_case_is_blocked_1_6_m_from_the_middle_where_the_sphere_bound_reaches_1_5()
    {
        // R 0.3, h 1.8, r 0.5: the box (±0.3, ±0.3, 0..1.8)'s sphere is 0.995 (padded 0.996); a sphere bound passes
        // within 1.496 of the middle, but the cylinder blocks a centre (0.79, 0, 2.29) from its base, 1.599 from it.
        var scenes = Scenes(0.3f, 1.8f, new Vector3(50f, 60f, 0f), Quaternion.Identity);
        var entry = scenes[0].Objects[0];
        Assert.InRange(entry.BoundRadius, 0.995f, 0.997f);
        var local = new Vector3(0.79f, 0f, 2.29f);
        Assert.InRange(Vector3.Distance(local, new Vector3(0f, 0f, 0.9f)), 1.59f, 1.6f);
        Assert.True(CylinderSphereTest.Touches(Vector3.Zero, 0.3f, 1.8f, local, 0.5f));
        Assert.True(AssertSceneAnswersAsTheCylinder(scenes, local, 0.5f));
    }

    [Fact]
    public void A_tilted_cylinder_s_rim_corner_across_a_land_cell_edge_is_asked_in_the_mover_s_land_cell()
    {
        // Tilted 45° about y, the corner direction (R + r, h/2 + r) lies along landblock x: with r 1.5 it is 2.97 m
        // from the middle, 0.37 m beyond the object's footprint (its sphere 0.996 m, padded) plus the mover's range
        // (1.5 m, padded) along x. With the object's sphere just inside land cell 0 and the mover in cell 1, a
        // partition that pads the mover's range by r alone never asks the object.
        const float R = 0.3f, H = 1.8f, Mover = 1.5f;
        var local = new Vector3(R + Mover - 0.01f, 0f, H + Mover - 0.01f);
        var best = (Rotation: Quaternion.Identity, Along: float.MinValue);
        foreach (var angle in new[] { MathF.PI / 4, -MathF.PI / 4, 3 * MathF.PI / 4, -3 * MathF.PI / 4 })
        {
            var rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitY, angle);
            var entry = Scenes(R, H, Vector3.Zero, rotation)[0].Objects[0];
            var along = entry.Frame.ToEntity(local).X - entry.LandblockBound.Center.X;
            if (along > best.Along) best = (rotation, along);
        }
        Assert.InRange(best.Along, 2.9f, 3.0f);
        var probe = Scenes(R, H, Vector3.Zero, best.Rotation)[0].Objects[0];
        // The bound's footprint ends 1 cm inside cell 0 (x < 24).
        var offset = 24f - (probe.BoundRadius * 1.001f + 0.05f) - 0.01f - probe.LandblockBound.Center.X;
        var scenes = Scenes(R, H, new Vector3(offset, 100f, 20f), best.Rotation);
        var at = scenes[0].Objects[0].Frame.ToEntity(local);
        Assert.True(LandCellPartition.Footprint(scenes[0].Objects[0].LandblockBound.Center, scenes[0].Objects[0].BoundRadius) is { X1: 0 });
        Assert.True(at.X - Mover * 1.001f - 0.05f > 24f, $"{at}: the mover's own range is all in cell 1");
        Assert.True(AssertSceneAnswersAsTheCylinder(scenes, local, Mover));
        Assert.True(scenes[0].Partition.Reaches(0, at, Mover));
    }

    [Fact]
    public void Random_cylinders_rotations_and_movers_are_answered_as_the_object_s_own_test_answers()
    {
        var random = new Random(30);
        var blocked = 0;
        var checkedProbes = 0;
        for (var i = 0; i < 60; i++)
        {
            float radius = 0.05f + random.NextSingle() * 2f, height = 0.05f + random.NextSingle() * 4f;
            var axis = Vector3.Normalize(new Vector3(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f));
            var rotation = i % 3 == 0 ? Quaternion.CreateFromAxisAngle(Vector3.UnitZ, random.NextSingle() * 6.3f) : Quaternion.CreateFromAxisAngle(axis, random.NextSingle() * 6.3f);
            // Near land-cell corners (every 24 m) as often as not.
            var position = new Vector3(24f * random.Next(1, 8) + (random.NextSingle() - 0.5f) * 6f, 24f * random.Next(1, 8) + (random.NextSingle() - 0.5f) * 6f, random.NextSingle() * 50f);
            // Every other object has a sphere beside the cylinder too, so its bound is not centred on the cylinder.
            Vector3? sphere = i % 2 == 0 ? null : new Vector3(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.2f) * 6f;
            var scenes = Scenes(radius, height, position, rotation, sphere);
            foreach (var mover in new[] { 0.25f, 0.5f, 1.5f, 0.05f + random.NextSingle() * 3f })
                foreach (var local in Corners(radius, height, mover))
                {
                    blocked += AssertSceneAnswersAsTheCylinder(scenes, local, mover) ? 1 : 0;
                    checkedProbes++;
                    // Just outside the corner: clear for the cylinder alone; the scene answers as the object does.
                    var outside = local + 0.02f * Vector3.Normalize(local - new Vector3(0f, 0f, height / 2));
                    var outsideBlocked = AssertSceneAnswersAsTheCylinder(scenes, outside, mover);
                    if (sphere is null) Assert.False(outsideBlocked);
                }
        }
        Assert.Equal(checkedProbes, blocked);
    }

    /// <summary>
    /// The object placed in the scenes the tool builds (all-retail; compiled with its shapes registered apart, as
    /// the consumer's compiled scene is), asked at an entity-space centre: the scenes' answers (partitioned and
    /// exhaustive) and the entry's own equal the cylinder's test of the sphere as the entry turns it. Returns it.
    /// </summary>
    private static bool AssertSceneAnswersAsTheCylinder(SceneQuery[] scenes, Vector3 local, float mover)
    {
        bool? answer = null;
        foreach (var scene in scenes)
        {
            var entry = scene.Objects[0];
            var at = entry.Frame.ToEntity(local);
            var (turned, r) = entry.ToEntity(at, mover);
            var own = entry.EntityQuery.Overlaps(turned, r);
            Assert.True(own == scene.Overlaps(at, mover), $"{local} r {mover}: the cylinder says {own}, the scene not");
            Assert.True(own == scene.Exhaustive.Overlaps(at, mover), $"{local} r {mover}: the cylinder says {own}, the exhaustive walk not");
            Assert.True(own == entry.Overlaps(at, mover), $"{local} r {mover}: the cylinder says {own}, its entry not");
            answer ??= own;
            Assert.Equal(answer, own);
        }
        return answer!.Value;
    }

    /// <summary>Centres 1 cm inside the blocked box's rim corners, above and below, in 16 directions (entity space, base at the origin).</summary>
    private static IEnumerable<Vector3> Corners(float radius, float height, float mover)
    {
        var reach = radius + mover - 0.01f;
        for (var k = 0; k < 16; k++)
        {
            var angle = k * MathF.PI / 8f;
            var horizontal = reach * new Vector3(MathF.Cos(angle), MathF.Sin(angle), 0f);
            yield return horizontal + new Vector3(0f, 0f, height + mover - 0.01f);
            yield return horizontal - new Vector3(0f, 0f, mover - 0.01f);
        }
    }

    /// <summary>
    /// One Setup whose first shape is a CylSphere (base at the entity's origin), and a 0.5 m sphere at <paramref name="sphere"/> if given, placed
    /// once: the all-retail scene, the compiled scene (parts apart), and the consumer's registration (<see cref="PlacedParts"/> over the file's shapes).
    /// </summary>
    private static SceneQuery[] Scenes(float radius, float height, Vector3 position, Quaternion rotation, Vector3? sphere = null)
    {
        ShadowShape[] shapes = [new(ShapeSource.CylSphere, 0, null, CollisionType.Cylinder, Vector3.Zero, Quaternion.Identity, 1f, radius, height, null),
            .. sphere is { } at ? [new ShadowShape(ShapeSource.Sphere, 0, null, CollisionType.Sphere, at, Quaternion.Identity, 1f, 0.5f, 0f, null)] : Array.Empty<ShadowShape>()];
        var query = ObjectOverlapQuery.Create(shapes, _ => null);
        var model = new PreparedModel(query, query.Shapes, []);
        var bounds = ShapeBounds.Of(model.Shapes);
        var timing = new TimingStats(0, 0, 0, []);
        var compiled = new Dictionary<(SceneObjectKind, uint), ObjectCompilation>
        {
            [(SceneObjectKind.Setup, 0x02000001u)] = new(0x02000001u, SceneObjectKind.Setup, "retail", model, model, ProbeSpheres.Empty, [], timing, timing, bounds, []),
        };
        AcShadow.Analysis.Compile.PlacedObject[] placed = [new(new SceneObject(0, ScenePlacedBy.Object, 0, 0x02000001u, SceneObjectKind.Setup, new Frame(position, rotation)), null)];
        var (center, boundRadius) = SceneCompiler.Bound(bounds);
        var consumer = new SceneQuery([.. PlacedParts.Of(0, 0x02000001u, position, rotation, new AnyOverlap([new CylinderShapeQuery(Vector3.Zero, radius, height), .. sphere is { } c ? [new SphereShapeQuery(c, 0.5f)] : Array.Empty<ISphereOverlap>()]), center, boundRadius)]);
        return [SceneCompiler.Query(placed, compiled, [], c => c.Retail), SceneCompiler.Query(placed, compiled, [], c => c.Chosen, partsApart: true), consumer];
    }
}
