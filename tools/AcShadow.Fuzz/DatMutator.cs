using System.Buffers.Binary;

namespace AcShadow.Fuzz;

/// <summary>
/// Turns (seed, case index) into one damaged pair of dats, deterministically. Every tenth case truncates a
/// dat at a block boundary, taking the bases in turn and walking each one's boundaries in turn, so a few
/// hundred cases per base cut at each one; the others apply one to three random mutations (to the first
/// base three times in four), aimed at the header, the directory, block chains or object fields as often
/// as at random bytes.
/// </summary>
public sealed class DatMutator(IReadOnlyList<FuzzBase> bases)
{
    public DatMutator(FuzzBase source) : this([source]) { }

    private static readonly string[] Policies = ["retail", "union"];
    private static readonly string[] Formats = ["canonical", "canonical", "acdream", "both"];

    private static readonly float[] FloatLimits =
        [float.NaN, float.PositiveInfinity, float.NegativeInfinity, float.MaxValue, float.MinValue, float.Epsilon, -0f, 1e30f, -1e30f, 1e-30f];

    private static readonly long[] Int32Limits =
        [0, 1, -1, 2, 0x7F, 0x80, 0xFF, 0x100, 0x7FFF, 0x8000, 0xFFFF, 0x10000, int.MaxValue, int.MinValue, 0x40000000, 63, 64, 1 << 20, (1 << 20) + 1];

    private static readonly MutationKind[] Kinds = Enum.GetValues<MutationKind>().Where(k => k != MutationKind.Truncation).ToArray();

    public FuzzInput Mutate(long seed, int caseIndex)
    {
        var random = new Random(CaseSeed(seed, caseIndex));
        var truncation = caseIndex % 10 == 0;
        var source = truncation ? bases[caseIndex / 10 % bases.Count] : bases[random.Next(4) > 0 || bases.Count == 1 ? 0 : random.Next(1, bases.Count)];
        var portal = (byte[])source.Portal.Clone();
        var cell = (byte[])source.Cell.Clone();
        var dumpSetup = source.SetupIds[random.Next(source.SetupIds.Count)];
        var notes = new List<string>();
        if (truncation)
        {
            var boundaries = source.PortalLayout.BlockCount + 1 + source.CellLayout.BlockCount + 1;
            var turn = caseIndex / 10 / bases.Count;
            var k = turn % boundaries;
            var inPortal = k <= source.PortalLayout.BlockCount;
            var layout = inPortal ? source.PortalLayout : source.CellLayout;
            var block = inPortal ? k : k - source.PortalLayout.BlockCount - 1;
            // At the boundary, and now and then a few bytes either side of it.
            var cut = layout.BlockStart(block) + (turn / boundaries % 3 == 2 ? random.Next(-4, 5) : 0);
            cut = Math.Clamp(cut, 0, layout.Length);
            if (inPortal) portal = portal[..cut]; else cell = cell[..cut];
            notes.Add($"{(inPortal ? "portal" : "cell")}: truncated to {cut} bytes (block boundary {block})");
        }
        else
        {
            var count = random.Next(10) switch { < 6 => 1, < 9 => 2, _ => 3 };
            for (var i = 0; i < count; i++)
            {
                var inPortal = random.Next(100) < 80;
                var kind = Kinds[random.Next(Kinds.Length)];
                var bytes = inPortal ? portal : cell;
                var layout = inPortal ? source.PortalLayout : source.CellLayout;
                notes.Add($"{(inPortal ? "portal" : "cell")}: {Apply(kind, bytes, layout, random)}");
            }
        }
        return new FuzzInput(portal, cell, dumpSetup, source.Landblock, $"case {caseIndex} (seed {seed}, {source.Name}): {string.Join("; ", notes)}")
        {
            From = source,
            Policy = Policies[random.Next(Policies.Length)],
            Format = Formats[random.Next(Formats.Length)],
        };
    }

    /// <summary>A well-mixed 32-bit seed per case, the same on every machine (SplitMix64 finaliser).</summary>
    public static int CaseSeed(long seed, int caseIndex)
    {
        var z = unchecked((ulong)seed * 0x9E3779B97F4A7C15UL + (ulong)caseIndex + 1);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
        return unchecked((int)(z ^ (z >> 31)));
    }

