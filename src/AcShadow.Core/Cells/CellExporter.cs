using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Export;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Core.Scenes;
using AcShadow.Fixtures.Batch;
using AcShadow.Fixtures.Cells;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Cells;

/// <summary>
/// Writes an EnvCell's cell file ("acshadow.cell/1", docs/formats.md): the cell's frame in the landblock
/// and in the world, its cell structure's physics polygons (retail planes) and flattened PhysicsBSP in
/// the cell's own frame, its portals with their polygons, the cells it sees, and the objects placed in
/// it, each described exactly as scene.json describes a placed object (Setups point at their shadow
/// file; bare GfxObjs get their BSP dump and one shape from the same builder). Each cell structure is
/// turned into geometry once per exporter, however many cells use it. Thread-safe.
/// </summary>
public sealed class CellExporter(ExportEngine engine)
{
    private readonly CellStructures _structures = new(engine.Dat);

    /// <param name="setupFiles">The shadow file of every Setup the run exported.</param>
    /// <param name="setupProblems">Why a placed Setup has no export.</param>
    public CellExport Export(EnvCell cell, LandblockScene scene, IReadOnlyDictionary<uint, string> setupFiles, IReadOnlyDictionary<uint, string> setupProblems)
    {
        var diagnostics = new List<Diagnostic>();
        var (geometry, problem) = _structures.For(cell.EnvironmentFileId, cell.CellStructure);
        if (geometry is null)
        {
            var reason = $"EnvCell {JsonIds.Format(cell.Id)}: {problem}";
            return new CellExport(cell.Id, null, [], [], [new SkippedItem(cell.Id, reason, SelectionSource.Landblock)], [new Diagnostic(ExportDiagnosticCodes.Unresolved, reason)], cell.StaticObjects.Count);
        }

        var physics = geometry.Physics with { GfxObjId = cell.Id };
        diagnostics.AddRange(physics.Diagnostics.Select(d => new Diagnostic(ExportDiagnosticCodes.BspGeometry, d)));
        var portals = new JsonArr();
        var portalRecords = new List<CellPortalRecord>(cell.Portals.Count);
        for (var i = 0; i < cell.Portals.Count; i++)
        {
            var portal = cell.Portals[i];
            var (vertices, plane, portalProblem) = geometry.Portal(portal.PolygonId);
            if (portalProblem is not null) diagnostics.Add(new Diagnostic(ExportDiagnosticCodes.PortalPolygon, $"EnvCell {JsonIds.Format(cell.Id)} portal {i}: {portalProblem}"));
            portalRecords.Add(new CellPortalRecord(i, (ushort)portal.Flags, portal.PolygonId, cell.Sibling(portal.OtherCellId), portal.OtherPortalId, vertices, plane));
            portals.Add(new JsonObj()
                .Add("index", i)
                .Add("flags", (int)portal.Flags)
                .Add("polygonId", portal.PolygonId)
                .Add("otherCellId", JsonIds.Format(cell.Sibling(portal.OtherCellId)))
                .Add("outside", portal.LeadsOutside)
                .Add("otherPortalId", portal.OtherPortalId)
                .Add("polygon", new JsonObj()
                    .Add("vertices", JsonArr.Of(vertices, v => JsonArr.Of(v)))
                    .Add("plane", plane is { } p ? JsonShapes.Plane(p) : JsonNull.Value)));
        }

        var bspFiles = new SortedDictionary<string, BspDumpResult>(StringComparer.Ordinal);
        var skipped = new Dictionary<uint, SkippedItem>();
        var objects = new JsonArr();
        for (var i = 0; i < cell.StaticObjects.Count; i++)
        {
            var stab = cell.StaticObjects[i];
            var placed = new SceneObject(i, ScenePlacedBy.Cell, i, stab.Id, LandblockScene.KindOf(stab.Id), stab.Frame);
            objects.Add(SceneExporter.Describe(placed, scene, engine, setupFiles, setupProblems, bspFiles, skipped).Json);
        }

        var (wx, wy, wz) = WorldFrame.Origin(scene.Coordinates, cell.Position);
        var tree = BspFileWriter.ToJson(physics);
        var body = new JsonObj();
        foreach (var (name, value) in tree.Members)
            if (name is not ("format" or "gfxObjId" or "diagnostics")) body.Add(name, value);
        var json = new JsonObj()
            .Add("format", FileFormats.Cell.Format)
            .Add("cellId", JsonIds.Format(cell.Id))
            .Add("landblockId", JsonIds.Format(scene.LandBlockInfoId))
            .Add("environmentId", JsonIds.Format(cell.EnvironmentFileId))
            .Add("cellStructure", cell.CellStructure)
            .Add("flags", (long)cell.Flags)
            .Add("seenOutside", cell.SeenOutside)
            .Add("landblockFrame", new JsonObj().Add("origin", JsonArr.Of(cell.Position.Position)).Add("orientation", JsonShapes.Quaternion(cell.Position.Rotation)))
            .Add("worldFrame", new JsonObj()
                .Add("origin", new JsonArr().Add(JsonNum.Of(wx)).Add(JsonNum.Of(wy)).Add(JsonNum.Of(wz)))
                .Add("orientation", JsonShapes.Quaternion(cell.Position.Rotation)))
            .Add("physics", body)
            .Add("portals", portals)
            .Add("visibleCells", JsonArr.Of(cell.VisibleCells.Select(v => JsonIds.Format(cell.Sibling(v)))))
            .Add("objects", objects)
            .Add("diagnostics", JsonArr.Of(diagnostics, d => new JsonObj().Add("code", d.Code).Add("message", d.Message)));
        var visible = cell.VisibleCells.Select(cell.Sibling).ToArray();
        var file = new OutputFile(FileFormats.Cell.PathFor(cell.Id), FixtureKind.Cell, cell.Id, CanonicalJsonWriter.WriteUtf8(json), cell.StaticObjects.Count, physics.Polygons.Count)
        {
            Acdream = () => AcdreamCellWriter.File(cell.Id, cell.Position, physics, portalRecords, visible),
        };
        return new CellExport(cell.Id, file, bspFiles.Values.Where(d => d.File is not null).Select(d => d.File!).ToArray(),
            bspFiles.Values.SelectMany(d => d.Entries).ToArray(), skipped.Values.OrderBy(s => s.Id).ToArray(), diagnostics, cell.StaticObjects.Count);
    }
}
