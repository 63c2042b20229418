using System.Numerics;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Chart;

public class ShapeModelTests
{
    private static ChartSubject Subject(Setup setup) => new(setup, _ => null, _ => null);

    [Fact]
    public void Models_are_registered_in_chart_order_with_unique_names()
    {
        Assert.Equal(["retail", "union", "fallback-cylinder", "spheres", "part-spheres", "part-boxes", "part-hulls", "placement-pose"], ShapeModels.All.Select(m => m.Name));
        Assert.Same(ShapeModels.All[2], ShapeModels.Find("Fallback-Cylinder"));
    }

    [Fact]
    public void Fallback_cylinder_is_the_setup_radius_by_height_at_the_origin_whatever_cylspheres_or_spheres_the_setup_has()
    {
        var model = new FallbackCylinderModel();
        var withCyl = Records.Setup(0x02000001, [], cyls: [new CylSphere(new(1, 0, 0), 0.3f, 1.5f)],
            spheres: [new Sphere(new(9, 0, 0), 2f)], radius: 0.5f, height: 1f);
        var a = model.Prepare(Subject(withCyl));
        Assert.True(a.Overlaps(new Vector3(0.9f, 0, 0.5f), 0.5f));
        Assert.False(a.Overlaps(new Vector3(1.7f, 0, 0.5f), 0.5f));

        var door = Records.Setup(0x02000003, [], spheres: [new Sphere(new(0, 0, 0.018f), 0.1f)], radius: 0.141f, height: 0.2f);
        var c = Assert.Single(model.Prepare(Subject(door)).Shapes);
        Assert.Equal((CollisionType.Cylinder, 0.141f, 0.2f, Vector3.Zero), (c.Shape.CollisionType, c.Shape.Radius, c.Shape.CylHeight, c.Shape.LocalPosition));
        Assert.Equal("Setup Radius x Height", c.Name);
    }

    [Fact]
    public void Spheres_takes_every_cylsphere_and_sphere()
    {
        var setup = Records.Setup(0x02000004, [], cyls: [new CylSphere(new(1, 0, 0), 0.3f, 1.5f)], spheres: [new Sphere(new(9, 0, 0), 2f), new Sphere(new(-9, 0, 0), 1f)]);
        var prepared = new SpheresModel().Prepare(Subject(setup));
        Assert.Equal([CollisionType.Cylinder, CollisionType.Sphere, CollisionType.Sphere], prepared.Shapes.Select(p => p.Shape.CollisionType));
        Assert.True(prepared.Overlaps(new Vector3(-9, 0, 1.2f), 0.5f));
    }

    [Fact]
    public void Part_spheres_are_the_posed_root_spheres_of_the_retail_bsp_parts()
    {
        var gfx = Records.BoxGfxObj(0x01000001);
        var setup = Records.Setup(0x02000005, [gfx.Id], [Records.PlacementAt(Placement.Resting, new Vector3(3, 0, 0))]);
        var bsps = new CompiledBspCache(id => id == gfx.Id ? AcShadow.Core.Bsp.BspExtractor.Extract(gfx) : null);
        var prepared = new PartSpheresModel().Prepare(new ChartSubject(setup, Records.Lookup(gfx), bsps.Get));
        var sphere = Assert.Single(prepared.Shapes).Shape;
        Assert.Equal(CollisionType.Sphere, sphere.CollisionType);
        Assert.Equal(new Vector3(3, 0, 0), sphere.LocalPosition);
        Assert.Equal(0.75f, sphere.Radius);
    }

    [Fact]
    public void A_model_that_throws_blocks_nothing_and_the_chart_says_why()
    {
        var report = SampleChart.Run([SampleSubject()], new ChartOptions(), [new RetailModel(), new ThrowingModel()], new FixedTimer());
        var broken = report.Objects.Single().Models[1];
        Assert.All(broken.Answers, a => Assert.False(a));
        Assert.Contains(broken.Diagnostics, d => d.Code == ChartRunner.ModelFailed && d.Message.Contains("boom"));
    }

    private static ChartSubject SampleSubject()
    {
        var (portal, _) = AcShadow.Forging.SampleDats.Build();
        return new ChartSubjects(AcShadow.Core.Dat.DatDatabase.Open(new MemoryStream(portal), "p.dat")).For(0x02002000)!;
    }

    private sealed class ThrowingModel : IShapeModel
    {
        public string Name => "throws";
        public string Description => "always throws";
        public PreparedModel Prepare(ChartSubject subject) => throw new InvalidOperationException("boom");
    }
}