    private static string Apply(MutationKind kind, byte[] bytes, DatLayout layout, Random random) => kind switch
    {
        MutationKind.BitFlips => BitFlips(bytes, layout, random),
        MutationKind.ByteRun => ByteRun(bytes, layout, random),
        MutationKind.ZeroedBlock => ZeroedBlock(bytes, layout, random),
        MutationKind.ShuffledBlocks => ShuffledBlocks(bytes, layout, random),
        MutationKind.HeaderFieldAtLimit => HeaderField(bytes, layout, random),
        MutationKind.DirectoryFieldAtLimit => DirectoryField(bytes, layout, random),
        MutationKind.ObjectFieldAtLimit => ObjectField(bytes, layout, random),
        MutationKind.ChainPointer => ChainPointer(bytes, layout, random),
        _ => throw new ArgumentOutOfRangeException(nameof(kind)),
    };

    private static string BitFlips(byte[] bytes, DatLayout layout, Random random)
    {
        var flips = random.Next(1, 9);
        var at = new List<string>();
        for (var i = 0; i < flips; i++)
        {
            // Mostly past the header: the header has its own targeted mutation.
            var offset = random.Next(4) == 0 ? random.Next(bytes.Length) : random.Next(layout.FirstBlock, bytes.Length);
            var bit = random.Next(8);
            bytes[offset] ^= (byte)(1 << bit);
            at.Add($"0x{offset:X}.{bit}");
        }
        return $"bit flips at {string.Join(", ", at)}";
    }

    private static string ByteRun(byte[] bytes, DatLayout layout, Random random)
    {
        var length = random.Next(1, 65);
        var start = random.Next(layout.FirstBlock, bytes.Length);
        length = Math.Min(length, bytes.Length - start);
        var fill = random.Next(5) switch { 0 => 0x00, 1 => 0xFF, 2 => 0x7F, 3 => 0x80, _ => -1 };
        for (var i = 0; i < length; i++) bytes[start + i] = fill < 0 ? (byte)random.Next(256) : (byte)fill;
        return $"{length}-byte run of {(fill < 0 ? "random bytes" : $"0x{fill:X2}")} at 0x{start:X}";
    }

    private static string ZeroedBlock(byte[] bytes, DatLayout layout, Random random)
    {
        var block = random.Next(layout.BlockCount);
        var start = layout.BlockStart(block);
        var pointerOnly = random.Next(3) == 0;
        bytes.AsSpan(start, pointerOnly ? 4 : layout.BlockSize).Clear();
        return pointerOnly ? $"next pointer of block {block} zeroed" : $"block {block} zeroed";
    }

    private static string ShuffledBlocks(byte[] bytes, DatLayout layout, Random random)
    {
        var n = layout.BlockCount;
        var size = layout.BlockSize;
        if (random.Next(2) == 0)
        {
            var a = random.Next(n);
            var b = random.Next(n);
            var copy = bytes.AsSpan(layout.BlockStart(a), size).ToArray();
            bytes.AsSpan(layout.BlockStart(b), size).CopyTo(bytes.AsSpan(layout.BlockStart(a), size));
            copy.CopyTo(bytes.AsSpan(layout.BlockStart(b), size));
            return $"blocks {a} and {b} swapped";
        }
        var count = Math.Min(n, random.Next(3, 9));
        var first = random.Next(n - count + 1);
        var blocks = Enumerable.Range(first, count).Select(i => bytes.AsSpan(layout.BlockStart(i), size).ToArray()).ToArray();
        random.Shuffle(blocks);
        for (var i = 0; i < count; i++) blocks[i].CopyTo(bytes.AsSpan(layout.BlockStart(first + i), size));
        return $"blocks {first}..{first + count - 1} shuffled";
    }

    private static long Limit(DatLayout layout, Random random)
    {
        var special = new long[] { layout.Length, layout.Length - 1, layout.Length + 1, layout.BlockStart(random.Next(layout.BlockCount)), layout.BlockSize, DatHeaderSize };
        var all = Int32Limits.Concat(special).ToArray();
        return all[random.Next(all.Length)];
    }

