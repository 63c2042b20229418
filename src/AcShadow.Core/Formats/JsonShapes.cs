using System.Numerics;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Core.Formats;

/// <summary>The small value objects every format shares: quaternions, planes, spheres.</summary>
public static class JsonShapes
{
    public static JsonObj Quaternion(Quaternion q) =>
        new JsonObj().Add("w", q.W).Add("x", q.X).Add("y", q.Y).Add("z", q.Z);

    public static JsonObj Plane(Plane p) => new JsonObj().Add("normal", p.Normal).Add("d", p.D);

    public static JsonObj Sphere(Sphere s) => new JsonObj().Add("center", s.Center).Add("radius", s.Radius);
}
