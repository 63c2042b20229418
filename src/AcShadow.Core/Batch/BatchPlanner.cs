using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Export;
using AcShadow.Core.Scenes;

namespace AcShadow.Core.Batch;

/// <summary>
/// Resolves a <see cref="BatchSelection"/> against the dats: the union of the door catalog, every Setup,
/// a setups file's ids and a landblock's placed Setups, sorted by id; ids the dat lacks become
/// <see cref="SkippedItem"/>s, not errors.
/// </summary>
public static class BatchPlanner
{
    public static BatchPlan Plan(BatchSelection selection, IDatSource portal, IDatSource? cell, IReadOnlyList<uint> doorCatalog)
    {
        var requested = new SortedDictionary<uint, SelectionSource>();
        void Request(IEnumerable<uint> ids, SelectionSource source)
        {
            foreach (var id in ids) requested[id] = requested.GetValueOrDefault(id) | source;
        }

        var inDat = portal.ListIds(DatObjectKind.Setup).ToHashSet();
        if (selection.Doors) Request(doorCatalog, SelectionSource.Doors);
        if (selection.All) Request(inDat, SelectionSource.All);
        if (selection.Setups is { } list) Request(list.Ids, SelectionSource.SetupsFile);

        LandblockScene? scene = null;
        if (selection.Landblock is { } landblock)
        {
            if (cell is null)
                throw new SelectionException(SelectionProblem.NeedsCellDat, $"--landblock {LandblockIds.Short(landblock)} needs the cell dat: pass --cell-dat PATH (client_cell_1.dat)");
            var info = cell.ReadLandBlockInfo(landblock)
                ?? throw new SelectionException(SelectionProblem.NotInDat, $"landblock {LandblockIds.Short(landblock)} has no LandBlockInfo (0x{landblock:X8}) in {cell.Info.FileName}");
            scene = LandblockScene.From(info);
            if (selection.Cells) scene = WithCells(scene, info, cell);
            Request(scene.SetupIds, SelectionSource.Landblock);
        }

        var setups = new List<PlannedSetup>();
        var skipped = new List<SkippedItem>();
        foreach (var (id, from) in requested)
        {
            if (inDat.Contains(id)) setups.Add(new PlannedSetup(id, from));
            else skipped.Add(new SkippedItem(id, SkippedItem.NotInDat, from));
        }
        return new BatchPlan(setups, scene, skipped);
    }

    /// <summary>Each of the landblock's cells decoded once; one that is missing or damaged is named, not fatal.</summary>
    private static LandblockScene WithCells(LandblockScene scene, Dat.Objects.LandBlockInfo info, IDatSource cell)
    {
        var cells = new List<Dat.Objects.EnvCell>();
        var missing = new List<SkippedCell>();
        // A landblock cannot have more cells than the whole cell dat lists: a NumCells above that is damage
        // (it would otherwise name tens of thousands of missing cells), refused as a corrupt dat.
        var listed = cell.ListIds(DatObjectKind.EnvCell).ToHashSet();
        if (info.NumCells > listed.Count)
            throw new DatFormatException($"LandBlockInfo 0x{info.Id:X8} counts {info.NumCells} cells but the cell dat lists only {listed.Count} EnvCells");
        foreach (var id in LandblockScene.CellIds(info))
        {
            try
            {
                if (listed.Contains(id) && cell.ReadEnvCell(id) is { } envCell) cells.Add(envCell);
                else missing.Add(new SkippedCell(id, SkippedItem.NotInDat));
            }
            catch (DatFormatException e)
            {
                missing.Add(new SkippedCell(id, $"unreadable: {e.Message}"));
            }
        }
        return scene with { Cells = cells, MissingCells = missing };
    }
}
