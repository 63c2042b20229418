using System.Numerics;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Compile;
using AcShadow.Core.Batch;
using AcShadow.Fixtures;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Scenes;
using AcShadow.Tests.Chart;
using AcShadow.Tests.Forge;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Scenes;

/// <summary>
/// The land-cell partition (objects registered in the 24 m land cells their bound covers, as
/// calc_cross_cells_static registers a shadow; a mover sphere asked of the land cells find_cell_list gives it)
/// answers exactly as the exhaustive walk over every object and every cell: at every position the scene is
/// checked at, on the built-in sample and on landblock 0x0000 of a dat `forge scale` wrote, all-retail and
/// compiled (each posed part registered apart, as the compiled scene asks), and at spheres placed on land-cell edges
/// and tangent to every bound. Indoor cells are registered
/// by their tree's root sphere in the land cells beneath it, a superset of what the client reaches through
/// building portals: no answer the exhaustive walk gives is dropped, so no retail rule had to overrule it.
/// </summary>
public sealed class ScenePartitionTests(SmallScaleFixture scale) : IClassFixture<SmallScaleFixture>
{
    [Fact]
    public void The_partition_answers_as_the_exhaustive_walk_on_every_probe_of_the_sample_landblock()
    {
        var report = SceneCompileTests.Exact.Value;
        var (probes, edges) = AssertSameAnswers(report);
        Assert.Equal(report.Totals.Positions, probes);
        Assert.True(edges > 1_000, $"{edges} edge positions");
        // Every object and cell has a footprint, and the partition asks less than the exhaustive walk, counted.
        var retail = SceneCompiler.Query(report, c => c.Retail);
        Assert.Equal(0, retail.Partition.Everywhere);
        Assert.True(report.Totals.RetailOps < report.Totals.ExhaustiveOps, $"{report.Totals.RetailOps} vs {report.Totals.ExhaustiveOps}");
        AssertAboveTheNarrowFloor(report.Totals);
    }

    [Fact]
    public void A_partitioned_query_allocates_nothing()
    {
        var report = SceneCompileTests.Exact.Value;
        var probes = Positions(report).ToArray();
        foreach (var (pick, partsApart) in new (Func<ObjectCompilation, AcShadow.Analysis.Chart.Models.PreparedModel?>, bool)[] { (c => c.Retail, false), (c => c.Chosen, true) })
        {
            var query = SceneCompiler.Query(report, pick, partsApart);
            var blocked = 0;
            foreach (var (at, r) in probes) blocked += query.Overlaps(at, r) ? 1 : 0;
            var before = GC.GetAllocatedBytesForCurrentThread();
            foreach (var (at, r) in probes) blocked += query.Overlaps(at, r) ? 1 : 0;
            Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
            Assert.InRange(blocked, 2, 2 * probes.Length - 2);
        }
    }

    [Fact]
    public void The_partition_answers_as_the_exhaustive_walk_on_every_probe_of_a_forged_scale_landblock()
    {
        Assert.True(LandblockIds.TryParse("0x0000", out var landblock));
        var scene = BatchPlanner.Plan(new BatchSelection(false, false, null, landblock), scale.Files.Portal, scale.Files.Cell, []).Scene!;
        var subjects = new ChartSubjects(scale.Files.Portal);
        // A 1 m grid keeps the compile to seconds; the stability probes still sit on every polygon and plane.
        var options = new SceneCompileOptions { Chart = new ChartOptions { Spacing = 1f } };
        var report = SceneCompiler.Compile(scene, subjects, options, new FixedTimer());
        Assert.True(report.Placed.Count >= 20, $"{report.Placed.Count} placed objects");
        var (probes, edges) = AssertSameAnswers(report);
        Assert.Equal(report.Totals.Positions, probes);
        Assert.True(probes > 10_000, $"{probes} positions");
        Assert.True(edges > 1_000, $"{edges} edge positions");
        // Counted along the walks: the partition asks less than the exhaustive walk.
        Assert.True(report.Totals.RetailOps < report.Totals.ExhaustiveOps, $"{report.Totals.RetailOps} vs {report.Totals.ExhaustiveOps}");
        AssertAboveTheNarrowFloor(report.Totals);
    }

