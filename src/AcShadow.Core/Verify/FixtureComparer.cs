using AcShadow.Core.Dat;

namespace AcShadow.Core.Verify;

/// <summary>Compares regenerated files with the files of a fixtures folder, both as path → bytes.</summary>
public static class FixtureComparer
{
    public static FixtureComparison Compare(IReadOnlyDictionary<string, ReadOnlyMemory<byte>> expected, IReadOnlyDictionary<string, byte[]> actual,
        IReadOnlyList<string> datDifferences)
    {
        var missing = expected.Keys.Where(p => !actual.ContainsKey(p)).Order(StringComparer.Ordinal).ToArray();
        var extra = actual.Keys.Where(p => !expected.ContainsKey(p)).Order(StringComparer.Ordinal).ToArray();
        var changed = new List<ChangedFile>();
        foreach (var path in expected.Keys.Where(actual.ContainsKey).Order(StringComparer.Ordinal))
        {
            var old = actual[path];
            var fresh = expected[path];
            if (old.AsSpan().SequenceEqual(fresh.Span)) continue;
            // A checkout that turned LF into CRLF (Git for Windows' core.autocrlf) changes every file the same
            // harmless way: said as such, not as hundreds of differences.
            if (IsCrlfOf(old, fresh.Span))
            {
                changed.Add(new ChangedFile(path, [], OnlyLineEndings: true));
                continue;
            }
            var differences = JsonDiff.Compare(old, fresh.ToArray());
            changed.Add(new ChangedFile(path, differences, Reason: differences is { Count: 0 } ? SameValuesReason(old) : null));
        }
        return new FixtureComparison(missing, extra, changed, datDifferences, expected.Count);
    }

    /// <summary>Why a file holding the same JSON values as the regenerated one has other bytes.</summary>
    private static string SameValuesReason(byte[] old) => old.AsSpan().StartsWith(JsonDiff.Utf8Bom)
        ? "it starts with a UTF-8 byte-order mark, which acshadow never writes (the JSON after it is the same, and the library reads it)"
        : "the same JSON values laid out differently (key order, spacing or number spelling): acshadow writes one byte-exact layout, so the file was edited or rewritten by another tool";

    /// <summary>True when <paramref name="old"/> is <paramref name="fresh"/> with every LF written CRLF.</summary>
    internal static bool IsCrlfOf(ReadOnlySpan<byte> old, ReadOnlySpan<byte> fresh)
    {
        if (old.Length <= fresh.Length) return false;
        int i = 0, j = 0;
        while (i < old.Length && j < fresh.Length)
        {
            if (fresh[j] == (byte)'\n')
            {
                if (old[i] != (byte)'\r' || i + 1 >= old.Length || old[i + 1] != (byte)'\n') return false;
                i += 2;
            }
            else
            {
                if (old[i] != fresh[j]) return false;
                i++;
            }
            j++;
        }
        return i == old.Length && j == fresh.Length;
    }

    /// <summary>
    /// What differs between the dat index.json recorded and the dat at hand. With both content hashes, the
    /// hash decides (the file name never does: a copy under another name is the same dat); without one
    /// (an index written before hashes), the size and iteration.
    /// </summary>
    public static IReadOnlyList<string> DatDifferences(string label, DatSourceInfo? recorded, DatSourceInfo? current)
    {
        if (recorded is null && current is null) return [];
        if (recorded is null || current is null)
            return [$"{label}: index.json records {(recorded is null ? "none" : recorded.FileName)}, this run has {(current is null ? "none" : current.FileName)}"];
        var differences = new List<string>();
        if (recorded.Sha256 is { } was && current.Sha256 is { } now)
        {
            if (was == now) return [];
            differences.Add($"{label} content: SHA-256 {was} → {now}");
        }
        if (recorded.Size != current.Size) differences.Add($"{label} size: {recorded.Size} → {current.Size} bytes");
        if (recorded.Iteration != current.Iteration) differences.Add($"{label} iteration: {recorded.Iteration} → {current.Iteration}");
        return differences;
    }
}
