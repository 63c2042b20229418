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
        var best = TiltedTowardX(R, H, local);
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
    public void Beside_a_plain_object_the_tilted_cylinder_s_rim_corner_is_found_by_its_stretched_range_alone()
    {
        // The tilted cylinder's corner case above, with a 0.5 m sphere object 10 m along y whose footprint also ends
        // in land cell 0. The mover in cell 1 finds the cylinder by the cylinder's stretched range (and is
        // blocked by it, so a range padded by r alone answers clear); the sphere's plain range does not reach cell 0,
        // so the sphere is not asked (a range padded by the scene's largest stretch asks it).
        const float R = 0.3f, H = 1.8f, Mover = 1.5f;
        var local = new Vector3(R + Mover - 0.01f, 0f, H + Mover - 0.01f);
        var (rotation, along) = TiltedTowardX(R, H, local);
        Assert.InRange(along, 2.9f, 3.0f);
        var probe = Scenes(R, H, Vector3.Zero, rotation)[0].Objects[0];
        var offset = 24f - (probe.BoundRadius * 1.001f + 0.05f) - 0.01f - probe.LandblockBound.Center.X;
        // The sphere's bound (around its box, 0.87 m) ends 0.2 m inside cell 0.
        var neighbour = new Vector3(22.9f, 110f, 20f);
        var scenes = Scenes(R, H, new Vector3(offset, 100f, 20f), rotation, neighbour: neighbour);
        var at = scenes[0].Objects[0].Frame.ToEntity(local);
        Assert.True(at.X - Mover * 1.001f - 0.05f > 24f, $"{at}: the mover's plain range is all in cell 1");
        Assert.True(AssertSceneAnswersAsTheCylinder(scenes, local, Mover));
        foreach (var scene in scenes)
        {
            Assert.Equal(2, scene.Objects.Count);
            Assert.True(LandCellPartition.Footprint(scene.Objects[1].LandblockBound.Center, scene.Objects[1].BoundRadius) is { X1: 0 });
            Assert.Equal(1f, scene.Objects[1].RadiusStretch);
            Assert.Equal(1, scene.Partition.Stretched);
            Assert.True(scene.Partition.Reaches(0, at, Mover));
            Assert.False(scene.Partition.Reaches(1, at, Mover));
            var asked = new ScenePartitionTests.Asked();
            scene.Partition.Any(at, Mover, ref asked);
            Assert.Equal(new[] { 0 }, asked.Entries);
            // Beside the sphere, in the same land cells, the plain range asks it.
            var beside = new Vector3(at.X, neighbour.Y, neighbour.Z);
            Assert.True(scene.Partition.Reaches(1, beside - new Vector3(1f, 0f, 0f), Mover));
        }
    }

    [Fact]
    public void Scenes_mixing_tilted_cylinders_and_spheres_near_land_cell_corners_answer_as_their_exhaustive_walk()
    {
        // Several cylinders (tilted or not) and sphere objects around one land-cell corner, asked at every cylinder's
        // rim corners and just outside them, for movers of several radii: the partitioned scene answers as its
        // exhaustive walk, and blocks at every corner.
        var random = new Random(31);
        var corner = new Vector3(72f, 96f, 5f);
        for (var i = 0; i < 12; i++)
        {
            var objects = new List<PlacedQuery>();
            var cylinders = new List<(float Radius, float Height, PlacedQuery Entry)>();
            for (var k = 0; k < 6; k++)
            {
                var position = corner + new Vector3((random.NextSingle() - 0.5f) * 8f, (random.NextSingle() - 0.5f) * 8f, random.NextSingle() * 2f);
                var axis = Vector3.Normalize(new Vector3(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f));
                var rotation = Quaternion.CreateFromAxisAngle(axis, random.NextSingle() * 6.3f);
                if (k % 2 == 0)
                {
                    float radius = 0.05f + random.NextSingle(), height = 0.05f + random.NextSingle() * 3f;
                    var (center, boundRadius) = SceneCompiler.Bound(ShapeBounds.Of(ObjectOverlapQuery.Create([CylinderShape(radius, height)], _ => null).Shapes));
                    var entry = PlacedParts.Of(k, 0x02000001u, position, rotation, new AnyOverlap([new CylinderShapeQuery(Vector3.Zero, radius, height)]), center, boundRadius).Single();
                    objects.Add(entry);
                    cylinders.Add((radius, height, entry));
                }
                else
                {
                    var sphere = 0.1f + random.NextSingle();
                    objects.Add(new PlacedQuery(k, 0x02000002u, position, rotation, new SphereShapeQuery(Vector3.Zero, sphere), Vector3.Zero, sphere));
                }
            }
            var scene = new SceneQuery(objects);
            Assert.Equal(cylinders.Count, scene.Partition.Stretched);
            foreach (var mover in new[] { 0.25f, 0.5f, 1.5f, 0.05f + random.NextSingle() * 3f })
                foreach (var (radius, height, entry) in cylinders)
                    foreach (var local in Corners(radius, height, mover))
                    {
                        var at = entry.Frame.ToEntity(local);
                        Assert.True(scene.Overlaps(at, mover), $"{local} r {mover}: a rim corner answered clear");
                        Assert.True(scene.Exhaustive.Overlaps(at, mover));
                        var outside = entry.Frame.ToEntity(local + 0.02f * Vector3.Normalize(local - new Vector3(0f, 0f, height / 2)));
                        Assert.True(scene.Overlaps(outside, mover) == scene.Exhaustive.Overlaps(outside, mover), $"{outside} r {mover}");
                    }
        }
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

    /// <summary>The cylinder tilted 45° about y the way that puts <paramref name="local"/> furthest along landblock x from its bound's centre, and how far.</summary>
    private static (Quaternion Rotation, float Along) TiltedTowardX(float radius, float height, Vector3 local)
    {
        var best = (Rotation: Quaternion.Identity, Along: float.MinValue);
        foreach (var angle in new[] { MathF.PI / 4, -MathF.PI / 4, 3 * MathF.PI / 4, -3 * MathF.PI / 4 })
        {
            var rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitY, angle);
            var entry = Scenes(radius, height, Vector3.Zero, rotation)[0].Objects[0];
            var along = entry.Frame.ToEntity(local).X - entry.LandblockBound.Center.X;
            if (along > best.Along) best = (rotation, along);
        }
        return best;
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
    /// once, and (<paramref name="neighbour"/>) a second Setup, a 0.5 m sphere at its origin, placed there unturned: the all-retail scene, the
    /// compiled scene (parts apart), and the consumer's registration (<see cref="PlacedParts"/> over the file's shapes).
    /// </summary>
    private static SceneQuery[] Scenes(float radius, float height, Vector3 position, Quaternion rotation, Vector3? sphere = null, Vector3? neighbour = null)
    {
        ShadowShape[] shapes = [CylinderShape(radius, height), .. sphere is { } at ? [SphereShape(at)] : Array.Empty<ShadowShape>()];
        var timing = new TimingStats(0, 0, 0, []);
        var compiled = new Dictionary<(SceneObjectKind, uint), ObjectCompilation>();
        foreach (var (id, modelShapes) in new[] { (0x02000001u, shapes), (0x02000002u, [SphereShape(Vector3.Zero)]) })
        {
            var query = ObjectOverlapQuery.Create(modelShapes, _ => null);
            var model = new PreparedModel(query, query.Shapes, []);
            compiled[(SceneObjectKind.Setup, id)] = new(id, SceneObjectKind.Setup, "retail", model, model, ProbeSpheres.Empty, [], timing, timing, ShapeBounds.Of(model.Shapes), []);
        }
        AcShadow.Analysis.Compile.PlacedObject[] placed = [new(new SceneObject(0, ScenePlacedBy.Object, 0, 0x02000001u, SceneObjectKind.Setup, new Frame(position, rotation)), null),
            .. neighbour is { } n ? [new AcShadow.Analysis.Compile.PlacedObject(new SceneObject(1, ScenePlacedBy.Object, 0, 0x02000002u, SceneObjectKind.Setup, new Frame(n, Quaternion.Identity)), null)] : Array.Empty<AcShadow.Analysis.Compile.PlacedObject>()];
        var (center, boundRadius) = SceneCompiler.Bound(compiled[(SceneObjectKind.Setup, 0x02000001u)].Bounds);
        var consumer = new SceneQuery([.. PlacedParts.Of(0, 0x02000001u, position, rotation, new AnyOverlap([new CylinderShapeQuery(Vector3.Zero, radius, height), .. sphere is { } c ? [new SphereShapeQuery(c, 0.5f)] : Array.Empty<ISphereOverlap>()]), center, boundRadius),
            .. neighbour is { } other ? PlacedParts.Of(1, 0x02000002u, other, Quaternion.Identity, new AnyOverlap([new SphereShapeQuery(Vector3.Zero, 0.5f)]), Vector3.Zero, 0.5f) : []]);
        return [SceneCompiler.Query(placed, compiled, [], c => c.Retail), SceneCompiler.Query(placed, compiled, [], c => c.Chosen, partsApart: true), consumer];
    }

    private static ShadowShape CylinderShape(float radius, float height) =>
        new(ShapeSource.CylSphere, 0, null, CollisionType.Cylinder, Vector3.Zero, Quaternion.Identity, 1f, radius, height, null);

    private static ShadowShape SphereShape(Vector3 at) => new(ShapeSource.Sphere, 0, null, CollisionType.Sphere, at, Quaternion.Identity, 1f, 0.5f, 0f, null);
}
