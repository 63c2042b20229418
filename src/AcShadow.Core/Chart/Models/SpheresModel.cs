using System.Numerics;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Chart.Models;

/// <summary>The Setup's own primitives only: every CylSphere as a cylinder and every Sphere as a sphere, no BSP.</summary>
public sealed class SpheresModel : IShapeModel
{
    public string Name => "spheres";
    public string Description => "every CylSphere (cylinder) and every Sphere (sphere) of the Setup, no BSP";

    public PreparedModel Prepare(ChartSubject subject)
    {
        var scale = subject.EntityScale;
        var shapes = new List<ShadowShape>();
        for (var i = 0; i < subject.Setup.CylSpheres.Count; i++)
        {
            var c = subject.Setup.CylSpheres[i];
            shapes.Add(new ShadowShape(ShapeSource.CylSphere, i, null, CollisionType.Cylinder, c.Origin * scale, Quaternion.Identity, scale, c.Radius * scale, c.Height * scale, null));
        }
        for (var i = 0; i < subject.Setup.Spheres.Count; i++)
        {
            var s = subject.Setup.Spheres[i];
            shapes.Add(new ShadowShape(ShapeSource.Sphere, i, null, CollisionType.Sphere, s.Center * scale, Quaternion.Identity, scale, s.Radius * scale, 0f, null));
        }
        return PreparedModel.Of(shapes, subject);
    }
}
