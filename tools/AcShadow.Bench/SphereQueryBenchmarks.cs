using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Fixtures.Collision;
using BenchmarkDotNet.Attributes;

namespace AcShadow.Bench;

/// <summary>
/// The collision reference (BSP traversal) against the brute-force oracle on the sample's deepest BSP
/// (the ≥200-polygon house), over a fixed set of player-size probes around it.
/// </summary>
public class SphereQueryBenchmarks
{
    private ISphereOverlap _reference = null!;
    private ISphereOverlap _bruteForce = null!;
    private Vector3[] _probes = [];

    [GlobalSetup]
    public void Setup()
    {
        var (portal, _) = AcShadow.Forging.SampleDats.Build();
        using var dat = AcShadow.Core.Dat.DatDatabase.Open(new MemoryStream(portal), "sample");
        var dump = BspExtractor.Extract(dat.ReadGfxObj(SampleIds.House)!)!;
        _reference = BspSphereQuery.From(dump);
        _bruteForce = BruteForceSphereQuery.From(dump);
        var random = new Random(1);
        var c = dump.BoundingSphere.Center;
        var r = dump.BoundingSphere.Radius;
        _probes = Enumerable.Range(0, 4096)
            .Select(_ => c + new Vector3((float)(random.NextDouble() * 2 - 1), (float)(random.NextDouble() * 2 - 1), (float)(random.NextDouble() * 2 - 1)) * r)
            .ToArray();
    }

    [Benchmark(Baseline = true, OperationsPerInvoke = 4096)]
    public int Reference() => Count(_reference);

    [Benchmark(OperationsPerInvoke = 4096)]
    public int BruteForce() => Count(_bruteForce);

    private int Count(ISphereOverlap query)
    {
        var hits = 0;
        foreach (var p in _probes) if (query.Overlaps(p, 0.5f)) hits++;
        return hits;
    }
}
