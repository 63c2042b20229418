using System.Numerics;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures;

/// <summary>
/// One Setup's fixture as acshadow wrote it: its shadow file and the BSP dump of every GfxObj a BSP shape
/// names, loaded and checked. <see cref="Overlaps"/> answers in the entity's own frame with the same
/// collision reference the tool runs; <see cref="PlaceAt"/> puts it in a world frame.
/// </summary>
public sealed class SetupFixture
{
    private readonly ObjectOverlapQuery _query;

    /// <summary>The shadow file: the Setup's shapes, how it was posed, and what was said about it.</summary>
    public ShadowShapeSet Shadow { get; }

    /// <summary>The BSP dumps the shapes use, by GfxObj id.</summary>
    public IReadOnlyDictionary<uint, BspDump> Bsps { get; }

    /// <summary>Shapes the collision reference could not use (for example a BSP shape whose dump is absent).</summary>
    public IReadOnlyList<Diagnostic> Diagnostics => _query.Diagnostics;

    private SetupFixture(ShadowShapeSet shapes, IReadOnlyDictionary<uint, BspDump> bsps)
    {
        Shadow = shapes;
        Bsps = bsps;
        var compiled = bsps.ToDictionary(p => p.Key, p => CompiledBsp.Compile(p.Value));
        _query = ObjectOverlapQuery.Create(shapes, id => compiled.GetValueOrDefault(id));
    }

    /// <summary>
    /// Loads <c>setups/0x%08X.shadow.json</c> from a fixtures folder (what <c>acshadow dump</c> or
    /// <c>batch</c> wrote) and the <c>gfxobjs/*.bsp.json</c> dumps it references.
    /// </summary>
    public static SetupFixture Load(string fixturesFolder, uint setupId)
    {
        var shadowPath = Path.Combine(fixturesFolder, FileFormats.Shadow.PathFor(setupId));
        if (!File.Exists(shadowPath))
            throw new FileNotFoundException($"no shadow file for Setup {JsonIds.Format(setupId)} at {shadowPath}; generate it with `acshadow dump --setup {JsonIds.Format(setupId)} --out {fixturesFolder}`", shadowPath);
        var shapes = Read(shadowPath, ShadowFileReader.Read);
        var bsps = new SortedDictionary<uint, BspDump>();
        foreach (var id in shapes.Shapes.Where(s => s.CollisionType == CollisionType.Bsp && s.GfxObjId is not null).Select(s => s.GfxObjId!.Value).Distinct())
        {
            var bspPath = Path.Combine(fixturesFolder, FileFormats.Bsp.PathFor(id));
            if (!File.Exists(bspPath))
                throw new FileNotFoundException($"{FileFormats.Shadow.PathFor(setupId)} names GfxObj {JsonIds.Format(id)} but {bspPath} is missing; copy the whole output folder, not just setups/", bspPath);
            bsps[id] = Read(bspPath, BspFileReader.Read);
        }
        return new SetupFixture(shapes, bsps);
    }

    /// <summary>From records already in memory (for example read from embedded resources).</summary>
    public static SetupFixture From(ShadowShapeSet shapes, IEnumerable<BspDump> bsps) =>
        new(shapes, bsps.ToDictionary(b => b.GfxObjId));

    /// <summary>Does a sphere at this entity-space centre and radius touch the object? (Its shapes are in entity space.)</summary>
    public bool Overlaps(Vector3 center, float radius) => _query.Overlaps(center, radius);

    /// <summary>The object placed in a world frame: position, then rotation (a unit quaternion).</summary>
    public PlacedFixture PlaceAt(Vector3 position, Quaternion rotation) => new(this, position, rotation);

    private static T Read<T>(string path, Func<string, T> reader)
    {
        try
        {
            return reader(File.ReadAllText(path));
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
}
