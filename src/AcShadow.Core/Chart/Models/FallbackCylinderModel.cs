using System.Numerics;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Chart.Models;

/// <summary>
/// What the buggy client registered: ONE cylinder — the first CylSphere; else the first Sphere as
/// a cylinder of height 2r based at the sphere's centre (as the seed's builder places it); else the Setup's
/// Radius × Height standing at the entity origin. On a door that is a 14 cm "soda can".
/// </summary>
public sealed class FallbackCylinderModel : IShapeModel
{
    public string Name => "fallback-cylinder";
    public string Description => "one cylinder: the first CylSphere, else the first Sphere (h = 2r), else Setup Radius x Height at the origin (the buggy client)";

    public PreparedModel Prepare(ChartSubject subject)
    {
        var setup = subject.Setup;
        var scale = subject.EntityScale;
        ShadowShape shape;
        if (setup.CylSpheres.Count > 0)
        {
            var c = setup.CylSpheres[0];
            shape = new ShadowShape(ShapeSource.CylSphere, 0, null, CollisionType.Cylinder, c.Origin * scale, Quaternion.Identity, scale, c.Radius * scale, c.Height * scale, null);
        }
        else if (setup.Spheres.Count > 0)
        {
            var s = setup.Spheres[0];
            shape = new ShadowShape(ShapeSource.Sphere, 0, null, CollisionType.Cylinder, s.Center * scale, Quaternion.Identity, scale, s.Radius * scale, 2f * s.Radius * scale, null);
        }
        else
        {
            // Setup.Radius × Setup.Height has no source list of its own; it is reported as the Setup's sphere -1.
            shape = new ShadowShape(ShapeSource.Sphere, -1, null, CollisionType.Cylinder, Vector3.Zero, Quaternion.Identity, scale, setup.Radius * scale, setup.Height * scale, null);
        }
        return PreparedModel.Of([shape], subject);
    }
}
