using AcShadow.Core.Formats;
using AcShadow.Core.Movement;
using AcShadow.Fixtures.Batch;
using AcShadow.Fixtures.Formats;

namespace AcShadow.Core.Export;

/// <summary>
/// The files of one generated suite: its movement file and the BSP dumps its shapes name (gfxobjs/, the same
/// bytes a dump or batch writes), so the cases load with nothing else.
/// </summary>
public static class MovementExport
{
    public static IReadOnlyList<OutputFile> Files(GeneratedSuite generated)
    {
        ArgumentNullException.ThrowIfNull(generated);
        var suite = generated.Suite;
        var frames = suite.Cases.Sum(c => c.Expected.Count);
        var files = new List<OutputFile>
        {
            new(FileFormats.Movement.PathFor(suite.SetupId), FixtureKind.Movement, suite.SetupId, MovementFileWriter.Write(generated), suite.Cases.Count, frames),
        };
        foreach (var (id, dump) in generated.Subject.Dumps)
            files.Add(new OutputFile(FileFormats.Bsp.PathFor(id), FixtureKind.Bsp, id, BspFileWriter.Write(dump), 0, dump.Polygons.Count));
        return files;
    }
}
