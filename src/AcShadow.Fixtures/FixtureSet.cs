using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Scenes;
using AcShadow.Fixtures.Shapes;

using AcShadow.Fixtures.Movement;

namespace AcShadow.Fixtures;

/// <summary>
/// A folder acshadow wrote (<c>dump --out</c> or <c>batch --out</c>): Setups load on demand, the index and
/// the scene when present. <see cref="PlaceScene"/> places every collidable object of scene.json in the world.
/// </summary>
public sealed class FixtureSet
{
    private readonly Dictionary<uint, SetupFixture> _setups = [];
    private readonly Dictionary<uint, CellFixture> _cells = [];
    private readonly Lock _lock = new();
    private readonly Lazy<FixtureIndex?> _index;
    private readonly Lazy<FixtureScene?> _scene;

    private FixtureSet(string folder)
    {
        Folder = folder;
        _index = new(() => ReadOptional(FileFormats.Index.Path, FixtureIndex.Read));
        _scene = new(() => ReadOptional(FileFormats.Scene.Path, FixtureScene.Read));
    }

    public string Folder { get; }

    public static FixtureSet Open(string folder) =>
        Directory.Exists(folder) ? new FixtureSet(folder)
            : throw new DirectoryNotFoundException($"fixtures folder {folder} does not exist; generate it with `acshadow batch --out {folder}`");

    /// <summary>index.json, or null when the folder has none (a <c>dump</c> writes none).</summary>
    public FixtureIndex? Index => _index.Value;

    /// <summary>scene.json, or null when the batch selected no landblock.</summary>
    public FixtureScene? Scene => _scene.Value;

    public SetupFixture Setup(uint setupId)
    {
        lock (_lock)
        {
            if (!_setups.TryGetValue(setupId, out var fixture))
                _setups[setupId] = fixture = SetupFixture.Load(Folder, setupId);
            return fixture;
        }
    }

    /// <summary>
    /// An object's movement cases (<c>movement/0x%08X.movement.json</c>, written by <c>acshadow move</c> or
    /// <c>batch --movement</c>), with the BSP dumps its shapes name read from this folder's gfxobjs/.
    /// </summary>
    public MovementSuite Movement(uint setupId) =>
        MovementFileReader.Read(File.ReadAllText(Path.Combine(Folder, FileFormats.Movement.PathFor(setupId))),
            id => File.Exists(Path.Combine(Folder, FileFormats.Bsp.PathFor(id))) ? BspFileReader.Read(File.ReadAllText(Path.Combine(Folder, FileFormats.Bsp.PathFor(id)))) : null);

    /// <summary>An indoor cell's fixture (<c>cells/0x%08X.cell.json</c>), loaded once.</summary>
    public CellFixture Cell(uint cellId)
    {
        lock (_lock)
        {
            if (!_cells.TryGetValue(cellId, out var fixture))
                _cells[cellId] = fixture = CellFixture.Load(Folder, cellId);
            return fixture;
        }
    }

    /// <summary>Every cell scene.json lists with a file: the landblock's interior.</summary>
    public IReadOnlyList<CellFixture> SceneCells()
    {
        var scene = Scene ?? throw new FileNotFoundException($"{Path.Combine(Folder, FileFormats.Scene.Path)} is missing; generate it with `acshadow batch --landblock 0xXXYY --cell-dat PATH --out {Folder}`");
        return scene.Cells.Where(c => c.File is not null).Select(c => Cell(c.Id)).ToArray();
    }

    /// <summary>
    /// The objects placed inside a cell, each at its landblock-relative frame (the frame
    /// <see cref="CellFixture.Overlaps"/> takes), so a query can ask the cell and its contents alike.
    /// </summary>
    public IReadOnlyList<PlacedFixture> PlaceCellObjects(CellFixture cell)
    {
        var policy = Scene?.Policy ?? Index?.Policy ?? ShapePolicy.Retail;
        var scale = Scene?.EntityScale ?? Index?.EntityScale ?? 1f;
        return cell.File.Objects.Where(o => o.File is not null).Select(o =>
        {
            var fixture = o.Kind == SceneObjectKind.Setup ? Setup(o.Id) : BareGfxObj(o.Id, o.File!, o.Shapes, policy, scale);
            return fixture.PlaceAt(o.LandblockFrame.Position, o.LandblockFrame.Rotation);
        }).ToArray();
    }

    /// <summary>Every object of scene.json that has a file, placed at its world frame.</summary>
    public IReadOnlyList<PlacedFixture> PlaceScene()
    {
        var scene = Scene ?? throw new FileNotFoundException($"{Path.Combine(Folder, FileFormats.Scene.Path)} is missing; generate it with `acshadow batch --landblock 0xXXYY --cell-dat PATH --out {Folder}`");
        var placed = new List<PlacedFixture>();
        foreach (var o in scene.Objects.Where(o => o.File is not null))
        {
            var fixture = o.Kind == SceneObjectKind.Setup ? Setup(o.Id) : GfxObj(scene, o);
            placed.Add(fixture.PlaceAt(o.WorldFrame.Position, o.WorldFrame.Rotation));
        }
        return placed;
    }

    private SetupFixture GfxObj(FixtureScene scene, PlacedObject o) => BareGfxObj(o.Id, o.File!, o.Shapes, scene.Policy, scene.EntityScale);

    private SetupFixture BareGfxObj(uint id, string file, IReadOnlyList<ShadowShape> shapes, ShapePolicy policy, float entityScale)
    {
        var dump = BspFileReader.Read(File.ReadAllText(Path.Combine(Folder, file)));
        var set = new ShadowShapeSet(id, policy, new PlacementResolution(PlacementResolution.NoneName, PlacementResolution.NoneName),
            entityScale, true, shapes, []);
        return SetupFixture.From(set, [dump]);
    }

    private T? ReadOptional<T>(string name, Func<string, T> read) where T : class
    {
        var path = Path.Combine(Folder, name);
        if (!File.Exists(path)) return null;
        try
        {
            return read(File.ReadAllText(path));
        }
        catch (FormatException e)
        {
            throw new FormatException($"{path}: {e.Message}", e);
        }
    }
}
