using System.Text.Json;
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
using static AcShadow.Fixtures.Json.JsonPathFields;

namespace AcShadow.Core.Batch;

/// <summary>
/// Reads index.json back with everything verify needs to regenerate it: the fixtures library's parser of the
/// file, plus the dat identity, selection, formats and pose of <c>inputs</c>. Anything missing or malformed is a
/// <see cref="FormatException"/> naming the field.
/// </summary>
public static class BatchIndexReader
{
    public static BatchIndex Read(byte[] utf8)
    {
        JsonDocument doc;
        try
        {
            doc = JsonDocument.Parse(utf8);
        }
        catch (JsonException e)
        {
            throw new FormatException($"not JSON: {e.Message}");
        }
        using (doc)
        {
            try
            {
                return Read(doc.RootElement);
            }
            // JsonDocument.Parse checks structure only; a string holding bytes that are not UTF-8 fails when read.
            catch (InvalidOperationException e) when (e.InnerException is System.Text.DecoderFallbackException)
            {
                throw new FormatException($"a string is not UTF-8 text: {e.InnerException.Message}");
            }
        }
    }

    private static BatchIndex Read(JsonElement root)
    {
        var format = Str(root, "format", "$");
        if (format != FileFormats.Index.Format) throw new FormatException($"$.format is \"{format}\", expected \"{FileFormats.Index.Format}\"");
        var body = IndexFileReader.Read(root, static (inputs, policy, scale) =>
        {
            var cell = Member(inputs, "cellDat", "$.inputs");
            return new BatchInputs(
                Dat(Member(inputs, "dat", "$.inputs"), "$.inputs.dat"),
                cell.ValueKind == JsonValueKind.Null ? null : Dat(cell, "$.inputs.cellDat"),
                policy,
                scale,
                Selection(Member(inputs, "selection", "$.inputs"), "$.inputs.selection"))
            {
                Formats = Formats(inputs),
                Pose = Pose(inputs),
                DoorState = State(inputs),
                MotionTable = MotionTable(inputs),
                Movement = Movement(inputs),
            };
        });
        return new BatchIndex(body.Inputs, body.Files);
    }

    private static PosePolicy Pose(JsonElement inputs)
    {
        if (!inputs.TryGetProperty("pose", out var p)) return PosePolicy.Placement;
        var text = p.ValueKind == JsonValueKind.String ? p.GetString()! : "";
        return PoseNames.TryParse(text, out PosePolicy pose) ? pose : throw new FormatException($"$.inputs.pose \"{text}\" is not retail or placement");
    }

    private static DoorState State(JsonElement inputs)
    {
        if (!inputs.TryGetProperty("doorState", out var s)) return DoorState.Closed;
        var text = s.ValueKind == JsonValueKind.String ? s.GetString()! : "";
        return PoseNames.TryParse(text, out DoorState state) ? state : throw new FormatException($"$.inputs.doorState \"{text}\" is not closed or open");
    }

    private static MovementSelection? Movement(JsonElement inputs)
    {
        if (!inputs.TryGetProperty("movement", out var m)) return null;
        uint IdOf(JsonElement e, string where) => e.ValueKind == JsonValueKind.String && JsonIds.TryParse(e.GetString(), out var id) ? id
            : throw new FormatException($"{where} is not a hex id");
        if (m.ValueKind != JsonValueKind.Object || !m.TryGetProperty("setups", out var setups) || setups.ValueKind != JsonValueKind.Array || !m.TryGetProperty("mover", out var mover))
            throw new FormatException("$.inputs.movement needs setups (an array of ids) and mover");
        return new MovementSelection([.. setups.EnumerateArray().Select(e => IdOf(e, "$.inputs.movement.setups[]"))], IdOf(mover, "$.inputs.movement.mover"));
    }

    private static uint? MotionTable(JsonElement inputs)
    {
        if (!inputs.TryGetProperty("motionTable", out var m) || m.ValueKind == JsonValueKind.Null) return null;
        return m.ValueKind == JsonValueKind.String && JsonIds.TryParse(m.GetString(), out var id) ? id
            : throw new FormatException("$.inputs.motionTable is not a hex id");
    }

    private static OutputFormats Formats(JsonElement inputs)
    {
        if (!inputs.TryGetProperty("formats", out var f)) return OutputFormats.Canonical;
        var text = f.ValueKind == JsonValueKind.String ? f.GetString() : null;
        return OutputFormatNames.TryParse(text, out var formats) ? formats
            : throw new FormatException($"$.inputs.formats \"{text}\" is not canonical, acdream or both");
    }

    private static DatSourceInfo Dat(JsonElement e, string at)
    {
        var kindText = Str(e, "kind", at);
        if (!Enum.TryParse<DatFileKind>(kindText, out var kind)) throw new FormatException($"{at}.kind \"{kindText}\" is not a dat kind");
        // iterationSource is absent from indexes written before the Iteration record was read.
        var source = DatIterationSource.Directory;
        if (e.TryGetProperty("iterationSource", out var s) && !(s.ValueKind == JsonValueKind.String && DatIterationSources.TryParse(s.GetString(), out source)))
            throw new FormatException($"{at}.iterationSource is not record, directory or directory-record-unreadable");
        // sha256 is absent from indexes written before the dat's content was hashed.
        string? sha256 = null;
        if (e.TryGetProperty("sha256", out var h) && !(h.ValueKind == JsonValueKind.String && IsSha256(sha256 = h.GetString()!)))
            throw new FormatException($"{at}.sha256 is not a SHA-256 (64 lowercase hex digits)");
        return new DatSourceInfo(Str(e, "fileName", at), Num(e, "size", at), kind, (int)Num(e, "iteration", at), (int)Num(e, "blockSize", at)) { IterationSource = source, Sha256 = sha256 };
    }

    private static bool IsSha256(string text) => text.Length == 64 && text.All(c => char.IsAsciiDigit(c) || c is >= 'a' and <= 'f');

    private static BatchSelection Selection(JsonElement e, string at)
    {
        SetupList? list = null;
        var file = Member(e, "setupsFile", at);
        if (file.ValueKind != JsonValueKind.Null)
        {
            var ids = Member(file, "ids", at + ".setupsFile");
            if (ids.ValueKind != JsonValueKind.Array) throw new FormatException($"{at}.setupsFile.ids is not an array");
            list = new SetupList(Str(file, "name", at + ".setupsFile"), ids.EnumerateArray().Select((id, i) =>
                JsonIds.TryParse(id.ValueKind == JsonValueKind.String ? id.GetString() : null, out var v) ? v
                    : throw new FormatException($"{at}.setupsFile.ids[{i}] is not a hex id")).ToArray());
        }
        uint? landblock = null;
        var lb = Member(e, "landblock", at);
        if (lb.ValueKind != JsonValueKind.Null)
        {
            if (!LandblockIds.TryParse(lb.ValueKind == JsonValueKind.String ? lb.GetString() : null, out var id))
                throw new FormatException($"{at}.landblock is not a landblock id");
            landblock = id;
        }
        var cells = !e.TryGetProperty("cells", out var c) || c.ValueKind != JsonValueKind.False;
        return new BatchSelection(Bool(e, "doors", at), Bool(e, "all", at), list, landblock) { Cells = cells };
    }
}
