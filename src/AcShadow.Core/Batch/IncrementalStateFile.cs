using System.Security.Cryptography;
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
    public static byte[] Write(IncrementalState state) => CanonicalJsonWriter.WriteUtf8(Body(state).Add("sha256", Checksum(state)));

    /// <summary>
    /// The SHA-256 of the state's canonical bytes without this field, written last: a state edited by hand
    /// (a count, a hash, a path) no longer matches it and is not trusted, since reuse copies a file's
    /// recorded entry into index.json unread. A cache, not a seal: it catches edits, not forgeries.
    /// </summary>
    private static string Checksum(IncrementalState state) => Convert.ToHexStringLower(SHA256.HashData(CanonicalJsonWriter.WriteUtf8(Body(state))));

    private static JsonObj Body(IncrementalState state) => new JsonObj()
        .Add("format", IncrementalState.Format)
        .Add("tool", state.Tool)
        .Add("setups", JsonArr.Of(state.Setups.OrderBy(s => s.Id), s => new JsonObj()
            .Add("id", JsonIds.Format(s.Id))
            .Add("fingerprint", s.Fingerprint)
            .Add("parts", JsonArr.Of(s.Parts.Select(JsonIds.Format)))
            .Add("diagnostics", s.Diagnostics)
            .Add("files", JsonArr.Of(s.Files, BatchIndexWriter.File))));

    public static IncrementalState? TryRead(byte[] utf8)
    {
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
            var state = new IncrementalState(root.GetProperty("tool").GetString()!, setups);
            return root.TryGetProperty("sha256", out var sum) && sum.ValueKind == JsonValueKind.String && sum.GetString() == Checksum(state) ? state : null;
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
