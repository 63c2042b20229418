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
    public static float Number(JsonElement e) => e.ValueKind switch
    {
        JsonValueKind.Null => float.NaN,
        JsonValueKind.Number => e.GetSingle(),
        _ => throw new FormatException($"a number is expected, not {Kind(e)}"),
    };

    /// <summary>How a JSON value that is not what was expected is named in a message: "null", "a string", ...</summary>
    public static string Kind(JsonElement e) => e.ValueKind switch
    {
        JsonValueKind.Null => "null",
        JsonValueKind.String => "a string",
        JsonValueKind.Object => "an object",
        JsonValueKind.Array => "an array",
        JsonValueKind.True or JsonValueKind.False => "true or false",
        _ => "a number",
    };
    public static IEnumerable<JsonElement> Arr(JsonElement e, string name) => Prop(e, name).EnumerateArray();

    /// <summary>A "0x%08X" id field.</summary>
    public static uint Id(JsonElement e, string name) =>
        JsonIds.TryParse(Str(e, name), out var id) ? id : throw new FormatException($"{name} is not a hex id");

    public static Vector3 Vec(JsonElement e)
    {
        if (e.ValueKind != JsonValueKind.Array) throw new FormatException($"a vector is an array of 3 numbers, not {Kind(e)}");
        var a = e.EnumerateArray().Select(Number).ToArray();
        if (a.Length != 3) throw new FormatException("a vector needs 3 numbers");
        return new Vector3(a[0], a[1], a[2]);
    }

    public static Sphere Sphere(JsonElement e) => new(Vec(Prop(e, "center")), Float(e, "radius"));

    public static Quaternion Quat(JsonElement e) =>
        e.ValueKind == JsonValueKind.Object
            ? new(Float(e, "x"), Float(e, "y"), Float(e, "z"), Float(e, "w"))
            : throw new FormatException($"a quaternion is an object {{x, y, z, w}}, not {Kind(e)}");

    /// <summary>
    /// A rotation: a quaternion of length 1 (within 0.001, what float writing keeps). A zero quaternion rotates
    /// nothing into nowhere, so a file that holds one is refused here rather than drawn or queried.
    /// </summary>
    public static Quaternion Rotation(JsonElement e, string what)
    {
        var q = Quat(e);
        var length = q.Length();
        if (!float.IsFinite(length) || MathF.Abs(length - 1f) > 1e-3f)
            throw new FormatException($"{what} must be a unit quaternion (length 1), not one of length {length.ToString(System.Globalization.CultureInfo.InvariantCulture)}");
        return q;
    }

    /// <summary>A frame: {origin, orientation}.</summary>
    public static Frame FrameOf(JsonElement e) => new(Vec(Prop(e, "origin")), Quat(Prop(e, "orientation")));

    /// <summary>{normal, d}, or null (a degenerate polygon's plane).</summary>
    public static Plane? OptionalPlane(JsonElement e) =>
        e.ValueKind == JsonValueKind.Null ? null : new Plane(Vec(Prop(e, "normal")), Float(e, "d"));
}
