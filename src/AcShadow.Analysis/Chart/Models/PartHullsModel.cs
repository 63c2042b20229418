using AcShadow.Analysis.Fitting;

namespace AcShadow.Analysis.Chart.Models;

/// <summary>
/// Each retail BSP part as the solid convex hull of its physics vertices (<see cref="ConvexHullBuilder"/>),
/// answered by true distance with retail's ε and touching rules (<see cref="Fixtures.Collision.ConvexPolytope"/>).
/// Exact for a convex closed part.
/// </summary>
internal sealed class PartHullsModel : IShapeModel
{
    public string Name => "part-hulls";
    public string Description => "each retail BSP part's convex hull, true sphere-polytope distance";

    public PreparedModel Prepare(ChartSubject subject) => FittedParts.Prepare(subject, Name, (vertices, planes) =>
        ConvexHullBuilder.Build(vertices, planes) is { } hull ? (hull, null, hull) : null);
}
