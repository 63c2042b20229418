using System.Text.Json;
using AcShadow.Fixtures.Cells;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Scenes;
using static AcShadow.Fixtures.Json.JsonFields;

namespace AcShadow.Fixtures.Formats;

/// <summary>
/// Reads an "acshadow.cell/1" file into a <see cref="CellFile"/>. Malformed input is a
/// <see cref="FormatException"/> naming the field.
/// </summary>
internal static class CellFileReader
{
    public static CellFile Read(string json)
    {
        using var doc = JsonDocument.Parse(json);
        var root = doc.RootElement;
        FormatCheck.Require(root, FileFormats.Cell, "cell file");
        var cellId = Id(root, "cellId");
        var physics = BspFileReader.ReadBody(Prop(root, "physics"), cellId, []);
        var portals = Arr(root, "portals").Select(p =>
        {
            var polygon = Prop(p, "polygon");
            return new CellPortalRecord(Int(p, "index"), (ushort)Int(p, "flags"), (ushort)Int(p, "polygonId"),
                Id(p, "otherCellId"), (ushort)Int(p, "otherPortalId"),
                Arr(polygon, "vertices").Select(Vec).ToArray(),
                OptionalPlane(Prop(polygon, "plane")));
        }).ToArray();
        var visible = Arr(root, "visibleCells").Select(v => JsonIds.TryParse(v.GetString(), out var id) ? id : throw new FormatException("visibleCells holds a value that is not a hex id")).ToArray();
        var objects = Arr(root, "objects").Select(o =>
        {
            var file = Prop(o, "file");
            return new PlacedObject(Int(o, "index"), Id(o, "id"), SceneObjectKinds.Parse(Str(o, "kind")),
                FrameOf(Prop(o, "landblockFrame")), FrameOf(Prop(o, "worldFrame")),
                file.ValueKind == JsonValueKind.Null ? null : file.GetString(),
                o.TryGetProperty("shapes", out var s) ? s.EnumerateArray().Select(ShadowFileReader.ReadShape).ToArray() : []);
        }).ToArray();
        return new CellFile(cellId, Id(root, "environmentId"), Int(root, "cellStructure"), (uint)Prop(root, "flags").GetInt64(),
            Prop(root, "seenOutside").GetBoolean(),
            FrameOf(Prop(root, "landblockFrame")), FrameOf(Prop(root, "worldFrame")), physics, portals, visible, objects);
    }
}
