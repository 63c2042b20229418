using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Scenes;

namespace AcShadow.Core.Scenes;

/// <summary>
/// Everything one LandBlockInfo places, statics first then buildings, in dat order: the objects a
/// scene export describes.
/// </summary>
public sealed record LandblockScene(uint LandBlockInfoId, IReadOnlyList<SceneObject> Objects)
{
    public LandblockCoordinates Coordinates => LandblockCoordinates.Of(LandBlockInfoId);

    /// <summary>The landblock's indoor cells, each decoded once, in id order (empty with --no-cells).</summary>
    public IReadOnlyList<EnvCell> Cells { get; init; } = [];

    /// <summary>Cells the LandBlockInfo counts but the cell dat could not give (id → why).</summary>
    public IReadOnlyList<SkippedCell> MissingCells { get; init; } = [];

    /// <summary>
    /// The EnvCell ids a LandBlockInfo implies: its NumCells cells are 0xXXYY0100 upwards (ACE's
    /// LandblockInfo consumers and DatReaderWriter's readers number them so).
    /// </summary>
    public static IReadOnlyList<uint> CellIds(LandBlockInfo info)
    {
        var count = (int)Math.Min(info.NumCells, 0xFFFD - 0x0100 + 1u);
        var ids = new uint[count];
        for (var i = 0; i < count; i++) ids[i] = (info.Id & 0xFFFF0000u) | (uint)(0x0100 + i);
        return ids;
    }

    public static LandblockScene From(LandBlockInfo info)
    {
        var objects = new List<SceneObject>();
        for (var i = 0; i < info.Objects.Count; i++)
            objects.Add(new SceneObject(objects.Count, ScenePlacedBy.Object, i, info.Objects[i].Id, KindOf(info.Objects[i].Id), info.Objects[i].Frame));
        for (var i = 0; i < info.Buildings.Count; i++)
            objects.Add(new SceneObject(objects.Count, ScenePlacedBy.Building, i, info.Buildings[i].ModelId, KindOf(info.Buildings[i].ModelId), info.Buildings[i].Frame));
        return new LandblockScene(info.Id, objects);
    }

    /// <summary>The distinct Setup ids placed, sorted.</summary>
    public IReadOnlyList<uint> SetupIds => Objects.Where(o => o.Kind == SceneObjectKind.Setup).Select(o => o.Id)
        .Concat(Cells.SelectMany(c => c.StaticObjects).Select(s => s.Id).Where(id => KindOf(id) == SceneObjectKind.Setup))
        .Distinct().Order().ToArray();

    /// <summary>The distinct bare GfxObj ids placed, sorted.</summary>
    public IReadOnlyList<uint> GfxObjIds => Objects.Where(o => o.Kind == SceneObjectKind.GfxObj).Select(o => o.Id).Distinct().Order().ToArray();

    public static SceneObjectKind KindOf(uint id) =>
        DatObjectKind.Setup.Contains(id) ? SceneObjectKind.Setup
        : DatObjectKind.GfxObj.Contains(id) ? SceneObjectKind.GfxObj
        : SceneObjectKind.Other;
}

/// <summary>A cell the landblock counts that could not be read: not in the cell dat, or unreadable.</summary>
public sealed record SkippedCell(uint Id, string Reason);
