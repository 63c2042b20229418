using System.Numerics;
using System.Text.Json;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart.Models;

/// <summary>
/// The Setup's own collision primitives: its CylSpheres, Spheres and Radius × Height. The models that use
/// no BSP (<see cref="SpheresModel"/>, <see cref="FallbackCylinderModel"/>) are built from these alone, so
/// they come out the same from a dat's Setup and from the facts block of a shadow file.
/// </summary>
public sealed record SetupPrimitives(IReadOnlyList<CylSphere> CylSpheres, IReadOnlyList<Sphere> Spheres, float Radius, float Height)
{
    public static SetupPrimitives Of(Setup setup) => new(setup.CylSpheres, setup.Spheres, setup.Radius, setup.Height);

    /// <summary>The "setup" block of an acshadow.shadow/1 file (docs/formats.md), which records these facts as the dat holds them.</summary>
    public static SetupPrimitives FromShadowFile(JsonElement root)
    {
        var setup = Member(root, "setup");
        var cyls = Member(setup, "cylSpheres").EnumerateArray()
            .Select(c => new CylSphere(Vec(Member(c, "origin")), Num(Member(c, "radius")), Num(Member(c, "height")))).ToArray();
        var spheres = Member(setup, "spheres").EnumerateArray()
            .Select(s => new Sphere(Vec(Member(s, "center")), Num(Member(s, "radius")))).ToArray();
        return new SetupPrimitives(cyls, spheres, Num(Member(setup, "radius")), Num(Member(setup, "height")));
    }

    /// <summary>Every CylSphere as a cylinder and every Sphere as a sphere, scaled by the entity scale.</summary>
    public IReadOnlyList<ShadowShape> AllPrimitives(float scale)
    {
        var shapes = new List<ShadowShape>();
        for (var i = 0; i < CylSpheres.Count; i++)
        {
            var c = CylSpheres[i];
            shapes.Add(new ShadowShape(ShapeSource.CylSphere, i, null, CollisionType.Cylinder, c.Origin * scale, Quaternion.Identity, scale, c.Radius * scale, c.Height * scale, null));
        }
        for (var i = 0; i < Spheres.Count; i++)
        {
            var s = Spheres[i];
            shapes.Add(new ShadowShape(ShapeSource.Sphere, i, null, CollisionType.Sphere, s.Center * scale, Quaternion.Identity, scale, s.Radius * scale, 0f, null));
        }
        return shapes;
    }

    /// <summary>
    /// The one cylinder the buggy client registered, acshadow's single definition of it (audit's coverage, chart,
    /// view and the movement chart all use this): the Setup's Radius × Height, standing at the entity origin,
    /// reported as the Setup's sphere −1. Retail has no such shape; it is the seed design's fallback, whatever
    /// CylSpheres or Spheres the Setup has. On the sample door that is 0.141 m × 0.2 m, the "soda can".
    /// </summary>
    public ShadowShape FallbackCylinder(float scale) =>
        new(ShapeSource.Sphere, -1, null, CollisionType.Cylinder, Vector3.Zero, Quaternion.Identity, scale, Radius * scale, Height * scale, null);

    private static JsonElement Member(JsonElement e, string name) =>
        e.ValueKind == JsonValueKind.Object && e.TryGetProperty(name, out var v) ? v : throw new FormatException($"missing \"{name}\"");

    /// <summary>A number; <c>null</c> is how a shadow file writes a non-finite value (JSON has no NaN), read back as NaN.</summary>
    private static float Num(JsonElement e) => e.ValueKind switch
    {
        JsonValueKind.Number => e.GetSingle(),
        JsonValueKind.Null => float.NaN,
        _ => throw new FormatException("a number was expected"),
    };

    private static Vector3 Vec(JsonElement e)
    {
        if (e.ValueKind != JsonValueKind.Array || e.GetArrayLength() != 3) throw new FormatException("a vector [x, y, z] was expected");
        return new Vector3(Num(e[0]), Num(e[1]), Num(e[2]));
    }
}
