using AcShadow.Analysis.Chart.Output;
using AcShadow.Core.Bsp;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;

namespace AcShadow.Analysis.Compile;

/// <summary>
/// Every file `acshadow scene` writes, in the order they are written: the BSP dumps of the GfxObjs objects
/// still modelled by retail need (and no others), each indoor cell's PhysicsBSP dump (cells/0x%08X.bsp.json,
/// in the cell's frame), scene-chart.csv, scene-chart.svg, and last compiled-scene.json, the file that
/// names the dumps: a run that stops part-way never leaves a new scene beside old dumps.
/// </summary>
internal static class CompiledSceneFiles
{
    private const string ChartCsvPath = "scene-chart.csv";
    private const string ChartSvgPath = "scene-chart.svg";

    public static IReadOnlyList<OutputFile> Render(CompiledSceneReport report, Func<uint, BspDump?> dumps)
    {
        var files = new List<OutputFile>();
        foreach (var id in CompiledSceneWriter.BspGfxObjs(report))
            if (dumps(id) is { } dump) files.Add(new OutputFile(FileFormats.Bsp.PathFor(id), BspFileWriter.Write(dump)));
        foreach (var cell in report.Cells)
            if (cell.Bsp is not null) files.Add(new OutputFile(CompiledSceneWriter.CellBspPath(cell.Cell.Id), BspFileWriter.Write(cell.Physics!)));
        files.Add(OutputFile.Text(ChartCsvPath, SceneChartCsv.Write(report)));
        files.Add(OutputFile.Text(ChartSvgPath, SceneChartSvg.Write(report)));
        files.Add(new OutputFile(FileFormats.CompiledScene.Path, CompiledSceneWriter.Write(report)));
        return files;
    }
}
