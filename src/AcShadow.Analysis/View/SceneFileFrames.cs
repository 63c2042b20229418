using System.Numerics;
using System.Text.Json;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Analysis.View;

/// <summary>
/// Each object's landblock-relative frame from a scene file (its <c>landblockFrame</c>), by object index. A
/// view places objects relative to the landblock's corner: the world origin read back as float32 would cost
/// millimetres at world coordinates of 30 km.
/// </summary>
public static class SceneFileFrames
{
    public static IReadOnlyDictionary<int, Frame> Read(string sceneJson)
    {
        using var doc = JsonDocument.Parse(sceneJson);
        var frames = new Dictionary<int, Frame>();
        foreach (var o in doc.RootElement.GetProperty("objects").EnumerateArray())
        {
            var frame = o.GetProperty("landblockFrame");
            var origin = frame.GetProperty("origin");
            var q = frame.GetProperty("orientation");
            frames[o.GetProperty("index").GetInt32()] = new Frame(
                new Vector3(Number(origin[0]), Number(origin[1]), Number(origin[2])),
                new Quaternion(Number(q.GetProperty("x")), Number(q.GetProperty("y")), Number(q.GetProperty("z")), Number(q.GetProperty("w"))));
        }
        return frames;
    }

    /// <summary>A number; <c>null</c> is how acshadow writes a non-finite one (JSON has no NaN), read back as NaN for the view to leave out with a warning.</summary>
    private static float Number(JsonElement e) => e.ValueKind == JsonValueKind.Null ? float.NaN : e.GetSingle();
}
