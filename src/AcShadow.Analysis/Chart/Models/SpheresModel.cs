using AcShadow.Fixtures.Geometry;

namespace AcShadow.Analysis.Chart.Models;

/// <summary>The Setup's own primitives only: every CylSphere as a cylinder and every Sphere as a sphere, no BSP.</summary>
internal sealed class SpheresModel : IShapeModel
{
    public string Name => "spheres";
    public string Description => "every CylSphere (cylinder) and every Sphere (sphere) of the Setup, no BSP";

    public PreparedModel Prepare(ChartSubject subject) =>
        PreparedModel.Of(SetupPrimitives.Of(subject.Setup).AllPrimitives(subject.EntityScale), subject);
}
