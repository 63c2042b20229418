using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;

namespace AcShadow.Analysis.Doctor;

/// <summary>
/// `acshadow doctor`: reads every GfxObj and Setup of the portal dat (and every LandBlockInfo of the cell
/// dat) straight from their bytes, checks each claim acshadow rests on, runs the export twice, and returns
/// the report. Objects are decoded one at a time into each worker's buffer and dropped: memory stays flat
/// whatever the dat's size (only one byte per GfxObj id is kept, for the Setup checks). Pure: no console,
/// no files.
/// </summary>
public static class DoctorRunner
{
    public static DoctorReport Run(DatArchive portal, DatArchive? cell, DoctorOptions options, CancellationToken cancellation = default)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(options.Jobs, 1);
        var t = new DoctorTallies();
        var gfx = new GfxObjPhysics();
        var parallel = new ParallelOptions { MaxDegreeOfParallelism = options.Jobs, CancellationToken = cancellation };

        // GfxObjs first: the Setup checks ask whether each part has a PhysicsBSP.
        var gfxIds = Ids(portal, DatObjectKind.GfxObj);
        Parallel.ForEach(gfxIds, parallel, id =>
        {
            t.GfxObjs.Add();
            var gfxObj = Decode(portal, id, GfxObj.Read, g => g.Id, t, out var left);
            if (gfxObj is null) { gfx.Set(id, GfxObjPhysics.State.Unreadable); return; }
            t.GfxObjsDecoded.Add();
            // The decoder stops after the sort centre: only an object with nothing after it can be checked for unread bytes.
            if ((gfxObj.Flags & (GfxObjFlags.HasDrawing | GfxObjFlags.HasDIDDegrade)) != 0) t.BytesNotCheckable.Add();
            else BytesUsed(id, left, t);
            gfx.Set(id, gfxObj.PhysicsBsp is null ? GfxObjPhysics.State.NoBsp : GfxObjPhysics.State.Bsp);
            BspInspection.Inspect(gfxObj, t);
        });

        // Motion tables and animations decoded once each, however many Setups share them. Not disposed:
        // disposing would close the archive the caller owns.
        var motions = new DatDatabase(portal);
        Parallel.ForEach(Ids(portal, DatObjectKind.Setup), parallel, id =>
        {
            t.Setups.Add();
            var setup = Decode(portal, id, Setup.Read, s => s.Id, t, out var left);
            if (setup is null) return;
            t.SetupsDecoded.Add();
            BytesUsed(id, left, t);
            SetupInspection.Inspect(setup, gfx, t);
            MotionPoseInspection.Inspect(setup, motions, t);
        });

        if (cell is not null)
            Parallel.ForEach(Ids(cell, DatObjectKind.LandBlockInfo), parallel, id =>
            {
                t.LandBlockInfos.Add();
                var info = Decode(cell, id, LandBlockInfo.Read, l => l.Id, t, out var left);
                if (info is null) return;
                t.LandBlockInfosDecoded.Add();
                BytesUsed(id, left, t);
            });

        ExportSelfCheck.Outcome? export = null;
        if (options.Export) export = ExportSelfCheck.Run(portal, options.Jobs, cancellation);
        var peak = options.PeakMemoryBytes?.Invoke();

        return new DoctorReport(options.ToolVersion, Facts(portal), cell is null ? null : Facts(cell),
            DoctorChecks.From(t, portal, cell, export, peak));
    }

    private static uint[] Ids(DatArchive archive, DatObjectKind kind) =>
        [.. archive.Entries.Where(e => kind.Contains(e.Id)).Select(e => e.Id)];

    /// <summary>The decoded object, or null (the failure counted by reason) when its bytes cannot be read as one.</summary>
    private static T? Decode<T>(DatArchive archive, uint id, Func<DatBinaryReader, T> read, Func<T, uint> idOf, DoctorTallies t, out int left)
        where T : class
    {
        left = 0;
        var buffer = ObjectBytesBuffer.Take();
        try
        {
            var size = archive.ReadObjectBytes(id, ref buffer);
            if (size < 0) return null;
            var reader = new DatBinaryReader(buffer.AsMemory(0, size));
            var value = read(reader);
            if (idOf(value) != id) throw new DatFormatException($"the object's bytes carry id 0x{idOf(value):X8}");
            left = reader.Remaining;
            return value;
        }
        catch (Exception e) when (DatArchive.IsReadFailure(e))
        {
            t.Failed(id, e);
            return null;
        }
        finally
        {
            ObjectBytesBuffer.Return(buffer);
        }
    }

    private static void BytesUsed(uint id, int left, DoctorTallies t)
    {
        t.BytesChecked.Add();
        if (left > 0) t.BytesLeft.Add(id);
    }

    private static DoctorDatFacts Facts(DatArchive archive)
    {
        var byType = archive.Entries.GroupBy(e => e.Id >> 24).OrderBy(g => g.Key)
            .Select(g => new KeyValuePair<string, long>($"0x{g.Key:X2}", g.Count())).ToArray();
        return new DoctorDatFacts(archive.Header.Kind.ToString(), archive.Length, archive.Header.FileSize, archive.Header.BlockSize,
            archive.Entries.Count, archive.MaxIteration, byType);
    }
}
