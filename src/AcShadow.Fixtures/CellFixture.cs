using System.Numerics;
using AcShadow.Fixtures.Cells;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Formats;

namespace AcShadow.Fixtures;

/// <summary>
/// One indoor cell as acshadow wrote it (<c>cells/0x%08X.cell.json</c>), with the collision reference
/// over its physics polygons. Queries take landblock-relative points (the frame the dat stores the cell's
/// position in, so no precision is lost at world magnitudes); <see cref="OverlapsWorld"/> takes world ones.
/// The objects inside the cell are in <see cref="File"/>; <see cref="FixtureSet.PlaceCellObjects"/> loads them.
/// </summary>
public sealed class CellFixture
{
    private readonly CellOverlapQuery _query;
    private readonly CellOverlapQuery _world;

    public CellFile File { get; }
    public uint CellId => File.CellId;

    private CellFixture(CellFile file)
    {
        File = file;
        _query = new CellOverlapQuery(file.Physics, file.LandblockFrame.Position, file.LandblockFrame.Rotation);
        _world = new CellOverlapQuery(file.Physics, file.WorldFrame.Position, file.WorldFrame.Rotation);
    }

    public static CellFixture From(CellFile file) => new(file);

    /// <summary>Loads <c>cells/0x%08X.cell.json</c> from a fixtures folder.</summary>
    public static CellFixture Load(string fixturesFolder, uint cellId)
    {
        var path = Path.Combine(fixturesFolder, FileFormats.Cell.PathFor(cellId));
        if (!System.IO.File.Exists(path))
            throw new FileNotFoundException($"no cell file for 0x{cellId:X8} at {path}; generate it with `acshadow dump --cell 0x{cellId:X8} --cell-dat PATH --out {fixturesFolder}` or a landblock batch", path);
        try
        {
            return new CellFixture(CellFileReader.Read(System.IO.File.ReadAllText(path)));
        }
        catch (FormatException e)
        {
            throw new FormatException($"{path}: {e.Message}", e);
        }
        catch (System.Text.Json.JsonException e)
        {
            throw new FormatException($"{path}: not JSON: {e.Message}", e);
        }
    }

    /// <summary>Does a sphere at this landblock-relative centre touch one of the cell's physics polygons?</summary>
    public bool Overlaps(Vector3 landblockCenter, float radius) => _query.Overlaps(landblockCenter, radius);

    /// <summary>The same question for a world-space centre (float world coordinates: millimetre precision at most).</summary>
    public bool OverlapsWorld(Vector3 worldCenter, float radius) => _world.Overlaps(worldCenter, radius);

    /// <summary>A landblock-relative point in the cell's own frame (where its polygons are).</summary>
    public Vector3 ToCell(Vector3 landblockPoint) => _query.ToCell(landblockPoint);

    /// <summary>A point of the cell's own frame, landblock-relative.</summary>
    public Vector3 ToLandblock(Vector3 cellPoint) => _query.FromCell(cellPoint);
}
