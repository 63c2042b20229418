using System.Numerics;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart.Models;

/// <summary>
/// What the fitted models share: every retail BSP part, posed exactly as the retail model poses it (the
/// subject's pose and door state through <see cref="ChartSubject.Build"/>, so a fitted solid is never fitted
/// to a part the reference has moved), replaced by a solid fitted to its physics
/// vertices in part space and answered there (<see cref="PosedQuery"/>, so ε is in part units as for the
/// BSP). A part that nothing can be fitted to is left out with a diagnostic; objects without BSP parts get
/// nothing.
/// </summary>
internal static class FittedParts
{
    /// <summary><paramref name="fit"/> gives the part's solid (its query, and the box when it is one) from its vertices and its polygons' planes.</summary>
    public static PreparedModel Prepare(ChartSubject subject, string what,
        Func<IReadOnlyList<Vector3>, IReadOnlyList<Plane>, (ISphereOverlap Query, OrientedBox? Box, ConvexPolytope Polytope)?> fit)
    {
        var set = subject.Build(subject.Options(ShapePolicy.Retail));
        var parts = ObjectOverlapQuery.Create(set.Shapes.Where(s => s.CollisionType == CollisionType.Bsp), subject.Bsps);
        var queries = new List<ISphereOverlap>();
        var shapes = new List<PreparedShape>();
        var diagnostics = new List<Diagnostic>(parts.Diagnostics);
        foreach (var part in parts.Shapes)
        {
            var polygons = part.Bsp!.Polygons;
            var vertices = polygons.SelectMany(p => p.Vertices).Distinct().ToArray();
            var planes = polygons.Select(p => new Plane(p.Normal, p.D)).ToArray();
            if (fit(vertices, planes) is not { } solid)
            {
                diagnostics.Add(new Diagnostic(ModelDiagnosticCodes.UnfittablePart, $"{part.Name}: its {vertices.Length} physics vertices give no solid for {what} (all on a line or in a point, or a hull float rounding cannot settle); left out"));
                continue;
            }
            queries.Add(new PosedQuery(part.Pose, solid.Query));
            shapes.Add(part with { Bsp = null, Box = solid.Box, Polytope = solid.Polytope });
        }
        return new PreparedModel(new AnyOverlap(queries), shapes, diagnostics);
    }
}
