using AcShadow.Core.Batch;
using AcShadow.Core.Dat;
using AcShadow.Core.Export;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Core.Poses;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Batch;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Batch;

/// <summary>
/// Writes index.json: the run's inputs (enough for verify to regenerate), a summary, what was skipped,
/// and every file with its id, kind, counts, size and SHA-256. Nothing time- or machine-dependent goes
/// in, so the index is as reproducible as the files.
/// </summary>
public static class BatchIndexWriter
{
    /// <summary>The bytes <see cref="Write(Stream, BatchInputs, IReadOnlyList{FileEntry}, IReadOnlyList{SkippedItem})"/> writes, in memory (verify, tests).</summary>
    public static byte[] Write(BatchInputs inputs, IReadOnlyList<FileEntry> files, IReadOnlyList<SkippedItem> skipped)
    {
        var bytes = new MemoryStream();
        Write(bytes, inputs, files, skipped);
        return bytes.ToArray();
    }

    /// <summary>
    /// The canonical bytes of <see cref="ToJson"/>, with the files array (tens of thousands of entries on a
    /// retail dat) streamed to <paramref name="destination"/> in chunks instead of built as a tree or one
    /// buffer: either cost more memory at the end of a batch than the rest of it (a test holds the
    /// streamed bytes to the tree's).
    /// </summary>
    public static void Write(Stream destination, BatchInputs inputs, IReadOnlyList<FileEntry> files, IReadOnlyList<SkippedItem> skipped)
    {
        if (files.Count == 0)
        {
            destination.Write(CanonicalJsonWriter.WriteUtf8(ToJson(inputs, files, skipped)));
            return;
        }
        const string emptyFiles = "  \"files\": []\n}\n";
        var head = CanonicalJsonWriter.Write(Head(inputs, files, skipped).Add("files", new JsonArr()));
        if (!head.EndsWith(emptyFiles, StringComparison.Ordinal)) throw new InvalidOperationException("index.json must end with its files array");
        var t = new Utf8JsonText(ChunkBytes + 4096);
        t.Utf8(head[..^emptyFiles.Length]).Raw("  \"files\": [\n");
        for (var i = 0; i < files.Count; i++)
        {
            if (t.Length >= ChunkBytes) t.MoveTo(destination);
            var f = files[i];
            t.Raw("    {\n      \"path\": ").String(f.RelativePath)
                .Raw(",\n      \"kind\": ").String(FixtureKinds.Name(f.Kind))
                .Raw(",\n      \"id\": ").String(JsonIds.Format(f.Id))
                .Raw(",\n      \"shapes\": ").Int(f.ShapeCount)
                .Raw(",\n      \"polygons\": ").Int(f.PolygonCount)
                .Raw(",\n      \"bytes\": ").Int(f.Bytes)
                .Raw(",\n      \"sha256\": ").String(f.Sha256)
                .Raw(i < files.Count - 1 ? "\n    },\n" : "\n    }\n");
        }
        t.Raw("  ]\n}\n").MoveTo(destination);
    }

    private const int ChunkBytes = 64 * 1024;

    public static JsonObj ToJson(BatchInputs inputs, IReadOnlyList<FileEntry> files, IReadOnlyList<SkippedItem> skipped) =>
        Head(inputs, files, skipped).Add("files", JsonArr.Of(files, File));

    /// <summary>Everything before the files array.</summary>
    private static JsonObj Head(BatchInputs inputs, IReadOnlyList<FileEntry> files, IReadOnlyList<SkippedItem> skipped) => new JsonObj()
        .Add("format", FileFormats.Index.Format)
        .Add("inputs", Inputs(inputs))
        .Add("summary", new JsonObj()
            .Add("files", files.Count)
            .Add("setups", files.Count(f => f.Kind == FixtureKind.Shadow))
            .Add("bspDumps", files.Count(f => f.Kind == FixtureKind.Bsp))
            .Add("scenes", files.Count(f => f.Kind == FixtureKind.Scene))
            .Add("skipped", skipped.Count)
            .Add("bytes", files.Sum(f => f.Bytes)))
        .Add("skipped", JsonArr.Of(skipped, s => new JsonObj()
            .Add("id", JsonIds.Format(s.Id)).Add("reason", s.Reason).Add("from", JsonArr.Of(s.From.Names()))));

    private static JsonObj Inputs(BatchInputs inputs)
    {
        var selection = inputs.Selection;
        var chosen = new JsonObj()
            .Add("doors", selection.Doors)
            .Add("all", selection.All)
            .Add("setupsFile", selection.Setups is { } list
                ? new JsonObj().Add("name", list.Name).Add("ids", JsonArr.Of(list.Ids.Select(JsonIds.Format)))
                : JsonNull.Value)
            .Add("landblock", selection.Landblock is { } lb ? JsonIds.Format(lb) : null);
        // Written only when off, so indexes of runs before cells existed read the same.
        if (!selection.Cells) chosen.Add("cells", false);
        var json = new JsonObj()
            .Add("dat", Dat(inputs.Dat))
            .Add("cellDat", inputs.CellDat is { } cell ? Dat(cell) : JsonNull.Value)
            .Add("policy", inputs.Policy.Name())
            .Add("entityScale", inputs.EntityScale)
            .Add("pose", inputs.Pose.Name())
            .Add("doorState", inputs.DoorState.Name())
            .Add("motionTable", inputs.MotionTable is { } table ? JsonIds.Format(table) : null)
            .Add("selection", chosen);
        if (inputs.Movement is { } movement)
            json.Add("movement", new JsonObj().Add("setups", JsonArr.Of(movement.Setups.Select(JsonIds.Format))).Add("mover", JsonIds.Format(movement.Mover)));
        return inputs.Formats == OutputFormats.Canonical ? json : json.Add("formats", inputs.Formats.Name());
    }

    /// <summary>The dat's identity; its SHA-256 when the run hashed it (batch does: verify compares that, not the name).</summary>
    public static JsonObj Dat(DatSourceInfo info)
    {
        var json = new JsonObj()
            .Add("fileName", info.FileName)
            .Add("size", info.Size)
            .Add("kind", info.Kind.ToString())
            .Add("iteration", info.Iteration)
            .Add("iterationSource", info.IterationSource.Name())
            .Add("blockSize", info.BlockSize);
        return info.Sha256 is { } sha256 ? json.Add("sha256", sha256) : json;
    }

    /// <summary>One file's entry, as index.json and incremental.json both record it.</summary>
    internal static JsonNode File(FileEntry f) => new JsonObj()
        .Add("path", f.RelativePath)
        .Add("kind", FixtureKinds.Name(f.Kind))
        .Add("id", JsonIds.Format(f.Id))
        .Add("shapes", f.ShapeCount)
        .Add("polygons", f.PolygonCount)
        .Add("bytes", f.Bytes)
        .Add("sha256", f.Sha256);
}
