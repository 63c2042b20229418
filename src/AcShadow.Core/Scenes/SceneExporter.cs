using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Export;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Batch;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Scenes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Scenes;

/// <summary>
/// Writes a landblock's scene file: every placed object with its landblock-relative and world frames
/// and the file that describes it. Setups point at the shadow file the batch wrote for them; bare
/// GfxObjs get their BSP dump (through <see cref="ExportEngine"/>) and a one-shape entry.
/// </summary>
public static class SceneExporter
{
    /// <param name="setupFiles">The shadow file of every Setup the batch exported (the scene points at it).</param>
    /// <param name="setupProblems">Why a placed Setup has no export (not in the dat, unreadable).</param>
    /// <param name="cells">The cell files written for the scene's cells (listed in scene.json's "cells").</param>
    public static SceneExport Export(LandblockScene scene, ExportEngine engine,
        IReadOnlyDictionary<uint, string> setupFiles, IReadOnlyDictionary<uint, string> setupProblems, IReadOnlyList<CellExport>? cells = null)
    {
        var bspFiles = new SortedDictionary<string, BspDumpResult>(StringComparer.Ordinal);
        var skipped = new Dictionary<uint, SkippedItem>();
        var objects = new JsonArr();
        int resolved = 0, unresolved = 0;
        foreach (var placed in scene.Objects)
        {
            var entry = Describe(placed, scene, engine, setupFiles, setupProblems, bspFiles, skipped);
            if (entry.Resolved) resolved++; else unresolved++;
            objects.Add(entry.Json);
        }

        var coordinates = scene.Coordinates;
        var json = new JsonObj()
            .Add("format", FileFormats.Scene.Format)
            .Add("landblockId", JsonIds.Format(scene.LandBlockInfoId))
            .Add("landblock", new JsonObj().Add("x", coordinates.X).Add("y", coordinates.Y))
            .Add("worldOrigin", new JsonArr().Add(JsonNum.Of(coordinates.WorldOriginX)).Add(JsonNum.Of(coordinates.WorldOriginY)).Add(JsonNum.Of(0)))
            .Add("policy", engine.Options.Policy.Name())
            .Add("entityScale", engine.Options.EntityScale)
            .Add("summary", new JsonObj()
                .Add("objects", scene.Objects.Count)
                .Add("setups", scene.Objects.Count(o => o.Kind == SceneObjectKind.Setup))
                .Add("gfxObjs", scene.Objects.Count(o => o.Kind == SceneObjectKind.GfxObj))
                .Add("resolved", resolved)
                .Add("unresolved", unresolved))
            .Add("objects", objects)
            .Add("cells", JsonArr.Of(CellEntries(scene, cells ?? []), c => c));
        var file = new OutputFile(FileFormats.Scene.Path, FixtureKind.Scene, scene.LandBlockInfoId,
            CanonicalJsonWriter.WriteUtf8(json), 0, 0);
        return new SceneExport(file, bspFiles.Values.Where(d => d.File is not null).Select(d => d.File!).ToArray(),
            bspFiles.Values.SelectMany(d => d.Entries).ToArray(), skipped.Values.OrderBy(s => s.Id).ToArray());
    }

    /// <summary>Every cell the landblock counts, in id order: its file, or why it has none.</summary>
    private static IEnumerable<JsonObj> CellEntries(LandblockScene scene, IReadOnlyList<CellExport> cells)
    {
        var entries = cells.Select(c => (c.CellId, Json: new JsonObj()
                .Add("id", JsonIds.Format(c.CellId))
                .Add("file", c.Path)
                .Add("objects", c.ObjectCount)
                .Add("diagnostics", c.Diagnostics.Count)))
            .Concat(scene.MissingCells.Select(m => (CellId: m.Id, Json: new JsonObj()
                .Add("id", JsonIds.Format(m.Id))
                .Add("file", (string?)null)
                .Add("objects", 0)
                .Add("diagnostics", 1))));
        return entries.OrderBy(e => e.CellId).Select(e => e.Json);
    }

