using AcShadow.Core.Dat.Binary;
namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// The dat's Environment (portal dat, 0x0D000000-0x0D00FFFF; named so here to stay clear of
/// System.Environment): the cell shapes EnvCells choose from by index. Layout (DatReaderWriter's
/// dats.xml Environment, ACE's Environment.Unpack): id, a uint count, then per cell a uint key and a
/// <see cref="CellStruct"/>.
/// </summary>
public sealed record CellEnvironment(uint Id, IReadOnlyList<KeyValuePair<uint, CellStruct>> Cells)
{
    public CellStruct? Cell(uint index)
    {
        foreach (var (key, cell) in Cells)
            if (key == index) return cell;
        return null;
    }

    public static CellEnvironment Read(DatBinaryReader r)
    {
        var id = r.ReadUInt32();
        // A CellStruct is at least 3 counts, an empty vertex array, a leaf of each tree and the flag (64 bytes), plus its key.
        var count = r.ReadCount(r.ReadUInt32(), 68, "cell structure");
        var cells = new List<KeyValuePair<uint, CellStruct>>(count);
        for (var i = 0; i < count; i++)
        {
            var key = r.ReadUInt32();
            cells.Add(new(key, CellStruct.Read(r)));
        }
        return new CellEnvironment(id, cells);
    }

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt32(Id);
        w.WriteUInt32((uint)Cells.Count);
        foreach (var (key, cell) in Cells)
        {
            w.WriteUInt32(key);
            cell.Write(w);
        }
    }
}
