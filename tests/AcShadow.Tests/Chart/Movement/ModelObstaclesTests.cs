using System.Numerics;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Analysis.Chart.Movement;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Geometry;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Chart.Movement;

/// <summary>Models as the client's primitives: a box part's one-leaf BSP walks as the part's own tree does; spheres and cylinders keep their branch.</summary>
public class ModelObstaclesTests
{
    /// <summary>The sample door's leaf (GfxObj 0x010044B5, a 1.93 × 0.26 × 2.2 m box) alone, as a landblock places a bare GfxObj.</summary>
    private static ChartSubject Leaf() => SampleChart.Subjects.Value.ForBareGfxObj(0x010044B5)!;

    [Fact]
    public void A_box_part_fitted_as_a_box_or_a_hull_is_a_one_leaf_bsp_of_its_faces_and_walks_as_the_parts_tree_does()
    {
        var subject = Leaf();
        var boxes = new PartBoxesModel().Prepare(subject);
        var obstacle = Assert.Single(ModelObstacles.Of(boxes, ethereal: false));
        var shape = Assert.Single(obstacle.Shapes);
        var leaf = obstacle.Bsps[shape.GfxObjId!.Value];
        Assert.Equal(6, leaf.Polygons.Length);
        var root = Assert.Single(leaf.Nodes);
        Assert.True(root.IsLeaf && root.Solid);
        Assert.Equal(6, root.PolygonCount);

        var chart = MovementChartRunner.Chart(subject, SampleMovementChart.Options with { Walk = null },
            [new RetailModel(), new PartBoxesModel(), new PartHullsModel()], new FixedTransitionTimer());
        Assert.Equal(224, chart.Cases.Count);
        Assert.Contains(chart.Cases, c => c.Outcome.Class == AcShadow.Fixtures.Movement.MovementOutcome.Blocked);
        foreach (var model in chart.Models)
            Assert.All(model.Verdicts.Where((_, i) => !chart.Fragile[i]), v => Assert.Equal(MovementVerdict.Agree, v));
    }

    [Fact]
    public void Cylinders_and_spheres_stay_cylinders_and_spheres_each_its_own_object_in_builder_order()
    {
        var setup = Records.Setup(0x02000006, [], cyls: [new CylSphere(new Vector3(1, 0, 0), 0.3f, 1.5f)], spheres: [new Sphere(new Vector3(-2, 0, 0.5f), 0.5f)]);
        var prepared = new SpheresModel().Prepare(new ChartSubject(setup, _ => null, _ => null));
        var objects = ModelObstacles.Of(prepared, ethereal: true);
        Assert.Equal([AcShadow.Fixtures.Shapes.CollisionType.Cylinder, AcShadow.Fixtures.Shapes.CollisionType.Sphere], objects.Select(o => Assert.Single(o.Shapes).CollisionType));
        Assert.All(objects, o => Assert.True(o.Ethereal));
        Assert.All(objects, o => Assert.Equal(AcShadow.Core.Movement.MovementSubject.Origin, o.Position));
    }
}
