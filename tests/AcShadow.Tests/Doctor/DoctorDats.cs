using AcShadow.Analysis.Doctor;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Doctor;

/// <summary>
/// The forged sample portal dat with chosen objects replaced (re-encoded with the object writers and the
/// archive writer), read back through the real reader, and the doctor's report on it.
/// </summary>
public static class DoctorDats
{
    /// <summary>Every object of the sample portal dat, as stored.</summary>
    public static Dictionary<uint, byte[]> SampleObjects()
    {
        using var archive = DatArchive.Open(new MemoryStream(SampleDat.PortalBytes, writable: false), "client_portal.dat");
        return archive.Entries.ToDictionary(e => e.Id, e => archive.ReadObjectBytes(e.Id)!);
    }

    public static GfxObj ReadGfxObj(Dictionary<uint, byte[]> objects, uint id) => GfxObj.Read(new DatBinaryReader(objects[id]));

    public static Setup ReadSetup(Dictionary<uint, byte[]> objects, uint id) => Setup.Read(new DatBinaryReader(objects[id]));

    public static byte[] Encode(Action<DatBinaryWriter> write)
    {
        var w = new DatBinaryWriter();
        write(w);
        return w.ToArray();
    }

    public static byte[] Portal(Dictionary<uint, byte[]> objects) =>
        DatArchiveWriter.Write(objects, new DatArchiveWriter.Options(DatFileKind.Portal));

    /// <summary>The report on a portal dat, without the export runs (they are the tool's check, tested apart).</summary>
    public static DoctorReport Report(byte[] portal, int jobs = 2, bool export = false)
    {
        using var archive = DatArchive.Open(new MemoryStream(portal, writable: false), "client_portal.dat");
        return DoctorRunner.Run(archive, null, new DoctorOptions(jobs, "test", () => 64L << 20, export));
    }

    /// <summary>A GfxObj of the sample with a PhysicsBSP whose every internal node has both children (null when none has).</summary>
    public static IEnumerable<GfxObj> BspGfxObjs(Dictionary<uint, byte[]> objects) =>
        objects.Keys.Where(id => DatObjectKind.GfxObj.Contains(id)).Order().Select(id => ReadGfxObj(objects, id)).Where(g => g.PhysicsBsp is { IsLeaf: false });

    public static IEnumerable<PhysicsBspNode> Nodes(PhysicsBspNode node)
    {
        yield return node;
        if (node.Pos is { } pos) foreach (var n in Nodes(pos)) yield return n;
        if (node.Neg is { } neg) foreach (var n in Nodes(neg)) yield return n;
    }
}
