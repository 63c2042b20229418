using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart.Models;

/// <summary>
/// The reference: the retail shape family (ShadowShapeBuilder, Retail policy: parts' BSPs if any part has
/// one, else CylSpheres, else Spheres) with each BSP part answered by the retail tree query.
/// </summary>
internal sealed class RetailModel : IShapeModel
{
    public string Name => "retail";
    public string Description => "retail rules: every posed part's PhysicsBSP if any part has one, else CylSpheres, else Spheres (the reference)";

    public PreparedModel Prepare(ChartSubject subject)
    {
        var set = subject.Build(subject.Options(ShapePolicy.Retail));
        return PreparedModel.Of(set.Shapes, subject, set.Diagnostics);
    }
}
