using System.Numerics;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart.Models;

/// <summary>A model made ready for one object: its query, the shapes it tests, and what it had to skip.</summary>
internal sealed record PreparedModel(ISphereOverlap Query, IReadOnlyList<PreparedShape> Shapes, IReadOnlyList<Diagnostic> Diagnostics)
{
    public bool Overlaps(Vector3 center, float radius) => Query.Overlaps(center, radius);

    /// <summary>The object query over a shape list, with the builder's and the query's diagnostics together.</summary>
    public static PreparedModel Of(IEnumerable<ShadowShape> shapes, ChartSubject subject, IEnumerable<Diagnostic>? buildDiagnostics = null)
    {
        var query = ObjectOverlapQuery.Create(shapes, subject.Bsps);
        return new PreparedModel(query, query.Shapes, [.. buildDiagnostics ?? [], .. query.Diagnostics]);
    }
}
