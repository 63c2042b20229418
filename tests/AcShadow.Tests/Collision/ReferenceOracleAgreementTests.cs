using System.Diagnostics;
using AcShadow.Fixtures.Collision;
using Xunit.Abstractions;

namespace AcShadow.Tests.Collision;

/// <summary>
/// The reference (retail tree traversal) and the brute force answer the same predicate; on trees whose
/// pruning is conservative they must agree on every probe, boundary cases included — except at an exact
/// float tie, dist = ±(r − ε) at a splitting plane, where retail's "dist ≥ reach → positive child only"
/// drops a polygon lying in that plane on the other side. Each such disagreement must be that tie: the
/// reference says clear, the brute force blocked, and a sphere one hair (1e-5 m) larger blocks in both.
/// Forged trees follow retail and keep a polygon lying in a splitting plane on the negative side only, so
/// every probe placed exactly on a face (r = ε) or exactly r − ε in front of one is such a tie: the stress
/// probes aim there on purpose, and ties may be up to 3 % of them.
/// </summary>
public class ReferenceOracleAgreementTests(ITestOutputHelper output)
{
    private const int SampleProbes = 120_000;
    private const int ForgedProbes = 60_000;

    [Fact]
    public void Reference_and_brute_force_agree_on_the_sample_parts()
    {
        var dumps = CollisionCorpus.Sample;
        Assert.NotEmpty(dumps);
        var total = Agree(dumps.Select(d => ($"GfxObj 0x{d.GfxObjId:X8}", CompiledBsp.Compile(d))).ToArray(), SampleProbes, seed: 4);
        Assert.True(total >= SampleProbes);
    }

    [Fact]
    public void Reference_and_brute_force_agree_on_forged_parts()
    {
        var parts = CollisionCorpus.Forged().Select(f => (f.Name, CompiledBsp.Compile(f.Dump))).ToArray();
        var total = Agree(parts, ForgedProbes, seed: 7);
        Assert.True(total >= ForgedProbes);
    }

    [Fact]
    public void The_forged_parts_include_polygons_far_from_planar()
    {
        // Without them the agreement above would never exercise the sphere filter's slack for non-planar polygons.
        var twisted = CollisionCorpus.Forged().Where(f => f.Dump.Stats.NonPlanarPolygons.Count > 0).Select(f => f.Name).ToArray();
        Assert.Equal(4, twisted.Length);
        Assert.All(twisted, name => Assert.True(name.StartsWith("twisted", StringComparison.Ordinal) || name.StartsWith("box with a pulled corner", StringComparison.Ordinal), name));
    }

    private int Agree((string Name, CompiledBsp Bsp)[] parts, int probes, int seed)
    {
        var watch = Stopwatch.StartNew();
        var perPart = probes / parts.Length + 1;
        var failures = new List<string>();
        var total = 0;
        var tiesTotal = 0;
        var tieKinds = new SortedDictionary<string, int>(StringComparer.Ordinal);
        foreach (var (name, bsp) in parts)
        {
            Assert.True(bsp.PruningIsConservative, $"{name}: {string.Join("; ", bsp.Diagnostics)}");
            var reference = new BspSphereQuery(bsp);
            var oracle = new BruteForceSphereQuery(bsp);
            var blocked = 0;
            var ties = 0;
            foreach (var (center, radius, kind) in StressProbes.For(bsp, perPart, seed + total))
            {
                var a = reference.Overlaps(center, radius);
                var b = oracle.Overlaps(center, radius);
                if (a) blocked++;
                total++;
                if (a == b) continue;
                if (!a && b && reference.Overlaps(center, radius + 1e-5f) && oracle.Overlaps(center, radius + 1e-5f))
                {
                    ties++;
                    var tieKind = radius == PhysicsEpsilon.Value ? kind + " (r = ε)" : kind;
                    tieKinds[tieKind] = tieKinds.GetValueOrDefault(tieKind) + 1;
                    continue;
                }
                if (failures.Count < 20)
                    failures.Add($"{name}: {kind} probe ({center.X:R}, {center.Y:R}, {center.Z:R}) r={radius:R}: reference {a}, brute force {b}");
            }
            tiesTotal += ties;
            output.WriteLine($"{name}: {perPart} probes, {blocked} blocked, {ties} exact ties");
        }
        output.WriteLine($"{total} probes in {watch.Elapsed.TotalSeconds:0.00} s, {tiesTotal} exact ties ({string.Join(", ", tieKinds.Select(k => $"{k.Key} {k.Value}"))})");
        Assert.True(tiesTotal < total * 3 / 100, $"{tiesTotal} ties in {total} probes: too many to be ties");
        Assert.True(failures.Count == 0, string.Join("\n", failures));
        return total;
    }
}
