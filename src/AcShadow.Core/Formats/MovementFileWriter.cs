using System.Numerics;
using AcShadow.Core.Json;
using AcShadow.Core.Movement;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Movement;

namespace AcShadow.Core.Formats;

/// <summary>
/// Writes one object Setup's movement suite as the canonical acshadow.movement-case/1 file (docs/formats.md):
/// the object in each state (its pose and shapes, whose BSPs are the gfxobjs/ dumps beside it), the floor, the
/// mover, and every case with its reference frames. A frame that changes nothing but where the mover is (movement.md
/// §3.4) is written short, only <c>f</c>, <c>valid</c> and <c>end</c>: the rest of its state is the frame before's.
/// </summary>
public static class MovementFileWriter
{
    public const string ReferenceImplementation = "acshadow-retail/1";

    public static byte[] Write(GeneratedSuite generated) => CanonicalJsonWriter.WriteUtf8(ToJson(generated));

    public static JsonObj ToJson(GeneratedSuite generated)
    {
        ArgumentNullException.ThrowIfNull(generated);
        var suite = generated.Suite;
        var objectId = JsonIds.Format(suite.SetupId);
        var any = suite.Objects.Values.First();
        return new JsonObj()
            .Add("format", FileFormats.Movement.Format)
            .Add("setupId", objectId)
            .Add("reference", new JsonObj().Add("impl", ReferenceImplementation))
            .Add("floor", new JsonObj().Add("kind", "flat").Add("z", MovementSubject.FloorZ))
            .Add("object", new JsonObj()
                .Add("frame", Frame(any.Position, any.Rotation))
                .Add("scale", any.Scale)
                .Add("footprint", new JsonObj().Add("min", generated.Footprint.Min).Add("max", generated.Footprint.Max))
                .Add("states", JsonArr.Of(suite.Objects, s => State(s.Key, s.Value, generated))))
            .Add("mover", new JsonObj()
                .Add("setupId", JsonIds.Format(suite.MoverSetupId))
                .Add("scale", suite.Mover.Scale)
                .Add("spheres", JsonArr.Of(suite.Mover.Spheres, JsonShapes.Sphere))
                .Add("stepUpHeight", suite.Mover.StepUpHeight)
                .Add("stepDownHeight", suite.Mover.StepDownHeight)
                .Add("edgeSlide", suite.Mover.EdgeSlide))
            .Add("tolerance", new JsonObj().Add("position", 0.001f).Add("normal", 0.0001f).Add("planeD", 0.001f))
            .Add("cases", JsonArr.Of(suite.Cases, c => Case(c, objectId)));
    }

    private static JsonObj State(string name, MovementObject obj, GeneratedSuite generated) => new JsonObj()
        .Add("state", name)
        .Add("ethereal", obj.Ethereal)
        .Add("pose", ShadowFileWriter.Pose(generated.Poses[name]))
        .Add("shapes", JsonArr.Of(obj.Shapes, s => ShadowFileWriter.Shape(s, BspReference)));

    /// <summary>A BSP dump's path relative to the movement file (movement/ and gfxobjs/ are siblings).</summary>
    private static string BspReference(uint gfxObjId) => "../" + FileFormats.Bsp.PathFor(gfxObjId);

    private static JsonObj Frame(Vector3 origin, Quaternion rotation) =>
        new JsonObj().Add("origin", origin).Add("orientation", JsonShapes.Quaternion(rotation));

    private static JsonObj Case(MovementCase c, string objectId)
    {
        var walk = c.Walk;
        var startPlane = walk.StartContact ?? new FlatFloor(walk.FloorZ).Plane;
        return new JsonObj()
            .Add("id", c.Id)
            .Add("state", c.State)
            .Add("start", new JsonObj()
                .Add("origin", walk.Start)
                .Add("orientation", JsonShapes.Quaternion(Quaternion.Identity))
                .Add("transient", JsonArr.Of(["Contact", "OnWalkable"]))
                .Add("contactPlane", JsonShapes.Plane(startPlane)))
            .Add("intent", new JsonObj()
                .Add("kind", "walk")
                .Add("heading", c.Heading)
                .Add("velocity", walk.Velocity)
                .Add("quantum", walk.Quantum)
                .Add("frames", walk.Frames))
            .Add("gate", JsonShapes.Plane(c.Gate))
            .Add("expected", new JsonObj()
                .Add("frames", Frames(c.Expected, objectId))
                .Add("outcome", Outcome(c.Outcome)))
            .Add("stability", new JsonObj().Add("fragile", c.Fragile).Add("minMargin", Margin(c.MinMargin)));
    }

    private static JsonNode Margin(float margin) => float.IsPositiveInfinity(margin) ? JsonNull.Value : JsonNum.Of(margin);

    private static JsonArr Frames(IReadOnlyList<MovementFrame> frames, string objectId)
    {
        var arr = new JsonArr();
        MovementFrame? previous = null;
        for (var i = 0; i < frames.Count; i++)
        {
            var f = frames[i];
            var full = i == 0 || i == frames.Count - 1 || !ChangesNothing(f, previous!);
            arr.Add(full ? FullFrame(f, objectId) : new JsonObj().Add("f", f.Frame).Add("valid", f.Valid).Add("end", f.Position));
            previous = f;
        }
        return arr;
    }

    /// <summary>
    /// A frame whose state is the frame before's in everything but its position and validity: the same steps,
    /// contact state, sliding and collision normals, hit and events (a free walk, or a walker held against a face).
    /// </summary>
    private static bool ChangesNothing(MovementFrame f, MovementFrame previous) =>
        f.Steps == previous.Steps && f.Contact == previous.Contact && f.OnWalkable == previous.OnWalkable
        && f.ContactPlane == previous.ContactPlane && f.SlidingNormal == previous.SlidingNormal
        && f.CollisionNormal == previous.CollisionNormal && f.HitObject == previous.HitObject && f.Events.SequenceEqual(previous.Events);

    private static JsonObj FullFrame(MovementFrame f, string objectId) => new JsonObj()
        .Add("f", f.Frame)
        .Add("valid", f.Valid)
        .Add("steps", f.Steps)
        .Add("end", f.Position)
        .Add("contact", f.Contact)
        .Add("onWalkable", f.OnWalkable)
        .Add("contactPlane", f.ContactPlane is { } plane ? JsonShapes.Plane(plane) : JsonNull.Value)
        .Add("slidingNormal", Optional(f.SlidingNormal))
        .Add("collisionNormal", Optional(f.CollisionNormal))
        .Add("collideObjects", f.HitObject ? JsonArr.Of([objectId]) : new JsonArr())
        .Add("events", JsonArr.Of(f.Events));

    private static JsonNode Optional(Vector3? v) => v is { } value ? JsonArr.Of(value) : JsonNull.Value;

    private static JsonObj Outcome(MovementOutcome o) => new JsonObj()
        .Add("class", o.Class)
        .Add("crossedGate", o.CrossedGate)
        .Add("firstContactFrame", o.FirstContactFrame is { } f ? JsonNum.Of(f) : JsonNull.Value)
        .Add("progress", o.Progress)
        .Add("lateral", o.Lateral)
        .Add("dz", o.Dz);
}
