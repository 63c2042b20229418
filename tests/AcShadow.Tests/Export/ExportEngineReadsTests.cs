using System.Collections.Concurrent;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Export;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Export;

/// <summary>
/// The export engine asks the dat for each GfxObj once however many Setups share it: a Setup's shapes need only the
/// part's <see cref="PartPhysics"/>, kept for the run, and its dump is made from the GfxObj the Setup just decoded.
/// A batch over a dat larger than its working set decoded shared parts again for every later Setup (23 % of a
/// batch's bytes on the benchmark's 3,000-Setup dat).
/// </summary>
public class ExportEngineReadsTests
{
    /// <summary>A dat that counts the GfxObj reads asked of it (its own cache keeps one object: every read decodes).</summary>
    private sealed class CountingDat(IDatSource inner) : IDatSource
    {
        public ConcurrentDictionary<uint, int> GfxObjReads { get; } = new();
        public DatSourceInfo Info => inner.Info;
        public Setup? ReadSetup(uint id) => inner.ReadSetup(id);
        public GfxObj? ReadGfxObj(uint id)
        {
            GfxObjReads.AddOrUpdate(id, 1, (_, n) => n + 1);
            return inner.ReadGfxObj(id);
        }
        public LandBlockInfo? ReadLandBlockInfo(uint id) => inner.ReadLandBlockInfo(id);
        public IReadOnlyList<uint> ListIds(DatObjectKind kind) => inner.ListIds(kind);
        public MotionTable? ReadMotionTable(uint id) => inner.ReadMotionTable(id);
        public Animation? ReadAnimation(uint id) => inner.ReadAnimation(id);
    }

    [Fact]
    public void Every_setup_of_the_sample_reads_each_gfxobj_once_and_exports_as_a_fresh_engine_does()
    {
        using var portal = SampleDat.OpenPortal();
        var dat = new CountingDat(new DatDatabase(portal.Archive, cacheCapacity: 1));
        var options = new ShapeBuildOptions(ShapePolicy.Retail);
        var engine = new ExportEngine(dat, options);
        var setups = portal.ListIds(DatObjectKind.Setup);
        // Twice over: the second pass finds every part and dump made.
        var exports = setups.Select(engine.ExportSetup).ToArray();
        var again = setups.Select(engine.ExportSetup).ToArray();

        var partIds = setups.SelectMany(id => portal.ReadSetup(id)!.Parts).Distinct().ToArray();
        Assert.True(setups.Sum(id => portal.ReadSetup(id)!.Parts.Count) > partIds.Length, "the sample's Setups share parts: else once is no news");
        Assert.Equal(partIds.Order(), dat.GfxObjReads.Keys.Order());
        Assert.All(dat.GfxObjReads, read => Assert.Equal(1, read.Value));

        for (var i = 0; i < setups.Count; i++)
        {
            var alone = new ExportEngine(portal, options).ExportSetup(setups[i])!;
            foreach (var export in new[] { exports[i]!, again[i]! })
            {
                Assert.Equal(alone.Shadow.Content.ToArray(), export.Shadow.Content.ToArray());
                Assert.Equal(alone.BspFiles.Select(f => (f.RelativePath, f.Content.ToArray())), export.BspFiles.Select(f => (f.RelativePath, f.Content.ToArray())));
                Assert.Equal(alone.Diagnostics, export.Diagnostics);
            }
        }
    }
}
