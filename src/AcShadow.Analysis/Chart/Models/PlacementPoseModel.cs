using AcShadow.Core.Poses;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart.Models;

/// <summary>
/// The retail shape family with every part at its placement frame (`--pose placement`), so the chart shows
/// what posing by the placement frame gets wrong where retail poses the parts by their animation frame
/// (a door's leaf, closed or open).
/// </summary>
internal sealed class PlacementPoseModel : IShapeModel
{
    public string Name => "placement-pose";
    public string Description => "retail rules with every part at its placement frame instead of the animation frame retail poses it by";

    public PreparedModel Prepare(ChartSubject subject)
    {
        var set = subject.Build(subject.Options(ShapePolicy.Retail) with { Pose = PosePolicy.Placement });
        return PreparedModel.Of(set.Shapes, subject, set.Diagnostics);
    }
}
