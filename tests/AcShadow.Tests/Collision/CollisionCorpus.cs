using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Dat;
using AcShadow.Fixtures.Bsp;
using AcShadow.Forging.Bsp;
using AcShadow.Forging;

namespace AcShadow.Tests.Collision;

/// <summary>
/// The parts the property tests run over: the built-in sample's GfxObjs (the forge's trees, read from its
/// dat), and test meshes with trees from both the forge's builder and <see cref="TestBspBuilder"/> (in
/// both, solid leaves hold polygons, so the retail centre check runs).
/// </summary>
public static class CollisionCorpus
{
    private static readonly Lazy<IReadOnlyList<BspDump>> SampleDumps = new(() =>
    {
        var (portal, _) = SampleDats.Build();
        using var dat = DatDatabase.Open(new MemoryStream(portal), "sample_portal.dat");
        return dat.ListIds(DatObjectKind.GfxObj)
            .Select(id => dat.ReadGfxObj(id))
            .Where(g => g is not null)
            .Select(g => BspExtractor.Extract(g!))
            .Where(d => d is not null)
            .Select(d => d!)
            .ToArray();
    });

    public static IReadOnlyList<BspDump> Sample => SampleDumps.Value;

    public static IEnumerable<(string Name, TestMesh Mesh)> Meshes()
    {
        yield return ("box", TestMesh.Box(new(0, 0, 1), new(0.5f, 0.25f, 1)));
        yield return ("turned box", TestMesh.Box(new(0.3f, -0.2f, 0.7f), new(0.8f, 0.1f, 0.6f), Quaternion.CreateFromYawPitchRoll(0.4f, 0.3f, -0.2f)));
        yield return ("wedge", TestMesh.Wedge(new(-1, -0.5f, 0), 2, 1, 0.6f));
        yield return ("floor", TestMesh.Floor(1, 1, 0));
        yield return ("leaf and jamb", TestMesh.Box(new(0, 0, 1.1f), new(0.965f, 0.13f, 1.1f)).Plus(TestMesh.Box(new(1.05f, 0, 1.15f), new(0.05f, 0.15f, 1.15f))));
        // Non-planar faces, far beyond the 1e-4 m tolerance: the reference's per-polygon sphere filter must
        // still pass every polygon the exact test would touch.
        yield return ("twisted floor", TestMesh.Floor(1, 1, 0).Pulled(1, new(0, 0, 0.35f)).Pulled(3, new(0, 0, 0.2f)));
        yield return ("box with a pulled corner", TestMesh.Box(new(0, 0, 0.8f), new(0.6f, 0.4f, 0.8f)).Pulled(7, new(0.25f, -0.2f, 0.3f)));
        yield return ("stairs", TestMesh.Box(new(0, 0, 0.1f), new(1, 0.5f, 0.1f)).Plus(TestMesh.Box(new(0.3f, 0, 0.3f), new(0.7f, 0.5f, 0.1f))).Plus(TestMesh.Box(new(0.6f, 0, 0.5f), new(0.4f, 0.5f, 0.1f))));
    }

    public static IEnumerable<(string Name, BspDump Dump)> Forged()
    {
        uint id = 0x01007000;
        foreach (var (name, mesh) in Meshes())
        {
            yield return ($"{name} (test tree)", TestGfx.Dump(id++, mesh));
            yield return ($"{name} (forge tree)", TestGfx.Dump(id++, mesh, PhysicsBspBuilder.Build(mesh.Vertices, mesh.Polygons.Select(p => (IReadOnlyList<short>)p).ToArray())));
        }
    }
}
