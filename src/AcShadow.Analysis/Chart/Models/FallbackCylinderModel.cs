using AcShadow.Fixtures.Geometry;

namespace AcShadow.Analysis.Chart.Models;

/// <summary>
/// What the buggy client registered: ONE cylinder, the Setup's Radius × Height standing at the entity origin
/// (<see cref="SetupPrimitives.FallbackCylinder"/>, the one definition audit, chart and view share). On the
/// sample door that is a 14 cm "soda can".
/// </summary>
internal sealed class FallbackCylinderModel : IShapeModel
{
    public string Name => "fallback-cylinder";
    public string Description => "one cylinder: the Setup's Radius x Height at the entity origin (the buggy client)";

    public PreparedModel Prepare(ChartSubject subject) =>
        PreparedModel.Of([SetupPrimitives.Of(subject.Setup).FallbackCylinder(subject.EntityScale)], subject);
}
