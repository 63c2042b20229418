using AcShadow.Fixtures.Geometry;

namespace AcShadow.Analysis.Chart.Models;

/// <summary>
/// What the buggy client registered: ONE cylinder — the first CylSphere; else the first Sphere as
/// a cylinder of height 2r based at the sphere's centre (as the seed's builder places it); else the Setup's
/// Radius × Height standing at the entity origin. On a door that is a 14 cm "soda can".
/// </summary>
internal sealed class FallbackCylinderModel : IShapeModel
{
    public string Name => "fallback-cylinder";
    public string Description => "one cylinder: the first CylSphere, else the first Sphere (h = 2r), else Setup Radius x Height at the origin (the buggy client)";

    public PreparedModel Prepare(ChartSubject subject) =>
        PreparedModel.Of([SetupPrimitives.Of(subject.Setup).FallbackCylinder(subject.EntityScale)], subject);
}
