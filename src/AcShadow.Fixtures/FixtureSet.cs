using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures;

/// <summary>
/// A folder acshadow wrote (<c>dump --out</c> or <c>batch --out</c>): Setups load on demand, the index and
/// the scene when present. <see cref="PlaceScene"/> places every collidable object of scene.json in the world.
/// </summary>
public sealed class FixtureSet
{
    private readonly Dictionary<uint, SetupFixture> _setups = [];
    private readonly Lock _lock = new();
    private readonly Lazy<FixtureIndex?> _index;
    private readonly Lazy<FixtureScene?> _scene;

    private FixtureSet(string folder)
    {
        Folder = folder;
        _index = new(() => ReadOptional("index.json", FixtureIndex.Read));
        _scene = new(() => ReadOptional("scene.json", FixtureScene.Read));
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

    /// <summary>Every object of scene.json that has a file, placed at its world frame.</summary>
    public IReadOnlyList<PlacedFixture> PlaceScene()
    {
        var scene = Scene ?? throw new FileNotFoundException($"{Path.Combine(Folder, "scene.json")} is missing; generate it with `acshadow batch --landblock 0xXXYY --cell-dat PATH --out {Folder}`");
        var placed = new List<PlacedFixture>();
        foreach (var o in scene.Objects.Where(o => o.File is not null))
        {
            var fixture = o.Kind == "setup" ? Setup(o.Id) : GfxObj(scene, o);
            placed.Add(fixture.PlaceAt(o.WorldPosition, o.WorldRotation));
        }
        return placed;
    }

    private SetupFixture GfxObj(FixtureScene scene, ScenePlacement o)
    {
        var dump = BspFileReader.Read(File.ReadAllText(Path.Combine(Folder, o.File!)));
        var set = new ShadowShapeSet(o.Id, scene.Policy, new PlacementResolution(PlacementResolution.NoneName, PlacementResolution.NoneName),
            scene.EntityScale, true, o.Shapes, []);
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
