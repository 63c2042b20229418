using System.Numerics;
using System.Text.Json;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Scenes;

namespace AcShadow.Fixtures;

/// <summary>
/// compiled-scene.json (what <c>acshadow scene</c> writes) loaded: every object answered by the model the
/// compiler chose for it — spheres, cylinders, part boxes, part convex hulls, or the part's retail BSP
/// read from the dump beside it — and every indoor cell by its retail tree (cells/0x%08X.bsp.json, asked
/// as <see cref="CellOverlapQuery"/> asks it), with the same float operations the tool checked them with.
/// Each part is registered on its own in the land cells (<see cref="PlacedParts"/>), as the tool's compiled scene is.
/// <see cref="Query"/> takes landblock-relative centres.
/// </summary>
public sealed class CompiledScene
{
    public uint LandblockId { get; }
    public IReadOnlyList<float> MoverRadii { get; }
    public double TolerancePercent { get; }
    internal IReadOnlyList<CompiledObject> Objects { get; }
    internal IReadOnlyList<CompiledCell> Cells { get; }
    internal SceneQuery Query { get; }

    private CompiledScene(uint landblockId, IReadOnlyList<float> moverRadii, double tolerance, IReadOnlyList<CompiledObject> objects, IReadOnlyList<CompiledCell> cells, SceneQuery query)
    {
        LandblockId = landblockId;
        MoverRadii = moverRadii;
        TolerancePercent = tolerance;
        Objects = objects;
        Cells = cells;
        Query = query;
    }

    /// <summary>Does a sphere at this landblock-relative centre touch anything of the scene, object or cell?</summary>
    public bool Overlaps(Vector3 landblockCenter, float radius) => Query.Overlaps(landblockCenter, radius);

    /// <summary>The cells whose walls, floors or ceilings a sphere at this landblock-relative centre touches.</summary>
    public IEnumerable<uint> TouchingCells(Vector3 landblockCenter, float radius) => Query.TouchingCells(landblockCenter, radius);

    /// <summary>Loads <c>compiled-scene.json</c> from a folder <c>acshadow scene --out</c> wrote, with the BSP dumps it names.</summary>
    public static CompiledScene Load(string folder)
    {
        var path = Path.Combine(folder, FileFormats.CompiledScene.Path);
        if (!File.Exists(path))
            throw new FileNotFoundException($"{path} is missing; generate it with `acshadow scene --landblock 0xXXYY --out {folder}`", path);
        try
        {
            return Read(File.ReadAllText(path), file => BspFileReader.Read(File.ReadAllText(Path.Combine(folder, file))));
        }
        catch (FormatException e)
        {
            throw new FormatException($"{path}: {e.Message}", e);
        }
        catch (JsonException e)
        {
            throw new FormatException($"{path}: not JSON: {e.Message}", e);
        }
    }

    /// <summary>From the file's text; <paramref name="bspFile"/> reads a BSP dump by its folder-relative path.</summary>
    public static CompiledScene Read(string json, Func<string, BspDump> bspFile) => From(CompiledSceneFile.Read(json), bspFile);

    /// <summary>The scene a parsed file describes, its BSP dumps read by <paramref name="bspFile"/>, each once.</summary>
    internal static CompiledScene From(CompiledSceneFile file, Func<string, BspDump> bspFile)
    {
        var trees = new Dictionary<string, BspSphereQuery>(StringComparer.Ordinal);
        // Every tree asked through its per-radius grids for the scene's mover radii: the walk's answers, faster.
        var grids = new BspReachGrids(file.MoverRadii);
        var objects = new List<CompiledObject>();
        var queries = new List<PlacedQuery>();
        foreach (var o in file.Objects)
        {
            var shapes = o.Shapes.Select(s => Shape(s, trees, grids, bspFile)).ToArray();
            objects.Add(new CompiledObject(o.Index, o.Id, o.Kind, o.Model, shapes.Length, new Frame(o.Position, o.Rotation)) { CellId = o.CellId });
            if (o.Bound is not { } bound) continue;
            queries.AddRange(PlacedParts.Of(o.Index, o.Id, o.Position, o.Rotation, new AnyOverlap(shapes), bound.Center, bound.Radius));
        }
        var cells = new List<CompiledCell>();
        var cellQueries = new List<SceneCell>();
        foreach (var c in file.Cells)
        {
            if (c.File is null) continue;
            cells.Add(new CompiledCell(c.CellId, c.Model!, new Frame(c.Position, c.Rotation)));
            try
            {
                cellQueries.Add(new SceneCell(c.CellId, new CellOverlapQuery(bspFile(c.File), c.Position, c.Rotation).Indexed(grids)));
            }
            catch (ArgumentException ex)
            {
                throw new FormatException($"cell {JsonIds.Format(c.CellId)}: {ex.Message}", ex);
            }
        }
        return new CompiledScene(file.LandblockId, file.MoverRadii, file.TolerancePercent, objects, cells, new SceneQuery(queries, cellQueries, file.MoverRadii));
    }

    private static ISphereOverlap Shape(CompiledSceneFile.Shape shape, Dictionary<string, BspSphereQuery> trees, BspReachGrids grids, Func<string, BspDump> bspFile) => shape switch
    {
        CompiledSceneFile.SphereShape s => new SphereShapeQuery(s.Center, s.Radius),
        CompiledSceneFile.CylinderShape c => new CylinderShapeQuery(c.Base, c.Radius, c.Height),
        CompiledSceneFile.BoxShape b => new PosedQuery(b.Pose, new BoxSphereQuery(b.Box)),
        CompiledSceneFile.HullShape h => new PosedQuery(h.Pose, h.Hull),
        CompiledSceneFile.BspShape t => new PosedQuery(t.Pose, grids.Index(Tree(t.File, trees, bspFile), t.Pose)),
        _ => throw new FormatException($"shape type \"{shape.Type}\" is not sphere, cylinder, box, hull or bsp"),
    };

    private static BspSphereQuery Tree(string file, Dictionary<string, BspSphereQuery> trees, Func<string, BspDump> bspFile)
    {
        if (!trees.TryGetValue(file, out var query))
            trees[file] = query = new BspSphereQuery(CompiledBsp.Compile(bspFile(file)));
        return query;
    }
}
