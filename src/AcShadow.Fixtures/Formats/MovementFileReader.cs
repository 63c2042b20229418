using System.Numerics;
using System.Text.Json;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Movement;
using static AcShadow.Fixtures.Json.JsonFields;

namespace AcShadow.Fixtures.Formats;

/// <summary>
/// Reads an acshadow.movement-case/1 file back into a <see cref="MovementSuite"/>: the object per state with the
/// BSPs its shapes name (from <c>bsp</c>, given a GfxObj id: the dumps in gfxobjs/ beside movement/), the mover
/// and the cases with their expected frames. A short frame is the frame before it at a new position (and validity).
/// </summary>
internal static class MovementFileReader
{
    public static MovementSuite Read(string json, Func<uint, BspDump?> bsp)
    {
        ArgumentNullException.ThrowIfNull(bsp);
        using var doc = JsonDocument.Parse(json);
        var root = doc.RootElement;
        FormatCheck.Require(root, FileFormats.Movement, "movement file");
        var floorZ = Float(Prop(root, "floor"), "z");
        var obj = Prop(root, "object");
        var frame = Prop(obj, "frame");
        var origin = Vec(Prop(frame, "origin"));
        var rotation = Quat(Prop(frame, "orientation"));
        var scale = Float(obj, "scale");
        var objects = new Dictionary<string, MovementObject>();
        foreach (var state in Arr(obj, "states"))
        {
            var shapes = Arr(state, "shapes").Select(ShadowFileReader.ReadShape).ToArray();
            var bsps = new Dictionary<uint, BspDump>();
            foreach (var id in shapes.Where(s => s.GfxObjId is not null).Select(s => s.GfxObjId!.Value).Distinct())
                if (bsp(id) is { } dump) bsps[id] = dump;
            objects[Str(state, "state")] = new MovementObject(shapes, bsps, origin, rotation, scale, Prop(state, "ethereal").GetBoolean());
        }
        var m = Prop(root, "mover");
        var mover = new Mover(Arr(m, "spheres").Select(Sphere).ToArray(), Float(m, "stepUpHeight"), Float(m, "stepDownHeight"), Float(m, "scale"))
        {
            EdgeSlide = Prop(m, "edgeSlide").GetBoolean(),
        };
        var cases = Arr(root, "cases").Select(c => ReadCase(c, floorZ)).ToArray();
        return new MovementSuite(Id(root, "setupId"), Id(m, "setupId"), mover, objects, cases);
    }

    private static MovementCase ReadCase(JsonElement c, float floorZ)
    {
        var start = Prop(c, "start");
        var intent = Prop(c, "intent");
        var walk = new Walk(Vec(Prop(start, "origin")), Vec(Prop(intent, "velocity")), floorZ, Int(intent, "frames"), Float(intent, "quantum"))
        {
            StartContact = Plane(Prop(start, "contactPlane")),
        };
        var expected = Prop(c, "expected");
        var frames = new List<MovementFrame>();
        foreach (var f in Arr(expected, "frames"))
            frames.Add(f.TryGetProperty("steps", out _) ? FullFrame(f) : ShortFrame(f, frames.Count > 0 ? frames[^1] : null));
        var o = Prop(expected, "outcome");
        var first = Prop(o, "firstContactFrame");
        var outcome = new MovementOutcome(Str(o, "class"), Prop(o, "crossedGate").GetBoolean(),
            first.ValueKind == JsonValueKind.Null ? null : first.GetInt32(), Float(o, "progress"), Float(o, "lateral"), Float(o, "dz"));
        var stability = Prop(c, "stability");
        var margin = Prop(stability, "minMargin");
        return new MovementCase(Str(c, "id"), Str(c, "state"), Float(intent, "heading"), walk, Plane(Prop(c, "gate")), frames, outcome,
            Prop(stability, "fragile").GetBoolean(), margin.ValueKind == JsonValueKind.Null ? float.PositiveInfinity : margin.GetSingle());
    }

    private static Plane Plane(JsonElement e) => OptionalPlane(e) ?? throw new FormatException("a plane is null");

    private static Vector3? OptionalVec(JsonElement e) => e.ValueKind == JsonValueKind.Null ? null : Vec(e);

    private static MovementFrame FullFrame(JsonElement f) => new(Int(f, "f"), Prop(f, "valid").GetBoolean(), Int(f, "steps"), Vec(Prop(f, "end")),
        Prop(f, "contact").GetBoolean(), Prop(f, "onWalkable").GetBoolean(), OptionalPlane(Prop(f, "contactPlane")),
        OptionalVec(Prop(f, "slidingNormal")), OptionalVec(Prop(f, "collisionNormal")), Prop(f, "collideObjects").GetArrayLength() > 0)
    {
        Events = [.. Arr(f, "events").Select(e => e.GetString() ?? throw new FormatException("an event is null"))],
    };

    private static MovementFrame ShortFrame(JsonElement f, MovementFrame? previous)
    {
        if (previous is null) throw new FormatException("the first frame of a case must be written in full");
        return previous with { Frame = Int(f, "f"), Valid = Prop(f, "valid").GetBoolean(), Position = Vec(Prop(f, "end")) };
    }
}
