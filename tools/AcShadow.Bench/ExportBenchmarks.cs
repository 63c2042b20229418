using AcShadow.Core.Dat;
using AcShadow.Core.Export;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;
using BenchmarkDotNet.Attributes;

namespace AcShadow.Bench;

/// <summary>
/// The one export path (what dump and batch run) over every Setup of the realistic-scale dat, single
/// threaded: shapes only, and shapes plus every shadow and BSP file's bytes.
/// </summary>
[MemoryDiagnoser]
public class ExportBenchmarks
{
    private DatDatabase _dat = null!;
    private uint[] _setups = [];

    [Params(ShapePolicy.Retail, ShapePolicy.Union)]
    public ShapePolicy Policy { get; set; }

    [GlobalSetup]
    public void Setup()
    {
        _dat = ScaleDat.Open();
        _setups = _dat.ListIds(DatObjectKind.Setup).ToArray();
        foreach (var id in _setups) _dat.ReadSetup(id);
        foreach (var id in _dat.ListIds(DatObjectKind.GfxObj)) _dat.ReadGfxObj(id);
    }

    [GlobalCleanup]
    public void Cleanup() => _dat.Dispose();

    [Benchmark]
    public int BuildShapesForEverySetup()
    {
        var shapes = 0;
        var options = new ShapeBuildOptions(Policy);
        foreach (var id in _setups) shapes += ShadowShapeBuilder.Build(_dat.ReadSetup(id)!, _dat.ReadGfxObj, options).Shapes.Count;
        return shapes;
    }

    [Benchmark]
    public long ExportEverySetup()
    {
        var engine = new ExportEngine(_dat, new ShapeBuildOptions(Policy));
        long bytes = 0;
        foreach (var id in _setups)
            foreach (var file in engine.ExportSetup(id)!.Files) bytes += file.Content.Length;
        return bytes;
    }
}
