using AcShadow.Forging;
using AcShadow.Forging.Geometry;
using AcShadow.Forging.Spec;
using BenchmarkDotNet.Attributes;

namespace AcShadow.Bench;

/// <summary>
/// The forge's PhysicsBSP builder on a 302-polygon part (a subdivided box with a prism on top): the
/// cost the tests used to assert with a stopwatch, measured here instead.
/// </summary>
public class ForgeBspBenchmarks
{
    private ForgeSpec _spec = null!;

    [GlobalSetup]
    public void Setup()
    {
        var mesh = new MeshBuilder().Box(new(-2, -2, 0), new(2, 2, 4), 7, 7, 7);
        mesh.Prism(new(0, 0, 4), 1, 1, 6);
        _spec = new ForgeSpec { GfxObjs = [mesh.ToSpec(0x01000001, true, false)] };
    }

    [Benchmark]
    public int Build300PolygonPart() => SpecCompiler.ToGfxObj(SpecValidator.Validate(_spec).GfxObjs[0]).PhysicsPolygons.Count;
}
