using System.Numerics;
using System.Text.Json;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Json;

/// <summary>
/// What every reader takes out of a <see cref="JsonElement"/>: a missing or malformed field is a
/// <see cref="FormatException"/> naming the field.
/// </summary>
internal static class JsonFields
{
    public static JsonElement Prop(JsonElement e, string name) =>
        e.TryGetProperty(name, out var v) ? v : throw new FormatException($"missing field \"{name}\"");

    public static string Str(JsonElement e, string name) => Prop(e, name).GetString() ?? throw new FormatException($"\"{name}\" is null");
    public static int Int(JsonElement e, string name) => Prop(e, name).GetInt32();
    public static float Float(JsonElement e, string name) => Number(Prop(e, name));

    /// <summary>The writers put null where a float is NaN or infinite (JSON has no such numbers); it reads back as NaN.</summary>
    public static float Number(JsonElement e) => e.ValueKind == JsonValueKind.Null ? float.NaN : e.GetSingle();
    public static IEnumerable<JsonElement> Arr(JsonElement e, string name) => Prop(e, name).EnumerateArray();

    /// <summary>A "0x%08X" id field.</summary>
    public static uint Id(JsonElement e, string name) =>
        JsonIds.TryParse(Str(e, name), out var id) ? id : throw new FormatException($"{name} is not a hex id");

    public static Vector3 Vec(JsonElement e)
    {
        var a = e.EnumerateArray().Select(Number).ToArray();
        if (a.Length != 3) throw new FormatException("a vector needs 3 numbers");
        return new Vector3(a[0], a[1], a[2]);
    }

    public static Sphere Sphere(JsonElement e) => new(Vec(Prop(e, "center")), Float(e, "radius"));

    public static Quaternion Quat(JsonElement e) => new(Float(e, "x"), Float(e, "y"), Float(e, "z"), Float(e, "w"));

    /// <summary>A frame: {origin, orientation}.</summary>
    public static Frame FrameOf(JsonElement e) => new(Vec(Prop(e, "origin")), Quat(Prop(e, "orientation")));

    /// <summary>{normal, d}, or null (a degenerate polygon's plane).</summary>
    public static Plane? OptionalPlane(JsonElement e) =>
        e.ValueKind == JsonValueKind.Null ? null : new Plane(Vec(Prop(e, "normal")), Float(e, "d"));
}