    /// <summary>
    /// The narrow-phase floor is what any broad phase must still ask: a clear position's every entry it is within, a
    /// blocked one's cheapest blocker. No walk counts less; the partition pays something for finding its entries.
    /// </summary>
    private static void AssertAboveTheNarrowFloor(SceneTotals totals)
    {
        Assert.True(totals.NarrowFloorOps > 0, $"floor {totals.NarrowFloorOps}");
        Assert.True(totals.NarrowFloorOps < totals.RetailOps, $"floor {totals.NarrowFloorOps} vs partitioned {totals.RetailOps}");
        Assert.True(totals.NarrowFloorOps < totals.ExhaustiveOps, $"floor {totals.NarrowFloorOps} vs exhaustive {totals.ExhaustiveOps}");
    }

    [Fact]
    public void The_loaded_compiled_scene_asks_through_the_partition_and_answers_as_its_exhaustive_walk()
    {
        using var dir = new TempDir();
        var report = SceneCompileTests.Exact.Value;
        foreach (var f in CompiledSceneFiles.Render(report, id => AcShadow.Core.Bsp.BspExtractor.Extract(SampleChart.Subjects.Value.GfxObj(id)!)))
        {
            var path = Path.Combine(dir.Path, f.RelativePath);
            Directory.CreateDirectory(Path.GetDirectoryName(path)!);
            File.WriteAllBytes(path, f.Content.Span);
        }
        var loaded = CompiledScene.Load(dir.Path);
        // Its parts registered apart, as the tool's compiled scene; the tool's object-by-object walk is the oracle.
        var tool = SceneCompiler.Query(report, c => c.Chosen).Exhaustive;
        Assert.True(loaded.Query.Objects.Count > report.Placed.Count, $"{loaded.Query.Objects.Count} entries for {report.Placed.Count} objects");
        var positions = Positions(report).Concat(EdgePositions(loaded.Query)).ToArray();
        foreach (var (at, r) in positions)
        {
            Assert.True(loaded.Overlaps(at, r) == loaded.Query.Exhaustive.Overlaps(at, r), $"{at} r {r}");
            Assert.True(loaded.Overlaps(at, r) == tool.Overlaps(at, r), $"{at} r {r}: the tool's walk");
        }
        Assert.Contains(positions, p => loaded.Overlaps(p.At, p.Radius));
        Assert.Contains(positions, p => !loaded.Overlaps(p.At, p.Radius));
    }

    [Fact]
    public void A_sphere_on_a_land_cell_edge_is_asked_in_every_cell_it_touches_and_an_entry_once()
    {
        // One bound straddling the edge x = 24 and one wholly in cell (2, 0).
        var partition = LandCellPartition.Build([(new Vector3(24f, 10f, 0f), 1f), (new Vector3(60f, 10f, 0f), 2f)]);
        // 0.5 m from the edge: a 0.6 m sphere reaches over it, a 0.25 m one does not.
        Assert.True(partition.Reach(new Vector3(23.5f, 10f, 0f), 0.6f, out var near));
        Assert.Equal(new LandCellPartition.CellRange(0, 0, 1, 0), near);
        Assert.True(partition.Reach(new Vector3(23.5f, 10f, 0f), 0.25f, out var inside));
        Assert.Equal(new LandCellPartition.CellRange(0, 0, 0, 0), inside);
        var asked = new Asked();
        Assert.False(partition.Any(new Vector3(24f, 10f, 0f), 0.5f, ref asked));
        Assert.Equal(new[] { 0 }, asked.Entries);
        Assert.Equal(1, asked.Visits);
        // A sphere just inside cell 1, within r of the edge at 48, is asked in cell 2 as well: the first entry is
        // registered in cell 1 (where its bound reaches), the second in cell 2.
        asked = new Asked();
        partition.Any(new Vector3(47.9f, 10f, 0f), 0.5f, ref asked);
        Assert.Equal(new[] { 0, 1 }, asked.Entries);
        Assert.Equal(1, asked.Visits);
        // Well inside cell 2, away from its edges, only cell 2 is visited.
        asked = new Asked();
        partition.Any(new Vector3(60f, 12f, 0f), 0.5f, ref asked);
        Assert.Equal(new[] { 1 }, asked.Entries);
        Assert.Equal(1, asked.Visits);
        // A bound with no finite centre is asked everywhere, first.
        var odd = LandCellPartition.Build([(new Vector3(float.NaN, 0f, 0f), 1f), null, (new Vector3(5f, 5f, 0f), 1f)]);
        Assert.Equal(2, odd.Everywhere);
        asked = new Asked();
        odd.Any(new Vector3(500f, 500f, 0f), 1f, ref asked);
        Assert.Equal(new[] { 0, 1 }, asked.Entries);
    }

