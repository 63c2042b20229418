using System.Text.Json;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Scenes;

namespace AcShadow.Fixtures.Cells;

/// <summary>
/// Reads an "acshadow.cell/1" file into a <see cref="CellFile"/>. Malformed input is a
/// <see cref="FormatException"/> naming the field.
/// </summary>
public static class CellFileReader
{
    public static CellFile Read(string json)
    {
        using var doc = JsonDocument.Parse(json);
        var root = doc.RootElement;
        FormatCheck.Require(root, CellFileFormat.Format, "cell file");
        var cellId = Id(root, "cellId");
        var frame = BspFileReader.Prop(root, "landblockFrame");
        var world = BspFileReader.Prop(root, "worldFrame");
        var physics = BspFileReader.ReadBody(BspFileReader.Prop(root, "physics"), cellId, []);
        var portals = BspFileReader.Arr(root, "portals").Select(p =>
        {
            var polygon = BspFileReader.Prop(p, "polygon");
            var plane = BspFileReader.Prop(polygon, "plane");
            return new CellPortalRecord(BspFileReader.Int(p, "index"), (ushort)BspFileReader.Int(p, "flags"), (ushort)BspFileReader.Int(p, "polygonId"),
                Id(p, "otherCellId"), (ushort)BspFileReader.Int(p, "otherPortalId"),
                BspFileReader.Arr(polygon, "vertices").Select(BspFileReader.Vec).ToArray(),
                plane.ValueKind == JsonValueKind.Null ? null : new System.Numerics.Plane(BspFileReader.Vec(BspFileReader.Prop(plane, "normal")), BspFileReader.Float(plane, "d")));
        }).ToArray();
        var visible = BspFileReader.Arr(root, "visibleCells").Select(v => JsonIds.TryParse(v.GetString(), out var id) ? id : throw new FormatException("visibleCells holds a value that is not a hex id")).ToArray();
        var objects = BspFileReader.Arr(root, "objects").Select(o =>
        {
            var landblock = BspFileReader.Prop(o, "landblockFrame");
            var file = BspFileReader.Prop(o, "file");
            return new CellObject(BspFileReader.Int(o, "index"), Id(o, "id"), SceneObjectKinds.Parse(BspFileReader.Str(o, "kind")),
                BspFileReader.Vec(BspFileReader.Prop(landblock, "origin")), BspFileReader.Quat(BspFileReader.Prop(landblock, "orientation")),
                BspFileReader.Vec(BspFileReader.Prop(BspFileReader.Prop(o, "worldFrame"), "origin")),
                file.ValueKind == JsonValueKind.Null ? null : file.GetString(),
                o.TryGetProperty("shapes", out var s) ? s.EnumerateArray().Select(ShadowFileReader.ReadShape).ToArray() : []);
        }).ToArray();
        return new CellFile(cellId, Id(root, "environmentId"), BspFileReader.Int(root, "cellStructure"), (uint)BspFileReader.Prop(root, "flags").GetInt64(),
            BspFileReader.Prop(root, "seenOutside").GetBoolean(),
            BspFileReader.Vec(BspFileReader.Prop(frame, "origin")), BspFileReader.Quat(BspFileReader.Prop(frame, "orientation")),
            BspFileReader.Vec(BspFileReader.Prop(world, "origin")), physics, portals, visible, objects);
    }

    private static uint Id(JsonElement e, string name) =>
        JsonIds.TryParse(BspFileReader.Str(e, name), out var id) ? id : throw new FormatException($"{name} is not a hex id");
}
