using System.Collections.Concurrent;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Batch;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Export;

/// <summary>
/// The one code path from dat to files, shared by dump, batch, scenes and verify: build a Setup's
/// shapes, then dump each GfxObj a BSP shape references. A GfxObj's dump is made once per engine
/// however many Setups share it. Thread-safe.
/// </summary>
/// <param name="bspSink">
/// When given, each BSP dump is handed to it once, as soon as it is made, with its bytes lent (valid only
/// during the call), and the engine keeps only the entries of the files the sink wrote for it: a batch streams its files and its memory does not grow with
/// the dat. Without it the engine keeps every dump's bytes and <see cref="SetupExport.BspFiles"/> holds them.
/// </param>
public sealed class ExportEngine(IDatSource dat, ShapeBuildOptions options, Func<OutputFile, IReadOnlyList<FileEntry>>? bspSink = null)
{
    private readonly ConcurrentDictionary<uint, Lazy<BspDumpResult>> _bsp = new();
    // Each GfxObj's few bytes the shapes need, kept for the run: a part shared by many Setups is decoded once for its
    // dump, not again for every later Setup after it has left the dat's small working set. A read that throws is
    // not kept, so each Setup says so.
    private readonly ConcurrentDictionary<uint, PartPhysics?> _parts = new();

    public IDatSource Dat { get; } = dat;
    public ShapeBuildOptions Options { get; } = options;

    /// <summary>The Setup's export, or null when the dat has no such Setup.</summary>
    public SetupExport? ExportSetup(uint setupId)
    {
        var setup = Dat.ReadSetup(setupId);
        if (setup is null) return null;
        var motions = new Poses.MotionReads(Dat);
        // The GfxObjs this Setup decoded, lent to their dumps below: a Setup with more parts than the dat keeps
        // decoded would otherwise decode its first parts twice.
        Dictionary<uint, GfxObj>? decoded = null;
        var set = ShadowShapeBuilder.Build(setup, Part, Options, motions);
        var shadow = new OutputFile(FileFormats.Shadow.PathFor(setupId), FixtureKind.Shadow, setupId,
            ShadowFileWriter.Write(setup, set), set.Shapes.Count, 0);
        var diagnostics = new List<Diagnostic>(set.Diagnostics);
        var bspFiles = new List<OutputFile>();
        var bspEntries = new List<FileEntry>();
        foreach (var gfxId in set.Shapes.Where(s => s.CollisionType == CollisionType.Bsp && s.GfxObjId is not null)
                     .Select(s => s.GfxObjId!.Value).Distinct())
        {
            var dump = ExportGfxObj(gfxId, decoded?.GetValueOrDefault(gfxId));
            if (dump.File is not null) bspFiles.Add(dump.File);
            bspEntries.AddRange(dump.Entries);
            diagnostics.AddRange(dump.Diagnostics);
        }
        return new SetupExport(setup, set, shadow, bspFiles, bspEntries, diagnostics) { MotionInputs = [.. motions.Ids] };

        PartPhysics? Part(uint id)
        {
            if (_parts.TryGetValue(id, out var known)) return known;
            var gfx = Dat.ReadGfxObj(id);
            if (gfx is not null) (decoded ??= [])[id] = gfx;
            return _parts.GetOrAdd(id, gfx is null ? null : PartPhysics.Of(gfx));
        }
    }

    /// <summary>A GfxObj's BSP dump (no entry when it is absent or has no PhysicsBSP), made once and reused.</summary>
    public BspDumpResult ExportGfxObj(uint gfxObjId) => ExportGfxObj(gfxObjId, null);

    /// <summary>As <see cref="ExportGfxObj(uint)"/>, from <paramref name="decoded"/> (this GfxObj, already read) when given.</summary>
    private BspDumpResult ExportGfxObj(uint gfxObjId, GfxObj? decoded) =>
        _bsp.GetOrAdd(gfxObjId, id => new Lazy<BspDumpResult>(() => MakeBsp(id, decoded ?? Dat.ReadGfxObj(id)))).Value;

    private BspDumpResult MakeBsp(uint id, GfxObj? gfx)
    {
        var dump = gfx is null ? null : BspExtractor.Extract(gfx);
        if (dump is null) return new BspDumpResult(null, null, [], []);
        var path = FileFormats.Bsp.PathFor(id);
        OutputFile Acdream() => AcdreamGfxObjWriter.File(id, dump);
        var diagnostics = dump.Diagnostics.Select(d => new Diagnostic(ExportDiagnosticCodes.BspGeometry, d)).ToArray();
        if (bspSink is null)
            return new BspDumpResult(new OutputFile(path, FixtureKind.Bsp, id, BspFileWriter.Write(dump), 0, dump.Polygons.Count) { Acdream = Acdream },
                path, [], diagnostics);
        // The sink writes and hashes the dump at once, so its bytes are lent, never copied into an array.
        var entries = BspFileWriter.Lend(dump, content => bspSink(new OutputFile(path, FixtureKind.Bsp, id, content, 0, dump.Polygons.Count) { Acdream = Acdream }));
        return new BspDumpResult(null, path, entries, diagnostics);
    }
}
