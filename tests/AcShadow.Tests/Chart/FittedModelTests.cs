using AcShadow.Forge;
using System.Numerics;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Analysis.Fitting;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Poses;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;
using AcShadow.Forging;
using AcShadow.Tests.Collision;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Chart;

/// <summary>
/// part-boxes and part-hulls: exact in their own geometry (a box part as a box, a convex part as a hull)
/// on every probe, the stability probes at the boundary included; not exact where the part is not that
/// shape (an L, a jamb with a threshold).
/// </summary>
public class FittedModelTests
{
    private static readonly IShapeModel[] Fitted = [new RetailModel(), new PartBoxesModel(), new PartHullsModel()];

    private static ObjectChart ChartOf(ChartSubject subject, ChartOptions? options = null) =>
        ChartRunner.Chart(subject, options ?? new ChartOptions(), Fitted, new FixedTimer());

    /// <summary>A one-part object whose part is the mesh, its BSP built by the tests' own builder, posed at <paramref name="at"/>.</summary>
    private static ChartSubject Hand(TestMesh mesh, Vector3 at, float scale = 1f)
    {
        var gfx = TestGfx.Make(0x01000100, mesh);
        var setup = Records.Setup(0x02000100, [gfx.Id], [Records.PlacementAt(Placement.Resting, at)]);
        var bsps = new CompiledBspCache(id => id == gfx.Id ? AcShadow.Core.Bsp.BspExtractor.Extract(gfx) : null);
        return new ChartSubject(setup, Records.Lookup(gfx), bsps.Get, scale);
    }

    private static ModelOutcome Model(ObjectChart chart, string name) => chart.Models.Single(m => m.Model == name);

    [Fact]
    public void The_sample_door_leaf_a_box_is_exact_as_part_boxes_on_every_probe_and_stability_probe()
    {
        var leaf = SampleChart.Subjects.Value.ForBareGfxObj(SampleSpecAuthor.DoorLeaf)!;
        var chart = ChartOf(leaf);
        var boxes = Model(chart, "part-boxes");
        Assert.True(boxes.Exact, $"{boxes.FalsePass} false pass, {boxes.FalseBlock} false block");
        Assert.True(Model(chart, "part-hulls").Exact);
        Assert.All(ProbeKinds.Stability, kind => Assert.True(ChartProbes.Count(chart.Probes, kind) > 0, $"no {kind} probes"));
        var box = Assert.Single(PreparedBoxes(leaf));
        Assert.Equal(new Vector3(0.965f, 0.13f, 1.1f), box.HalfExtents);
    }

    [Theory]
    [InlineData(DoorState.Closed)]
    [InlineData(DoorState.Open)]
    public void Fitted_parts_take_the_pose_and_door_state_the_retail_model_takes(DoorState state)
    {
        var pose = new ShapeBuildOptions(ShapePolicy.Retail) { DoorState = state };
        var door = new ChartSubjects(SampleChart.Subjects.Value.Dat, pose).For(SampleChart.Door)!;
        var retail = new RetailModel().Prepare(door).Shapes.Where(s => s.Bsp is not null).Select(s => (s.Name, s.Pose)).ToArray();
        Assert.Equal(3, retail.Length);
        foreach (var model in new IShapeModel[] { new PartBoxesModel(), new PartHullsModel() })
            Assert.Equal(retail, model.Prepare(door).Shapes.Select(s => (s.Name, s.Pose)).ToArray());
        // A solid that contains each correctly posed part can block more than retail, never less.
        var chart = ChartOf(door);
        Assert.Equal(0, Model(chart, "part-boxes").FalsePass);
        Assert.Equal(0, Model(chart, "part-hulls").FalsePass);
    }

    private static IEnumerable<OrientedBox> PreparedBoxes(ChartSubject subject) =>
        new PartBoxesModel().Prepare(subject).Shapes.Select(s => s.Box!.Value);

