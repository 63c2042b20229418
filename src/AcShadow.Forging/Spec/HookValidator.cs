using System.Globalization;
using System.Numerics;
using System.Text.Json;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Json;

namespace AcShadow.Forging.Spec;

/// <summary>
/// Checks a <see cref="HookSpec"/> against its type's layout (<see cref="AnimationHookLayout.Fields"/>) and
/// writes its payload: every field given once, none unknown, each value of the field's kind and range.
/// </summary>
public static class HookValidator
{
    public static AnimationHook Validate(HookSpec? h, string at)
    {
        if (h is null) throw new SpecException($"{at}: is null; expected {{\"type\", \"direction\", \"fields\"}}");
        if (h.Type is null || h.Type.Length == 0 || char.IsDigit(h.Type[0]) || h.Type[0] == '-'
            || !Enum.TryParse<AnimationHookType>(h.Type, ignoreCase: true, out var type) || !AnimationHookLayout.IsKnown(type))
            throw new SpecException($"{at}: hook type \"{h.Type}\" is not one of {string.Join(", ", Enum.GetNames<AnimationHookType>())}");
        var direction = h.Direction switch
        {
            null => 1,
            _ when h.Direction.Equals("Forward", StringComparison.OrdinalIgnoreCase) => 1,
            _ when h.Direction.Equals("Backward", StringComparison.OrdinalIgnoreCase) => -1,
            _ when h.Direction.Equals("Both", StringComparison.OrdinalIgnoreCase) => 0,
            _ => throw new SpecException($"{at}: direction \"{h.Direction}\" is not Forward, Backward or Both"),
        };

        var layout = AnimationHookLayout.Fields(type);
        var given = h.Fields ?? new Dictionary<string, JsonElement>();
        foreach (var name in given.Keys)
            if (!layout.Any(f => f.Name == name))
                throw new SpecException($"{at}: {type} has no field \"{name}\"; its fields are {Names(layout)}");
        var w = new DatBinaryWriter();
        foreach (var field in layout)
        {
            if (!given.TryGetValue(field.Name, out var value))
                throw new SpecException($"{at}: {type} needs field \"{field.Name}\" (its fields are {Names(layout)})");
            Write(w, field, value, $"{at} {field.Name}");
        }
        return new AnimationHook(type, direction, w.ToArray());
    }

    private static string Names(IReadOnlyList<AnimationHookField> layout) =>
        layout.Count == 0 ? "none" : string.Join(", ", layout.Select(f => f.Name));

    private static void Write(DatBinaryWriter w, AnimationHookField field, JsonElement value, string at)
    {
        switch (field.Kind)
        {
            case AnimationHookFieldKind.UInt32: w.WriteUInt32((uint)Whole(value, uint.MaxValue, at)); break;
            case AnimationHookFieldKind.UInt16: w.WriteUInt16((ushort)Whole(value, ushort.MaxValue, at)); break;
            case AnimationHookFieldKind.DataId: w.WriteUInt32(HexId(value, at)); break;
            case AnimationHookFieldKind.Bool32:
                if (value.ValueKind is not (JsonValueKind.True or JsonValueKind.False)) throw new SpecException($"{at}: expected true or false");
                w.WriteUInt32(value.GetBoolean() ? 1u : 0u);
                break;
            case AnimationHookFieldKind.Float: w.WriteSingle(Number(value, at)); break;
            case AnimationHookFieldKind.PackedGfxObjId:
                var id = HexId(value, at);
                if (!DatObjectKind.GfxObj.Contains(id)) throw new SpecException($"{at}: 0x{id:X8} is outside the GfxObj range {DatObjectKind.GfxObj.RangeText()}");
                w.WritePackedDataId(id, AnimationHookField.GfxObjBase);
                break;
            case AnimationHookFieldKind.Vector3: w.WriteVector3(Vector(value, at)); break;
            case AnimationHookFieldKind.Frame: w.WriteFrame(Frame(value, at)); break;
            default: throw new ArgumentOutOfRangeException(nameof(field), field.Kind, null);
        }
    }

    private static long Whole(JsonElement value, long max, string at)
    {
        if (value.ValueKind != JsonValueKind.Number || !value.TryGetInt64(out var n) || n < 0 || n > max)
            throw new SpecException($"{at}: expected a whole number from 0 to {max}");
        return n;
    }

    private static uint HexId(JsonElement value, string at)
    {
        var text = value.ValueKind == JsonValueKind.String ? value.GetString() : null;
        if (text is null || !text.StartsWith("0x", StringComparison.OrdinalIgnoreCase) || !JsonIds.TryParse(text, out var id))
            throw new SpecException($"{at}: expected a hex id like \"0x01000456\"");
        return id;
    }

    private static float Number(JsonElement value, string at)
    {
        if (value.ValueKind != JsonValueKind.Number || !value.TryGetDouble(out var d) || !float.IsFinite((float)d))
            throw new SpecException($"{at}: expected a finite float32 number");
        return (float)d;
    }

    private static Vector3 Vector(JsonElement value, string at)
    {
        if (value.ValueKind != JsonValueKind.Array || value.GetArrayLength() != 3) throw new SpecException($"{at}: expected [x, y, z]");
        return new Vector3(Number(value[0], $"{at} x"), Number(value[1], $"{at} y"), Number(value[2], $"{at} z"));
    }

    /// <summary>{"origin": [x, y, z], "orientation": {"w", "x", "y", "z"}}, both required and the quaternion unit.</summary>
    private static Frame Frame(JsonElement value, string at)
    {
        if (value.ValueKind != JsonValueKind.Object || !value.TryGetProperty("origin", out var origin) || !value.TryGetProperty("orientation", out var q)
            || value.EnumerateObject().Count() != 2)
            throw new SpecException($"{at}: expected {{\"origin\": [x, y, z], \"orientation\": {{\"w\", \"x\", \"y\", \"z\"}}}}");
        if (q.ValueKind != JsonValueKind.Object || q.EnumerateObject().Count() != 4
            || !q.TryGetProperty("w", out var qw) || !q.TryGetProperty("x", out var qx) || !q.TryGetProperty("y", out var qy) || !q.TryGetProperty("z", out var qz))
            throw new SpecException($"{at} orientation: expected {{\"w\", \"x\", \"y\", \"z\"}}");
        var rotation = new Quaternion(Number(qx, $"{at} orientation x"), Number(qy, $"{at} orientation y"), Number(qz, $"{at} orientation z"), Number(qw, $"{at} orientation w"));
        var length = rotation.Length();
        if (Math.Abs(length - 1) > SpecValidator.UnitTolerance)
            throw new SpecException($"{at} orientation: quaternion length is {length.ToString("0.######", CultureInfo.InvariantCulture)}, not 1; normalize it");
        return new Frame(Vector(origin, $"{at} origin"), rotation);
    }
}
