using System.Collections.Concurrent;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat;
using AcShadow.Core.Json;
using AcShadow.Core.Shapes;

namespace AcShadow.Core.Export;

/// <summary>
/// The one code path from dat to files, shared by dump, batch, scenes and verify: build a Setup's
/// shapes, then dump each GfxObj a BSP shape references. A GfxObj's dump is made once per engine
/// however many Setups share it. Thread-safe.
/// </summary>
public sealed class ExportEngine(IDatSource dat, ShapeBuildOptions options)
{
    private readonly ConcurrentDictionary<uint, Lazy<(OutputFile? File, IReadOnlyList<Diagnostic> Diagnostics)>> _bsp = new();

    public IDatSource Dat { get; } = dat;
    public ShapeBuildOptions Options { get; } = options;

    /// <summary>The Setup's export, or null when the dat has no such Setup.</summary>
    public SetupExport? ExportSetup(uint setupId)
    {
        var setup = Dat.ReadSetup(setupId);
        if (setup is null) return null;
        var set = ShadowShapeBuilder.Build(setup, Dat.ReadGfxObj, Options);
        var shadow = new OutputFile(ShadowFileFormat.PathFor(setupId), OutputKind.Shadow, setupId,
            ShadowFileWriter.Write(setup, set), set.Shapes.Count, 0);
        var diagnostics = new List<Diagnostic>(set.Diagnostics);
        var bspFiles = new List<OutputFile>();
        foreach (var gfxId in set.Shapes.Where(s => s.CollisionType == CollisionType.Bsp && s.GfxObjId is not null)
                     .Select(s => s.GfxObjId!.Value).Distinct())
        {
            var (file, bspDiagnostics) = ExportGfxObj(gfxId);
            if (file is not null) bspFiles.Add(file);
            diagnostics.AddRange(bspDiagnostics);
        }
        return new SetupExport(setup, set, shadow, bspFiles, diagnostics);
    }

    /// <summary>A GfxObj's BSP dump (null when it is absent or has no PhysicsBSP), made once and reused.</summary>
    public (OutputFile? File, IReadOnlyList<Diagnostic> Diagnostics) ExportGfxObj(uint gfxObjId) =>
        _bsp.GetOrAdd(gfxObjId, id => new Lazy<(OutputFile?, IReadOnlyList<Diagnostic>)>(() => MakeBsp(id))).Value;

    public BspDump? ExtractBsp(uint gfxObjId)
    {
        var gfx = Dat.ReadGfxObj(gfxObjId);
        return gfx is null ? null : BspExtractor.Extract(gfx);
    }

    private (OutputFile?, IReadOnlyList<Diagnostic>) MakeBsp(uint id)
    {
        var dump = ExtractBsp(id);
        if (dump is null) return (null, []);
        var file = new OutputFile(BspFileFormat.PathFor(id), OutputKind.Bsp, id, BspFileWriter.Write(dump), 0, dump.Polygons.Count);
        return (file, dump.Diagnostics.Select(d => new Diagnostic("bsp-geometry", d)).ToArray());
    }
}
