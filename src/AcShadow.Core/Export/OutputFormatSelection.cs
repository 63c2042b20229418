using System.Text;
using AcShadow.Core.Json;

namespace AcShadow.Core.Export;

/// <summary>
/// Turns a run's canonical files into the files the chosen formats ask for: the canonical ones as they are,
/// and for each BSP dump its acdream GfxObj file. The acdream file is made from the canonical file's own
/// bytes (read back losslessly), so both formats always say the same thing. Sorted by path.
/// </summary>
public static class OutputFormatSelection
{
    public static IReadOnlyList<OutputFile> Apply(IEnumerable<OutputFile> canonical, OutputFormats formats)
    {
        var files = canonical.ToArray();
        if (formats == OutputFormats.Canonical) return files;
        var result = new List<OutputFile>();
        if (formats.HasFlag(OutputFormats.Canonical)) result.AddRange(files);
        if (formats.HasFlag(OutputFormats.Acdream))
        {
            foreach (var bsp in files.Where(f => f.Kind == OutputKind.Bsp))
            {
                var dump = BspFileReader.Read(Encoding.UTF8.GetString(bsp.Content));
                result.Add(new OutputFile(AcdreamGfxObjFormat.PathFor(bsp.Id), OutputKind.AcdreamGfxObj, bsp.Id,
                    AcdreamGfxObjWriter.Write(dump), 0, AcdreamGfxObjWriter.PolygonCount(dump)));
            }
        }
        return [.. result.OrderBy(f => f.RelativePath, StringComparer.Ordinal)];
    }
}
