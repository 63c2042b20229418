using AcShadow.Core.Dat.Binary;
namespace AcShadow.Core.Dat;

/// <summary>
/// The 400-byte header at offset 0: a 256-byte version string and 64 bytes of transaction data,
/// then (from 0x140) the magic 0x5442, block size, file size, data set and the B-tree root offset.
/// </summary>
public sealed record DatHeader(
    int BlockSize,
    int FileSize,
    DatFileKind Kind,
    uint SubSet,
    int FirstFreeBlock,
    int LastFreeBlock,
    int FreeBlockCount,
    int RootBlock,
    int MasterMapId,
    int EngineVersion,
    int GameVersion,
    Guid MajorVersion,
    uint MinorVersion)
{
    public const int Size = 400;
    public const int Magic = 0x5442;
    private const int VersionBytes = 256;
    private const int TransactionBytes = 64;

    public static DatHeader Read(DatBinaryReader r)
    {
        r.Skip(VersionBytes + TransactionBytes);
        var magic = r.ReadInt32();
        if (magic != Magic)
            throw new DatFormatException($"not an Asheron's Call dat file: magic at 0x140 is 0x{magic:X8}, expected 0x{Magic:X8}");
        var blockSize = r.ReadInt32();
        var fileSize = r.ReadInt32();
        var kind = (DatFileKind)r.ReadUInt32();
        var subSet = r.ReadUInt32();
        var firstFree = r.ReadInt32();
        var lastFree = r.ReadInt32();
        var freeCount = r.ReadInt32();
        var root = r.ReadInt32();
        r.ReadInt32(); // new LRU
        r.ReadInt32(); // old LRU
        r.ReadInt32(); // use LRU
        var masterMap = r.ReadInt32();
        var engine = r.ReadInt32();
        var game = r.ReadInt32();
        var major = new Guid(r.ReadBytes(16));
        var minor = r.ReadUInt32();
        if (blockSize < 64 || blockSize > 1 << 20)
            throw new DatFormatException($"dat header gives an implausible block size {blockSize}");
        return new DatHeader(blockSize, fileSize, kind, subSet, firstFree, lastFree, freeCount, root, masterMap, engine, game, major, minor);
    }

    public void Write(DatBinaryWriter w)
    {
        w.WriteBytes(new byte[VersionBytes]);
        var transactions = new byte[TransactionBytes];
        transactions[1] = 0x50; // "\0PL\0": the empty transaction record retail dats carry
        transactions[2] = 0x4C;
        w.WriteBytes(transactions);
        w.WriteInt32(Magic);
        w.WriteInt32(BlockSize);
        w.WriteInt32(FileSize);
        w.WriteUInt32((uint)Kind);
        w.WriteUInt32(SubSet);
        w.WriteInt32(FirstFreeBlock);
        w.WriteInt32(LastFreeBlock);
        w.WriteInt32(FreeBlockCount);
        w.WriteInt32(RootBlock);
        w.WriteInt32(0);
        w.WriteInt32(0);
        w.WriteInt32(0);
        w.WriteInt32(MasterMapId);
        w.WriteInt32(EngineVersion);
        w.WriteInt32(GameVersion);
        w.WriteBytes(MajorVersion.ToByteArray());
        w.WriteUInt32(MinorVersion);
    }
}
