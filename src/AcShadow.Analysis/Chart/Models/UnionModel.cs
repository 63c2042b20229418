using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart.Models;

/// <summary>
/// The seed design's shape set (ShadowShapeBuilder, Union policy: every CylSphere, Spheres as 2r-tall
/// cylinders when there are no CylSpheres, and every part's BSP), BSP parts answered by the retail tree query.
/// </summary>
internal sealed class UnionModel : IShapeModel
{
    public string Name => "union";
    public string Description => "the seed design: all CylSpheres, Spheres as cylinders (h = 2r) when no CylSpheres, and all BSP parts";

    public PreparedModel Prepare(ChartSubject subject)
    {
        var set = subject.Build(subject.Options(ShapePolicy.Union));
        return PreparedModel.Of(set.Shapes, subject, set.Diagnostics);
    }
}