    /// <summary>One placed object's entry (scene.json's objects, a cell file's objects): its frames, its file, its diagnostics.</summary>
    internal static (JsonObj Json, bool Resolved) Describe(SceneObject placed, LandblockScene scene, ExportEngine engine,
        IReadOnlyDictionary<uint, string> setupFiles, IReadOnlyDictionary<uint, string> setupProblems,
        SortedDictionary<string, BspDumpResult> bspFiles, Dictionary<uint, SkippedItem> skipped)
    {
        var (wx, wy, wz) = WorldFrame.Origin(scene.Coordinates, placed.Frame);
        var json = new JsonObj()
            .Add("index", placed.Index)
            .Add("placedBy", placed.PlacedBy.Name())
            .Add("placedIndex", placed.PlacedIndex)
            .Add("id", JsonIds.Format(placed.Id))
            .Add("kind", placed.Kind.Name())
            .Add("landblockFrame", FrameJson(JsonArr.Of(placed.Frame.Position), placed.Frame))
            .Add("worldFrame", FrameJson(new JsonArr().Add(JsonNum.Of(wx)).Add(JsonNum.Of(wy)).Add(JsonNum.Of(wz)), placed.Frame));
        var diagnostics = new List<Diagnostic>();
        string? file = null;
        JsonNode? shapes = null;
        switch (placed.Kind)
        {
            case SceneObjectKind.Setup when setupFiles.TryGetValue(placed.Id, out var shadowPath):
                file = shadowPath;
                break;
            case SceneObjectKind.Setup:
                diagnostics.Add(new(ExportDiagnosticCodes.Unresolved, $"Setup {JsonIds.Format(placed.Id)}: {setupProblems.GetValueOrDefault(placed.Id, SkippedItem.NotInDat)}"));
                break;
            case SceneObjectKind.GfxObj:
                (file, shapes) = DescribeGfxObj(placed.Id, engine, bspFiles, skipped, diagnostics);
                break;
            default:
                diagnostics.Add(new(ExportDiagnosticCodes.Unresolved, $"id {JsonIds.Format(placed.Id)} is neither a Setup ({DatObjectKind.Setup.RangeText()}) nor a GfxObj ({DatObjectKind.GfxObj.RangeText()})"));
                break;
        }
        json.Add("file", file);
        if (placed.Kind == SceneObjectKind.GfxObj) json.Add("shapes", shapes ?? new JsonArr());
        json.Add("diagnostics", JsonArr.Of(diagnostics, d => new JsonObj().Add("code", d.Code).Add("message", d.Message)));
        var resolved = placed.Kind switch
        {
            SceneObjectKind.Setup => file is not null,
            SceneObjectKind.GfxObj => shapes is not null,
            _ => false,
        };
        return (json, resolved);
    }

    /// <summary>A drawing-only GfxObj is resolved (it has no shapes and no dump: nothing of it collides).</summary>
    private static (string? File, JsonNode? Shapes) DescribeGfxObj(uint id, ExportEngine engine,
        SortedDictionary<string, BspDumpResult> bspFiles, Dictionary<uint, SkippedItem> skipped, List<Diagnostic> diagnostics)
    {
        GfxObj? gfx;
        try
        {
            gfx = engine.Dat.ReadGfxObj(id);
        }
        catch (DatFormatException e)
        {
            var reason = $"unreadable: {e.Message}";
            skipped[id] = new SkippedItem(id, reason, SelectionSource.Landblock);
            diagnostics.Add(new(DiagnosticCodes.UnreadableGfxObj, $"GfxObj {JsonIds.Format(id)}: {reason}"));
            return (null, null);
        }
        if (gfx is null)
        {
            skipped[id] = new SkippedItem(id, SkippedItem.NotInDat, SelectionSource.Landblock);
            diagnostics.Add(new(ExportDiagnosticCodes.Unresolved, $"GfxObj {JsonIds.Format(id)}: {SkippedItem.NotInDat}"));
            return (null, null);
        }
        var set = BareGfxObjShape.Build(gfx, engine.Dat.ReadGfxObj, engine.Options);
        diagnostics.AddRange(set.Diagnostics);
        var dump = engine.ExportGfxObj(id);
        diagnostics.AddRange(dump.Diagnostics);
        if (dump.Path is not null) bspFiles[dump.Path] = dump;
        return (dump.Path, BareGfxObjShape.ShapesJson(gfx, set));
    }

    private static JsonObj FrameJson(JsonArr origin, Frame frame) =>
        new JsonObj().Add("origin", origin).Add("orientation", JsonShapes.Quaternion(frame.Rotation));
}