    [Fact]
    public void A_stretched_entry_is_asked_by_a_mover_whose_stretched_radius_reaches_its_land_cell()
    {
        // A bound 1 m wide whose footprint ends in cell 0 (x < 24); a 1.5 m mover 0.4 m into cell 1 beyond the
        // range r alone pads (1.5 · 1.001 + 0.05). With the stretch √2 (a CylSphere's box profile) its range
        // reaches back into cell 0, and the entry is asked.
        (Vector3, float)?[] bounds = [(new Vector3(22.9f, 10f, 0f), 1f)];
        var at = new Vector3(24f + 1.5f * 1.001f + 0.05f + 0.4f, 10f, 0f);
        var plain = LandCellPartition.Build(bounds);
        Assert.False(plain.Reaches(0, at, 1.5f));
        var stretched = LandCellPartition.Build(bounds, [BoundStretch.Cylinder]);
        Assert.True(stretched.Reaches(0, at, 1.5f));
        Assert.False(stretched.Reach(at, 1.5f, out _), "the plain range reaches no footprint");
        Assert.True(stretched.Reach(at, 1.5f, out var cells, stretched: true));
        // The grid holds cell 0 alone (the only footprint), so the range is clamped to it.
        Assert.Equal(new LandCellPartition.CellRange(0, 0, 0, 0), cells);
        var asked = new Asked();
        stretched.Any(at, 1.5f, ref asked);
        Assert.Equal(new[] { 0 }, asked.Entries);
        // 1.2 m further out, past the stretched pad (2.17 m) as well, cell 0 is not asked.
        Assert.False(stretched.Reaches(0, at + new Vector3(1.2f, 0f, 0f), 1.5f));
        Assert.Throws<ArgumentOutOfRangeException>(() => LandCellPartition.Build(bounds, [0.5f]));
        Assert.Throws<ArgumentException>(() => LandCellPartition.Build(bounds, [1f, 1f]));
    }

    [Fact]
    public void A_plain_entry_beside_a_stretched_one_is_asked_only_within_the_plain_range()
    {
        // Two bounds whose footprints end in cell 0, the first stretched (a cylinder's √2), the second plain (a
        // sphere, or a part's reach a hair over 1). The mover 0.4 m into cell 1 beyond its plain range: the stretched
        // entry is asked, the plain one is not, as it would be were every range padded by the scene's largest stretch.
        (Vector3, float)?[] bounds = [(new Vector3(22.9f, 10f, 0f), 1f), (new Vector3(22.9f, 14f, 0f), 1f), (new Vector3(22.9f, 18f, 0f), 1f)];
        var at = new Vector3(24f + 1.5f * 1.0001f * 1.001f + 0.05f + 0.4f, 12f, 0f);
        var partition = LandCellPartition.Build(bounds, [BoundStretch.Cylinder, 1f, 1.0001f]);
        Assert.Equal(1, partition.Stretched);
        var asked = new Asked();
        Assert.False(partition.Any(at, 1.5f, ref asked));
        Assert.Equal(new[] { 0 }, asked.Entries);
        Assert.Equal(1, asked.Visits);
        Assert.True(partition.Reaches(0, at, 1.5f));
        Assert.False(partition.Reaches(1, at, 1.5f));
        Assert.False(partition.Reaches(2, at, 1.5f));
        // 0.5 m nearer, within the plain range, all three are asked, in the cell's order.
        asked = new Asked();
        partition.Any(at - new Vector3(0.5f, 0f, 0f), 1.5f, ref asked);
        Assert.Equal(new[] { 0, 1, 2 }, asked.Entries);
        // A part's reach a hair over 1 is plain.
        Assert.Equal(0, LandCellPartition.Build(bounds, [1f, 1f, 1.0001f]).Stretched);
    }

