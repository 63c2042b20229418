using AcShadow.Analysis.Fitting;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Analysis.Chart.Models;

/// <summary>
/// Each retail BSP part as one solid oriented box: the tighter of the box along the part's own axes and the
/// box along the principal axes of its physics vertices (<see cref="PartBoxFit"/>), answered by true
/// distance with retail's ε and touching rules (<see cref="BoxSphereQuery"/>). Exact for a part that is a box.
/// </summary>
internal sealed class PartBoxesModel : IShapeModel
{
    public string Name => "part-boxes";
    public string Description => "each retail BSP part's oriented box (part axes or principal axes, the tighter), true sphere-box distance";

    public PreparedModel Prepare(ChartSubject subject) => FittedParts.Prepare(subject, Name, (vertices, _) =>
        PartBoxFit.Of(vertices) is { } box ? (new BoxSphereQuery(box), box, box.ToPolytope()) : null);
}
