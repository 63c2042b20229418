using AcShadow.Core.Dat;
using AcShadow.Forging;

namespace AcShadow.Fuzz;

/// <summary>
/// The intact dats every case starts from: the forge's built-in sample (portal and cell), their layouts,
/// the Setups `dump` may be asked for and the landblock `batch` exports.
/// </summary>
public sealed class FuzzBase
{
    public FuzzBase(string name, byte[] portal, byte[] cell)
    {
        Name = name;
        Portal = portal;
        Cell = cell;
        PortalLayout = new DatLayout(portal);
        CellLayout = new DatLayout(cell);
        SetupIds = PortalLayout.Objects.Select(o => o.Id).Where(id => DatObjectKind.Setup.Contains(id)).ToArray();
        Landblock = CellLayout.Objects.Select(o => o.Id).First(id => DatObjectKind.LandBlockInfo.Contains(id)) >> 16;
    }

    public static FuzzBase Sample()
    {
        var (portal, cell) = SampleDats.Build();
        return new FuzzBase("sample", portal, cell);
    }

    /// <summary>
    /// The sample portal dat with filler objects (ids acshadow never reads) added until its directory is a
    /// two-level B-tree: the sample alone fits in one leaf, so branches and inner nodes would go unfuzzed.
    /// </summary>
    public static FuzzBase SampleWithDeepDirectory()
    {
        var (portal, cell) = SampleDats.Build();
        using var archive = DatArchive.Open(new MemoryStream(portal, writable: false), "sample.dat");
        var objects = archive.Entries.ToDictionary(e => e.Id, e => archive.ReadObjectBytes(e.Id)!);
        for (var i = 0u; objects.Count <= 2 * DatBTreeNode.MaxEntries; i++)
            objects[FillerIds + i] = BitConverter.GetBytes(FillerIds + i);
        var deep = DatArchiveWriter.Write(objects, new DatArchiveWriter.Options(archive.Header.Kind, archive.Header.BlockSize));
        return new FuzzBase("sample with a two-level directory", deep, cell);
    }

    /// <summary>Texture ids (0x06…): a portal dat holds them, acshadow never decodes them.</summary>
    private const uint FillerIds = 0x06000000;

    public static IReadOnlyList<FuzzBase> All() => [Sample(), SampleWithDeepDirectory()];

    public string Name { get; }

    public byte[] Portal { get; }
    public byte[] Cell { get; }
    public DatLayout PortalLayout { get; }
    public DatLayout CellLayout { get; }
    public IReadOnlyList<uint> SetupIds { get; }

    /// <summary>The landblock (0xXXYY) whose scene batch exports.</summary>
    public uint Landblock { get; }
}