    [Fact]
    public void An_object_turned_by_a_not_quite_unit_quaternion_is_registered_by_the_reach_its_broad_phase_tests()
    {
        // A half turn about z stored with |q|² = 1.0009 (Frame::IsValid keeps it): the matrix is s·R + (1 − s)·I, so a
        // sphere 60 m out along the entity's x blocks centres 4(s − 1)·60 = 0.22 m further along landblock x than its
        // bound moved into the landblock (plus the mover's r), more than the partition's pads (0.05 m and 0.1 % each
        // side). Registered by its plain sphere, whose footprint ends in land cell 0, it is never asked by a mover
        // whose range lies in cell 1; registered by its broad phase's reach, it is.
        var turn = new Quaternion(0f, 0f, MathF.Sqrt(1.0009f), 0f);
        var sphere = new Vector3(60f, 0f, 0f);
        PlacedQuery Placed(Vector3 position) => new(0, 0x02000001u, position, turn, new SphereShapeQuery(sphere, 0.5f), sphere, 0.5f);
        var probe = Placed(Vector3.Zero);
        var offset = 24f - (0.5f * 1.001f + 0.05f) - 0.01f - probe.LandblockBound.Center.X;
        var scene = new SceneQuery([Placed(new Vector3(offset, 100f, 10f))]);
        var entry = scene.Objects[0];
        Assert.True(LandCellPartition.Footprint(entry.LandblockBound.Center, entry.BoundRadius) is { X1: 0 });
        // The furthest blocked centre along +x, 1 mm inside.
        float inside = 0f, outside = 2f;
        for (var i = 0; i < 40; i++)
        {
            var mid = (inside + outside) / 2;
            if (entry.Overlaps(entry.LandblockBound.Center + new Vector3(mid, 0f, 0f), 0.5f)) inside = mid; else outside = mid;
        }
        var at = entry.LandblockBound.Center + new Vector3(inside - 1e-3f, 0f, 0f);
        Assert.True(inside > 0.5f + 0.5f + 0.2f, $"blocked {inside} m out");
        Assert.True(at.X - (0.5f * entry.RadiusStretch * 1.001f + 0.05f) > 24f, $"{at}: the mover's range is all in cell 1");
        Assert.True(entry.Overlaps(at, 0.5f));
        Assert.True(scene.Exhaustive.Overlaps(at, 0.5f));
        Assert.True(scene.Overlaps(at, 0.5f));
        Assert.True(scene.Partition.Reaches(0, at, 0.5f));
    }

