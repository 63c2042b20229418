using AcShadow.Core.Dat;
using BenchmarkDotNet.Attributes;

namespace AcShadow.Bench;

/// <summary>The reader on the realistic-scale dat: opening (header + whole B-tree), and decoding every object.</summary>
[MemoryDiagnoser]
public class DatReadBenchmarks
{
    [GlobalSetup]
    public void Setup() => _ = ScaleDat.PortalBytes;

    [Benchmark]
    public int OpenAndWalkDirectory()
    {
        using var dat = ScaleDat.Open();
        return dat.Archive.Entries.Count;
    }

    [Benchmark]
    public int DecodeEverySetup()
    {
        using var dat = ScaleDat.Open();
        var parts = 0;
        foreach (var id in dat.ListIds(DatObjectKind.Setup)) parts += dat.ReadSetup(id)!.Parts.Count;
        return parts;
    }

    [Benchmark]
    public int DecodeEveryGfxObj()
    {
        using var dat = ScaleDat.Open();
        var polygons = 0;
        foreach (var id in dat.ListIds(DatObjectKind.GfxObj)) polygons += dat.ReadGfxObj(id)!.PhysicsPolygons.Count;
        return polygons;
    }
}
