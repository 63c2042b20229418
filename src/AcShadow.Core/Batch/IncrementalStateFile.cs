using System.Security.Cryptography;
using System.Text;
using System.Text.Json;
using AcShadow.Core.Export;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Batch;
using AcShadow.Fixtures.Json;

namespace AcShadow.Core.Batch;

/// <summary>
/// incremental.json (docs/batch.md): <see cref="IncrementalState"/> as canonical JSON. Reading is
/// forgiving by design: anything unreadable gives null, and the run that asked
/// for it simply exports everything. A state naming a file outside the folder (an absolute path, "..")
/// is unreadable too: it is data, and reuse never reaches past the folder on its word; so is one whose
/// content no longer matches its own SHA-256 (edited by hand), or that has none (written before it).
/// </summary>
public static class IncrementalStateFile
{
    /// <summary>The state's canonical bytes, its checksum last. The body is serialised once and the member spliced in before the closing brace.</summary>
    public static byte[] Write(IncrementalState state)
    {
        var body = CanonicalJsonWriter.WriteUtf8(Body(state));
        // A body laid out member by member ends in "\n}\n"; one small enough to sit on a line (no Setups) is written whole again.
        if (!body.AsSpan().StartsWith("{\n"u8) || !body.AsSpan().EndsWith(Closing))
            return CanonicalJsonWriter.WriteUtf8(Body(state).Add("sha256", Checksum(body)));
        var sum = Encoding.ASCII.GetBytes(Checksum(body));
        return [.. body.AsSpan(0, body.Length - Closing.Length), .. MemberHead, .. sum, (byte)'"', .. Closing];
    }

    /// <summary>
    /// The SHA-256 of the state's canonical bytes without this field, written last: a state edited by hand
    /// (a count, a hash, a path) no longer matches it and is not trusted, since reuse copies a file's
    /// recorded entry into index.json unread. A cache, not a seal: it catches edits, not forgeries.
    /// </summary>
    private static string Checksum(ReadOnlySpan<byte> canonicalBody) => Convert.ToHexStringLower(SHA256.HashData(canonicalBody));

    private static ReadOnlySpan<byte> Closing => "\n}\n"u8;
    private static ReadOnlySpan<byte> MemberHead => ",\n  \"sha256\": \""u8;
    private const int HexLength = 2 * SHA256.HashSizeInBytes;

    /// <summary>
    /// Whether the file carries its checksum as <see cref="Write"/> lays it out (the member last, before the closing
    /// brace) and the bytes around the member hash to it. Checked over the bytes as read: serialising a retail state
    /// again to hash it cost an incremental run with nothing to do a fifth of its time (9.5 MB on the 7,000-Setup dat).
    /// </summary>
    private static bool HoldsItsChecksum(ReadOnlySpan<byte> file)
    {
        var member = file.Length - Closing.Length - MemberHead.Length - HexLength - 1;
        if (member < 0 || !file.EndsWith(Closing) || !file[member..].StartsWith(MemberHead) || file[^(Closing.Length + 1)] != '"') return false;
        using var hash = IncrementalHash.CreateHash(HashAlgorithmName.SHA256);
        hash.AppendData(file[..member]);
        hash.AppendData(Closing);
        Span<byte> sum = stackalloc byte[SHA256.HashSizeInBytes];
        hash.GetHashAndReset(sum);
        Span<byte> hex = stackalloc byte[HexLength];
        return Convert.TryToHexStringLower(sum, hex, out _) && hex.SequenceEqual(file.Slice(member + MemberHead.Length, HexLength));
    }

    private static JsonObj Body(IncrementalState state) => new JsonObj()
        .Add("format", IncrementalState.Format)
        .Add("tool", state.Tool)
        .Add("setups", JsonArr.Of(state.Setups.OrderBy(s => s.Id), s => new JsonObj()
            .Add("id", JsonIds.Format(s.Id))
            .Add("fingerprint", s.Fingerprint)
            .Add("parts", JsonArr.Of(s.Parts.Select(JsonIds.Format)))
            .Add("diagnostics", s.Diagnostics)
            .Add("files", JsonArr.Of(s.Files, BatchIndexWriter.File))));

    public static IncrementalState? TryRead(byte[] utf8) => TryRead(utf8, out _);

    /// <summary>As <see cref="TryRead(byte[])"/>; <paramref name="asWritten"/>: the file carries its checksum as <see cref="Write"/> lays it out (<see cref="HoldsItsChecksum"/>).</summary>
    public static IncrementalState? TryRead(byte[] utf8, out bool asWritten)
    {
        asWritten = false;
        try
        {
            using var doc = JsonDocument.Parse(utf8);
            var root = doc.RootElement;
            if (root.GetProperty("format").GetString() != IncrementalState.Format) return null;
            var setups = root.GetProperty("setups").EnumerateArray().Select(s => new IncrementalSetup(
                Id(s.GetProperty("id")),
                s.GetProperty("fingerprint").GetString()!,
                s.GetProperty("parts").EnumerateArray().Select(Id).ToArray(),
                s.GetProperty("diagnostics").GetInt32(),
                s.GetProperty("files").EnumerateArray().Select(f => new FileEntry(
                    Inside(f.GetProperty("path").GetString()),
                    Kind(f.GetProperty("kind").GetString()),
                    Id(f.GetProperty("id")),
                    f.GetProperty("shapes").GetInt32(),
                    f.GetProperty("polygons").GetInt32(),
                    f.GetProperty("bytes").GetInt64(),
                    f.GetProperty("sha256").GetString()!)).ToArray())).ToArray();
            // One record a Setup: reuse and the unchanged check key records by Setup, and a second one is no state this tool wrote.
            if (setups.Select(s => s.Id).Distinct().Count() != setups.Length) return null;
            var state = new IncrementalState(root.GetProperty("tool").GetString()!, setups);
            // Laid out otherwise (by hand, or the small state written on one line): the checksum of the state as read, serialised again.
            asWritten = HoldsItsChecksum(utf8);
            return asWritten || (root.TryGetProperty("sha256", out var sum) && sum.ValueKind == JsonValueKind.String
                && sum.GetString() == Checksum(CanonicalJsonWriter.WriteUtf8(Body(state)))) ? state : null;
        }
        catch (Exception e) when (e is JsonException or InvalidOperationException or KeyNotFoundException or FormatException)
        {
            return null;
        }
    }

    private static string Inside(string? path) =>
        RelativeOutputPath.StaysInside(path) ? path! : throw new FormatException($"not a path inside the folder: {path}");

    private static uint Id(JsonElement e) =>
        JsonIds.TryParse(e.GetString(), out var id) ? id : throw new FormatException($"not an id: {e}");

    private static FixtureKind Kind(string? name) =>
        Enum.GetValues<FixtureKind>().Where(k => FixtureKinds.Name(k) == name).Select(k => (FixtureKind?)k).FirstOrDefault()
        ?? throw new FormatException($"not a file kind: {name}");
}