    [Fact]
    public void A_range_s_flat_candidates_are_the_cell_walk_s_entries_in_its_order_each_once()
    {
        // Bounds of every size over and around a landblock; movers from a centimetre to beyond a cell (the
        // cell-by-cell fallback). The reference: every entry whose footprint meets the mover's cells, ordered by
        // the first cell (y then x) both share, then by entry.
        // With and without stretched entries (a cylinder's √2, and a wider 2.5 whose range may be more than a cell
        // wider): each found within its own range, plain and stretched in one order.
        foreach (var stretchedToo in new[] { false, true })
        {
            var random = new Random(30);
            var bounds = Enumerable.Range(0, 60)
                .Select(_ => ((Vector3, float)?)(new Vector3(random.NextSingle() * 240f - 24f, random.NextSingle() * 240f - 24f, 0f), random.NextSingle() * random.NextSingle() * 40f))
                .ToArray();
            float[] stretches = [.. Enumerable.Range(0, bounds.Length).Select(e => !stretchedToo ? 1f : e % 7 == 0 ? BoundStretch.Cylinder : e % 13 == 0 ? 2.5f : e % 2 == 0 ? 1.0001f : 1f)];
            var partition = LandCellPartition.Build(bounds, stretches);
            Assert.Equal(stretches.Count(s => s > 1.01f), partition.Stretched);
            var footprints = bounds.Select(b => LandCellPartition.Footprint(b!.Value.Item1, b.Value.Item2)).ToArray();
            for (var i = 0; i < 4000; i++)
            {
                var at = new Vector3(random.NextSingle() * 300f - 54f, random.NextSingle() * 300f - 54f, 0f);
                var r = i % 10 == 0 ? random.NextSingle() * 40f : random.NextSingle() * 3f;
                var asked = new Asked();
                partition.Any(at, r, ref asked);
                var plainMet = partition.Reach(at, r, out var plain);
                var wideMet = partition.Reach(at, r, out var wide, stretched: true);
                // Each entry's own range: the stretched one past 1.01, the plain one otherwise.
                (bool Met, LandCellPartition.CellRange Cells) RangeOf(int e) => stretches[e] > 1.01f ? (wideMet, wide) : (plainMet, plain);
                int[] expected = [.. Enumerable.Range(0, bounds.Length)
                    .Where(e => footprints[e] is { } f && RangeOf(e).Met && f.Meets(RangeOf(e).Cells))
                    .OrderBy(e => Math.Max(footprints[e]!.Value.Y0, RangeOf(e).Cells.Y0)).ThenBy(e => Math.Max(footprints[e]!.Value.X0, RangeOf(e).Cells.X0)).ThenBy(e => e)];
                Assert.True(expected.SequenceEqual(asked.Entries), $"{at} r {r}: expected {string.Join(",", expected)}, asked {string.Join(",", asked.Entries)}");
                Assert.True(wideMet || !plainMet);
                // One flat array while the plain range is 3 x 3 at most and the stretched one a cell wider at most; else
                // each cell of the stretched range that is in the plain one or holds a stretched entry.
                var flat = plainMet && plain.X1 - plain.X0 < 3 && plain.Y1 - plain.Y0 < 3
                    && plain.X0 - wide.X0 <= 1 && plain.Y0 - wide.Y0 <= 1 && wide.X1 - plain.X1 <= 1 && wide.Y1 - plain.Y1 <= 1;
                var cells = !wideMet ? 0 : Enumerable.Range(wide.Y0, wide.Y1 - wide.Y0 + 1)
                    .SelectMany(y => Enumerable.Range(wide.X0, wide.X1 - wide.X0 + 1).Select(x => (x, y)))
                    .Count(c => plainMet && plain.Holds(c.x, c.y)
                        || Enumerable.Range(0, bounds.Length).Any(e => stretches[e] > 1.01f && footprints[e] is { } f && f.Holds(c.x, c.y)));
                Assert.Equal(!wideMet ? 0 : flat ? 1 : cells, asked.Visits);
            }
        }
    }

    /// <summary>Lists the entries a walk asks, in its order, and counts the candidate lists it loads.</summary>
    internal struct Asked() : LandCellPartition.IEntryTest
    {
        public List<int> Entries { get; } = [];
        public int Visits { get; private set; }

        public readonly bool Test(int entry)
        {
            Entries.Add(entry);
            return false;
        }

        public void Visit() => Visits++;
    }