    private const int DatHeaderSize = 400;

    private static string HeaderField(byte[] bytes, DatLayout layout, Random random)
    {
        var (name, offset) = DatLayout.HeaderFields[random.Next(DatLayout.HeaderFields.Count)];
        if (offset + 4 > bytes.Length) return $"header field {name} beyond the file";
        var value = Limit(layout, random);
        BinaryPrimitives.WriteInt32LittleEndian(bytes.AsSpan(offset), unchecked((int)value));
        return $"header {name} = {value}";
    }

    private static string DirectoryField(byte[] bytes, DatLayout layout, Random random)
    {
        var node = layout.NodeChains[random.Next(layout.NodeChains.Count)];
        var entries = BinaryPrimitives.ReadInt32LittleEndian(bytes.AsSpan(layout.FileOffset(node, 62 * 4)));
        var value = unchecked((int)Limit(layout, random));
        var choice = random.Next(10);
        int payloadOffset;
        string what;
        if (choice < 2 || entries <= 0)
        {
            payloadOffset = 62 * 4;
            what = "entry count";
        }
        else if (choice < 4)
        {
            var branch = random.Next(Math.Min(62, entries + 1));
            payloadOffset = branch * 4;
            what = $"branch {branch}";
        }
        else
        {
            // Entry layout: flags+version, id, offset, size, date, iteration.
            var entry = random.Next(Math.Min(entries, 61));
            var field = random.Next(1, 6);
            payloadOffset = 62 * 4 + 4 + entry * 24 + field * 4;
            what = $"entry {entry} {new[] { "", "id", "offset", "size", "date", "iteration" }[field]}";
        }
        var at = layout.FileOffset(node, payloadOffset);
        BinaryPrimitives.WriteInt32LittleEndian(bytes.AsSpan(at), value);
        return $"B-tree node 0x{node[0]:X} {what} = {value}";
    }

    private static string ObjectField(byte[] bytes, DatLayout layout, Random random)
    {
        var obj = layout.Objects[random.Next(layout.Objects.Count)];
        if (obj.Size < 4) return $"object 0x{obj.Id:X8} too small to aim at";
        var width = random.Next(3) switch { 0 => 1, 1 => 2, _ => 4 };
        var offset = random.Next((int)obj.Size - width + 1);
        if (width == 4 && random.Next(2) == 0) offset &= ~3; // counts sit on 4-byte boundaries
        // Floats at their limits too: positions, radii and planes are floats, and NaN or infinity must
        // come out as a diagnostic, never a crash or invalid JSON.
        var value = width == 4 && random.Next(3) == 0
            ? BitConverter.SingleToInt32Bits(FloatLimits[random.Next(FloatLimits.Length)])
            : Limit(layout, random);
        var written = new byte[4];
        BinaryPrimitives.WriteInt32LittleEndian(written, unchecked((int)value));
        for (var i = 0; i < width; i++) bytes[layout.FileOffset(obj.Blocks, offset + i)] = written[i];
        return $"object 0x{obj.Id:X8} byte {offset}: {width}-byte field = 0x{unchecked((uint)value) & (width == 4 ? 0xFFFFFFFF : (1u << (8 * width)) - 1):X}";
    }

    private static string ChainPointer(byte[] bytes, DatLayout layout, Random random)
    {
        var block = random.Next(layout.BlockCount);
        var start = layout.BlockStart(block);
        var (target, what) = random.Next(6) switch
        {
            0 => (start, "itself"),
            1 => (layout.BlockStart(random.Next(Math.Max(1, block))), "an earlier block"),
            2 => (layout.Length, "the end of the file"),
            3 => (random.Next(1, DatHeaderSize), "inside the header"),
            4 => (start + random.Next(1, layout.BlockSize), "the middle of a block"),
            _ => (unchecked((int)0x80000000) | layout.BlockStart(random.Next(layout.BlockCount)), "a block, with the top bit set"),
        };
        BinaryPrimitives.WriteInt32LittleEndian(bytes.AsSpan(start), target);
        return $"next pointer of block {block} → 0x{target:X} ({what})";
    }
}