    [Fact]
    public void A_box_turned_inside_its_part_is_exact_along_its_principal_axes()
    {
        var turn = Quaternion.CreateFromYawPitchRoll(0.5f, 0.3f, 0.2f);
        var mesh = TestMesh.Box(new Vector3(0.2f, -0.1f, 1f), new Vector3(0.9f, 0.15f, 1.1f), turn);
        var subject = Hand(mesh, new Vector3(2f, 1f, 0f));
        var box = Assert.Single(PreparedBoxes(subject));
        Assert.Equal(8.0 * 0.9 * 0.15 * 1.1, box.Volume, 3);
        var chart = ChartOf(subject);
        Assert.True(Model(chart, "part-boxes").Exact, $"{Model(chart, "part-boxes").FalseBlock} false block, {Model(chart, "part-boxes").FalsePass} false pass");
        Assert.True(Model(chart, "part-hulls").Exact);
    }

    [Fact]
    public void An_l_shaped_part_is_neither_a_box_nor_a_hull_and_both_only_block_too_much()
    {
        // Two boxes meeting in an L: the box and the hull both fill the inner corner.
        var l = TestMesh.Box(new Vector3(0, 0, 0.5f), new Vector3(1f, 0.25f, 0.5f)).Plus(TestMesh.Box(new Vector3(0.75f, 1f, 0.5f), new Vector3(0.25f, 0.75f, 0.5f)));
        var chart = ChartOf(Hand(l, Vector3.Zero));
        foreach (var name in new[] { "part-boxes", "part-hulls" })
        {
            var m = Model(chart, name);
            Assert.False(m.Exact, name);
            Assert.True(m.FalseBlock > 0, name);
            Assert.Equal(0, m.FalsePass);
        }
        var sample = ChartOf(SampleChart.Subjects.Value.ForBareGfxObj(SampleSpecAuthor.LBlock)!);
        Assert.False(Model(sample, "part-boxes").Exact);
        Assert.False(Model(sample, "part-hulls").Exact);
    }

    [Fact]
    public void A_convex_wedge_is_exact_as_its_hull_but_not_as_a_box()
    {
        var chart = ChartOf(Hand(TestMesh.Wedge(new Vector3(-1, -0.5f, 0), 2f, 1f, 0.8f), new Vector3(0, 0, 0.2f)));
        Assert.True(Model(chart, "part-hulls").Exact, $"{Model(chart, "part-hulls").FalseBlock} false block, {Model(chart, "part-hulls").FalsePass} false pass");
        Assert.False(Model(chart, "part-boxes").Exact);
    }

    [Fact]
    public void The_sample_door_is_not_exact_as_boxes_or_hulls_because_a_jamb_carries_its_threshold()
    {
        var door = ChartOf(SampleChart.Subjects.Value.For(SampleChart.Door)!);
        Assert.False(Model(door, "part-boxes").Exact);
        // The jamb's hull fills the wedge between post and threshold: a few centimetres beside the leaf.
        Assert.True(Model(door, "part-hulls").FalseBlock > 0);
    }

    [Fact]
    public void A_scaled_part_keeps_epsilon_in_part_units_as_retail_does()
    {
        var chart = ChartOf(Hand(TestMesh.Box(Vector3.Zero, new Vector3(0.5f, 0.4f, 0.3f)), Vector3.Zero, scale: 3f));
        Assert.True(Model(chart, "part-boxes").Exact);
        Assert.True(Model(chart, "part-hulls").Exact);
    }

    [Fact]
    public void Boxes_and_hulls_follow_retails_touching_rules()
    {
        var reach = 0.5f - PhysicsEpsilon.Value;
        // A face the shrunk sphere only touches is clear (BSPNODE: dist >= r - eps goes to the empty side alone).
        // A box flat in x puts that face at x = 0, where the distance is computed without rounding.
        var flat = new OrientedBox(Vector3.Zero, Quaternion.Identity, new Vector3(0f, 0.5f, 0.25f));
        foreach (ISphereOverlap solid in new ISphereOverlap[] { new BoxSphereQuery(flat), flat.ToPolytope() })
        {
            Assert.False(solid.Overlaps(new Vector3(reach, 0, 0), 0.5f));
            Assert.True(solid.Overlaps(new Vector3(MathF.BitDecrement(reach), 0, 0), 0.5f));
            Assert.False(solid.Overlaps(Vector3.Zero, PhysicsEpsilon.Value));
        }
        var box = new OrientedBox(Vector3.Zero, Quaternion.Identity, new Vector3(1f, 0.5f, 0.25f));
        foreach (ISphereOverlap solid in new ISphereOverlap[] { new BoxSphereQuery(box), box.ToPolytope() })
        {
            Assert.True(solid.Overlaps(new Vector3(1f + reach - 1e-4f, 0, 0), 0.5f));
            Assert.False(solid.Overlaps(new Vector3(1f + reach + 1e-4f, 0, 0), 0.5f));
            // Beyond an edge: true distance, not a padded box.
            var diagonal = reach / MathF.Sqrt(2f);
            Assert.True(solid.Overlaps(new Vector3(1f + diagonal - 1e-4f, 0.5f + diagonal - 1e-4f, 0), 0.5f));
            Assert.False(solid.Overlaps(new Vector3(1f + diagonal + 1e-4f, 0.5f + diagonal + 1e-4f, 0), 0.5f));
            Assert.False(solid.Overlaps(new Vector3(1f + reach - 1e-3f, 0.5f + reach - 1e-3f, 0), 0.5f));
            // A centre inside blocks, even for a sphere smaller than epsilon.
            Assert.True(solid.Overlaps(new Vector3(0.1f, 0.1f, 0.1f), 0.0001f));
            Assert.False(solid.Overlaps(new Vector3(float.NaN, 0, 0), 0.5f));
        }
    }