    /// <summary>
    /// Every scene position (what Totals asks) and every edge position: the partitioned answer and the touched
    /// cells equal the exhaustive walk's (object by object), all-retail, compiled, and compiled with each posed part
    /// registered on its own (<see cref="PlacedParts"/>; its edge positions are tangent to every part's bound).
    /// Returns how many of each were checked.
    /// </summary>
    private static (int Probes, int Edges) AssertSameAnswers(CompiledSceneReport report)
    {
        var probes = Positions(report).ToArray();
        var edges = 0;
        foreach (var (pick, partsApart) in new (Func<ObjectCompilation, AcShadow.Analysis.Chart.Models.PreparedModel?>, bool)[] { (c => c.Retail, false), (c => c.Chosen, false), (c => c.Chosen, true) })
        {
            var oracle = SceneCompiler.Query(report, pick).Exhaustive;
            var query = SceneCompiler.Query(report, pick, partsApart);
            if (partsApart)
                Assert.True(query.Objects.Count > query.Objects.Select(o => o.FrameKey).Distinct().Count(), $"{query.Objects.Count} entries: no object was split into parts");
            var edgeProbes = EdgePositions(query).ToArray();
            edges = edgeProbes.Length;
            int blocked = 0;
            foreach (var (at, r) in probes.Concat(edgeProbes))
            {
                var expected = oracle.Overlaps(at, r);
                Assert.True(expected == query.Overlaps(at, r), $"{at} r {r}: exhaustive {expected} (parts apart: {partsApart})");
                Assert.True(expected == query.Exhaustive.Overlaps(at, r), $"{at} r {r}: exhaustive {expected}, its own entries walked in turn");
                if (expected) blocked++;
                var cells = query.Cells.Where(c => c.Query.Overlaps(at, r)).Select(c => c.CellId);
                Assert.Equal(cells, query.TouchingCells(at, r));
            }
            Assert.InRange(blocked, 1, probes.Length + edgeProbes.Length - 1);
        }
        return (probes.Length, edges);
    }

    /// <summary>Every object's and every cell's probes moved into the landblock, as the scene's totals ask them.</summary>
    internal static IEnumerable<(Vector3 At, float Radius)> Positions(CompiledSceneReport report)
    {
        foreach (var placed in report.Placed)
        {
            if (report.For(placed.Object) is not { } c) continue;
            var frame = new PartPose(placed.Object.Frame.Position, Quaternion.Normalize(placed.Object.Frame.Rotation), 1f);
            foreach (var p in c.Probes) yield return (frame.ToEntity(p.Center), p.Radius);
        }
        foreach (var cell in report.Cells)
            foreach (var p in cell.Probes) yield return (cell.Frame.ToEntity(p.Center), p.Radius);
    }

    /// <summary>
    /// Spheres where a partition could lose an answer: tangent to each entry's bound (16 directions in the
    /// plane, and above and below), and every metre along every land-cell edge line the bound crosses or nears, at
    /// offsets of 0, ±r/2, ±r and ±(r + 1 mm) from the edge — for radii 0.25, 0.5 and 1.5 m.
    /// </summary>
    internal static IEnumerable<(Vector3 At, float Radius)> EdgePositions(SceneQuery query)
    {
        var bounds = query.Objects.Select(o => o.LandblockBound).Concat(query.Cells.Select(c => c.Query.Bound).OfType<(Vector3 Center, float Radius)>());
        foreach (var (center, radius) in bounds)
            foreach (var r in new[] { 0.25f, 0.5f, 1.5f })
            {
                var reach = radius + r;
                for (var k = 0; k < 16; k++)
                {
                    var angle = k * MathF.PI / 8f;
                    yield return (center + reach * new Vector3(MathF.Cos(angle), MathF.Sin(angle), 0f), r);
                }
                yield return (center + new Vector3(0f, 0f, reach), r);
                yield return (center - new Vector3(0f, 0f, reach), r);
                var lo = (int)MathF.Floor((center.X - reach) / 24f);
                var hi = (int)MathF.Floor((center.X + reach) / 24f) + 1;
                var loY = (int)MathF.Floor((center.Y - reach) / 24f);
                var hiY = (int)MathF.Floor((center.Y + reach) / 24f) + 1;
                foreach (var offset in new[] { 0f, r / 2, -r / 2, r, -r, r + 1e-3f, -r - 1e-3f })
                    for (var t = -reach; t <= reach; t += 1f)
                    {
                        for (var line = lo; line <= hi; line++) yield return (new Vector3(line * 24f + offset, center.Y + t, center.Z), r);
                        for (var line = loY; line <= hiY; line++) yield return (new Vector3(center.X + t, line * 24f + offset, center.Z), r);
                    }
            }
    }
}
