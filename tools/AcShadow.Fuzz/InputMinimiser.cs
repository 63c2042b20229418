using AcShadow.Core.Dat;

namespace AcShadow.Fuzz;

/// <summary>
/// Shrinks a failing input while it still fails with the same signature: first undoes each damaged run
/// of bytes that is not needed, then (when the damaged dat still opens) rebuilds it with only the objects
/// the failure needs, then cuts off the blocks past what the failure needs.
/// </summary>
public sealed class InputMinimiser(CaseRunner runner)
{
    private int _attempt;

    public FuzzInput Minimise(FuzzInput input, CaseFailure failure)
    {
        bool Fails(FuzzInput candidate) => runner.Run(candidate, $"minimise-{_attempt++}").Failure?.Signature == failure.Signature;

        var portal = input.From is { } original ? UndoRuns(input.Portal, original.Portal, p => Fails(input with { Portal = p })) : input.Portal;
        var cell = input.From is { } intact ? UndoRuns(input.Cell, intact.Cell, c => Fails(input with { Portal = portal, Cell = c })) : input.Cell;
        portal = KeepNeededObjects(portal, p => Fails(input with { Portal = p, Cell = cell }));
        cell = KeepNeededObjects(cell, c => Fails(input with { Portal = portal, Cell = c }));
        portal = CutTail(portal, p => Fails(input with { Portal = p, Cell = cell }));
        cell = CutTail(cell, c => Fails(input with { Portal = portal, Cell = c }));
        portal = ZeroUnneededBlocks(portal, p => Fails(input with { Portal = p, Cell = cell }));
        cell = ZeroUnneededBlocks(cell, c => Fails(input with { Portal = portal, Cell = c }));
        return input with { Portal = portal, Cell = cell };
    }

    /// <summary>Each run of changed bytes (runs closer than 16 bytes merged) is put back to the original if the failure stays.</summary>
    private static byte[] UndoRuns(byte[] damaged, byte[] original, Func<byte[], bool> fails)
    {
        var current = (byte[])damaged.Clone();
        var shared = Math.Min(current.Length, original.Length);
        var runs = new List<(int Start, int End)>();
        for (var i = 0; i < shared; i++)
        {
            if (current[i] == original[i]) continue;
            if (runs.Count > 0 && i - runs[^1].End < 16) runs[^1] = (runs[^1].Start, i + 1);
            else runs.Add((i, i + 1));
        }
        foreach (var (start, end) in runs.Take(400))
        {
            var candidate = (byte[])current.Clone();
            original.AsSpan(start, end - start).CopyTo(candidate.AsSpan(start));
            if (fails(candidate)) current = candidate;
        }
        return current;
    }

    /// <summary>Rewrites the dat with a subset of its objects (bytes as damaged), dropping each object the failure does not need.</summary>
    private static byte[] KeepNeededObjects(byte[] dat, Func<byte[], bool> fails)
    {
        Dictionary<uint, byte[]> objects;
        DatArchiveWriter.Options options;
        try
        {
            using var archive = DatArchive.Open(new MemoryStream(dat, writable: false), "minimise.dat");
            objects = archive.Entries.ToDictionary(e => e.Id, e => archive.ReadObjectBytes(e.Id)!);
            options = new DatArchiveWriter.Options(archive.Header.Kind, archive.Header.BlockSize);
        }
        catch (Exception)
        {
            return dat; // the container itself is what is damaged (however it fails): rebuilding would repair it
        }
        var rebuilt = DatArchiveWriter.Write(objects, options);
        if (!fails(rebuilt)) return dat;
        foreach (var id in objects.Keys.Order().ToArray())
        {
            var fewer = objects.Where(kv => kv.Key != id).ToDictionary();
            var candidate = DatArchiveWriter.Write(fewer, options);
            if (!fails(candidate)) continue;
            objects = fewer;
            rebuilt = candidate;
        }
        return rebuilt;
    }

    /// <summary>
    /// Zeroes each block the failure does not need. When the damage is in the directory (which a rebuild
    /// would repair) the file keeps its length, but what is left is the part that matters, and it compresses.
    /// </summary>
    private static byte[] ZeroUnneededBlocks(byte[] dat, Func<byte[], bool> fails)
    {
        var blockSize = BlockSizeOf(dat);
        if (blockSize is null) return dat;
        var current = (byte[])dat.Clone();
        for (var start = FirstBlock(blockSize.Value); start < current.Length; start += blockSize.Value)
        {
            var length = Math.Min(blockSize.Value, current.Length - start);
            if (current.AsSpan(start, length).IndexOfAnyExcept((byte)0) < 0) continue;
            var candidate = (byte[])current.Clone();
            candidate.AsSpan(start, length).Clear();
            if (fails(candidate)) current = candidate;
        }
        return current;
    }

    private static int? BlockSizeOf(byte[] dat) =>
        dat.Length < DatHeader.Size ? null : Math.Clamp(BitConverter.ToInt32(dat, 0x144), 64, 1 << 20);

    private static int FirstBlock(int blockSize) => (DatHeader.Size + blockSize - 1) / blockSize * blockSize;

    /// <summary>The shortest prefix ending on a block boundary that still fails (or the dat unchanged).</summary>
    private static byte[] CutTail(byte[] dat, Func<byte[], bool> fails)
    {
        if (BlockSizeOf(dat) is not { } blockSize) return dat;
        for (var length = FirstBlock(blockSize); length < dat.Length; length += blockSize)
            if (fails(dat[..length])) return dat[..length];
        return dat;
    }
}