    [Fact]
    public void Stability_probes_straddle_retails_boundary_for_every_mover_radius()
    {
        var leaf = SampleChart.Subjects.Value.ForBareGfxObj(SampleSpecAuthor.DoorLeaf)!;
        var options = new ChartOptions { MoverRadii = [0.3f, 1.2f] };
        var retail = new RetailModel().Prepare(leaf);
        var probes = StabilityProbes.Build(retail.Shapes, options);
        Assert.Equal([0.5f, 0.3f, 1.2f], probes.Select(p => p.Radius).Distinct());
        // Each face point gives (front: short, past), (behind: short, past), (across: behind, in front);
        // on a closed box, the first of a front pair blocks and the second is clear.
        var faces = probes.Where(p => p.Kind == ProbeKind.Face).ToArray();
        for (var i = 0; i < faces.Length; i += 6)
        {
            Assert.True(retail.Overlaps(faces[i].Center, faces[i].Radius), $"face probe {i}");
            Assert.False(retail.Overlaps(faces[i + 1].Center, faces[i + 1].Radius), $"face probe {i + 1}");
        }
        foreach (var kind in new[] { ProbeKind.Edge, ProbeKind.Vertex })
        {
            var pairs = probes.Where(p => p.Kind == kind).ToArray();
            for (var i = 0; i < pairs.Length; i += 2)
            {
                Assert.True(retail.Overlaps(pairs[i].Center, pairs[i].Radius), $"{kind} probe {i}");
                Assert.False(retail.Overlaps(pairs[i + 1].Center, pairs[i + 1].Radius), $"{kind} probe {i + 1}");
            }
        }
    }

    [Fact]
    public void Hulls_keep_only_corners_and_take_the_parts_own_planes()
    {
        // A box with subdivided faces: 2x2x1 lattice of extra vertices on its faces and edges.
        var gfx = SampleChart.Subjects.Value.GfxObj(SampleSpecAuthor.Pedestal)!;
        var bsp = SampleChart.Subjects.Value.Bsps.Get(gfx.Id)!;
        var vertices = bsp.Polygons.SelectMany(p => p.Vertices).Distinct().ToArray();
        var hull = ConvexHullBuilder.Build(vertices, bsp.Polygons.Select(p => new Plane(p.Normal, p.D)).ToArray())!;
        Assert.Equal(8, hull.Vertices.Count);
        Assert.Equal(6, hull.Faces.Count);
        foreach (var face in hull.Faces)
            Assert.Contains(bsp.Polygons, p => p.Normal == face.Normal && p.D == face.D);
        Assert.Null(ConvexHullBuilder.Build([Vector3.Zero, Vector3.UnitX, new Vector3(2, 0, 0)], []));
        var flat = ConvexHullBuilder.Build([Vector3.Zero, Vector3.UnitX, Vector3.UnitY, new Vector3(1, 1, 0)], [])!;
        Assert.Equal(2, flat.Faces.Count);
        Assert.False(flat.Overlaps(new Vector3(0.5f, 0.5f, 0.6f), 0.5f));
        Assert.True(flat.Overlaps(new Vector3(0.5f, 0.5f, 0.4f), 0.5f));
    }
}
