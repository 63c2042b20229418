using System.Diagnostics;
using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat;
using AcShadow.Core.Export;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Bench.Harness;

/// <summary>The collision reference against its brute-force oracle on the dat's big GfxObjs.</summary>
public sealed record CollisionResult(int GfxObjs, int MinPolygons, int MedianPolygons, int MaxPolygons, int Queries, int Disagreements,
    IReadOnlyList<double> ReferenceNanoseconds, IReadOnlyList<double> BruteForceNanoseconds);

/// <summary>
/// Per query: up to <see cref="MaxGfxObjs"/> GfxObjs of at least <see cref="MinPolygons"/> physics polygons
/// (spread evenly over the dat's ids), player-size probes (radius 0.5) at seeded random points inside each
/// one's bounding sphere; every probe asked of both, the answers compared, each timed over all probes.
/// </summary>
public static class CollisionComparison
{
    public const int MinPolygons = 200, MaxGfxObjs = 24, ProbesPerGfxObj = 2000;

    public static CollisionResult Run(DatDatabase dat, int repetitions)
    {
        // Find the big ones without keeping every decoded GfxObj: a small working set, then re-read the chosen.
        var scan = new DatDatabase(dat.Archive, cacheCapacity: 64);
        var big = dat.ListIds(DatObjectKind.GfxObj)
            .Where(id => scan.ReadGfxObj(id) is { PhysicsBsp: not null } g && g.PhysicsPolygons.Count >= MinPolygons)
            .ToArray();
        var take = Math.Min(MaxGfxObjs, big.Length);
        var chosen = Enumerable.Range(0, take).Select(k => dat.ReadGfxObj(big[k * big.Length / take])!).ToArray();
        var subjects = chosen.Select(g =>
        {
            var dump = BspExtractor.Extract(g)!;
            var random = new Random((int)g.Id);
            var c = dump.BoundingSphere.Center;
            var r = dump.BoundingSphere.Radius;
            var probes = Enumerable.Range(0, ProbesPerGfxObj)
                .Select(_ => c + new Vector3((float)(random.NextDouble() * 2 - 1), (float)(random.NextDouble() * 2 - 1), (float)(random.NextDouble() * 2 - 1)) * r)
                .ToArray();
            return (Reference: (ISphereOverlap)BspSphereQuery.From(dump), Brute: (ISphereOverlap)BruteForceSphereQuery.From(dump), Probes: probes, Polygons: g.PhysicsPolygons.Count);
        }).ToArray();

        var disagreements = 0;
        foreach (var s in subjects)
            foreach (var p in s.Probes)
                if (s.Reference.Overlaps(p, 0.5f) != s.Brute.Overlaps(p, 0.5f)) disagreements++;

        var queries = subjects.Sum(s => s.Probes.Length);
        double Time(Func<(ISphereOverlap Reference, ISphereOverlap Brute, Vector3[] Probes, int Polygons), ISphereOverlap> pick)
        {
            var clock = Stopwatch.StartNew();
            var hits = 0;
            foreach (var s in subjects)
            {
                var query = pick(s);
                foreach (var p in s.Probes) if (query.Overlaps(p, 0.5f)) hits++;
            }
            GC.KeepAlive(hits);
            return clock.Elapsed.TotalNanoseconds / Math.Max(1, queries);
        }
        Time(s => s.Reference);
        Time(s => s.Brute); // warm-up
        var reference = new List<double>();
        var brute = new List<double>();
        for (var i = 0; i < Math.Max(3, repetitions); i++)
        {
            reference.Add(Time(s => s.Reference));
            brute.Add(Time(s => s.Brute));
        }
        var polygons = subjects.Select(s => s.Polygons).Order().ToArray();
        return new CollisionResult(subjects.Length, polygons.FirstOrDefault(), polygons.Length == 0 ? 0 : polygons[polygons.Length / 2], polygons.LastOrDefault(),
            queries, disagreements, reference, brute);
    }
}
