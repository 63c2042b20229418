using System.Globalization;
using System.Numerics;
using System.Text.Json;

namespace AcShadow.Analysis.View;

/// <summary>
/// How glTF's numbers are spelled in the JSON chunk: each float in its shortest round-trip invariant form
/// ("0.9", "-0.965", "1E-05"), so a reader gets back the exact single-precision value and the same value
/// always gives the same bytes whatever the culture.
/// </summary>
internal static class GltfJson
{
    public static void WriteFloat(Utf8JsonWriter json, float value)
    {
        if (!float.IsFinite(value)) throw new ArgumentOutOfRangeException(nameof(value), value, "glTF numbers are finite.");
        json.WriteRawValue(value.ToString("R", CultureInfo.InvariantCulture));
    }

    public static void WriteFloat(Utf8JsonWriter json, string name, float value)
    {
        json.WritePropertyName(name);
        WriteFloat(json, value);
    }

    public static void WriteVector(Utf8JsonWriter json, string name, Vector3 v)
    {
        json.WriteStartArray(name);
        WriteFloat(json, v.X);
        WriteFloat(json, v.Y);
        WriteFloat(json, v.Z);
        json.WriteEndArray();
    }

    public static void WriteQuaternion(Utf8JsonWriter json, string name, Quaternion q)
    {
        json.WriteStartArray(name);
        WriteFloat(json, q.X);
        WriteFloat(json, q.Y);
        WriteFloat(json, q.Z);
        WriteFloat(json, q.W);
        json.WriteEndArray();
    }
}
