using AcShadow.Analysis.Chart.Models;

namespace AcShadow.Analysis.Chart;

/// <summary>
/// Every probe one object is asked about, in order: the grid around everything any model sees, the
/// doorway lines across the reference's footprint, then the stability probes on the reference's
/// geometry and on every model's fitted solids (<see cref="StabilityProbes"/>). The chart and the scene compiler lay them the same way.
/// </summary>
internal sealed record ChartProbes(Probe[] Probes, float GridSpacing, Bounds Bounds, DoorwayProbes.Opening? Doorway, IReadOnlyList<string> Notes)
{
    public static ChartProbes Lay(PreparedModel reference, IReadOnlyList<PreparedModel> models, ChartOptions options)
    {
        var everything = ShapeBounds.Of(models.SelectMany(p => p.Shapes));
        // The reference's BSP parts, then every model's fitted solids (each once: the reference may be among the models).
        var surfaces = reference.Shapes.Where(s => s.Bsp is not null)
            .Concat(models.Where(m => !ReferenceEquals(m, reference)).SelectMany(m => m.Shapes).Where(s => s.Polytope is not null));
        var grid = ProbeGrid.Build(everything, options);
        var opening = DoorwayProbes.Find(ShapeBounds.Of(reference.Shapes));
        var stability = StabilityProbes.Lay(surfaces, options);
        var probes = grid.Probes.Concat(DoorwayProbes.Build(opening, options)).Concat(stability.Probes).ToArray();
        var notes = new List<string>();
        if (grid.Spacing != options.Spacing)
        {
            // Said with the size that forced it: a span of 1e38 m is a corrupt sphere or vertex, not a big object.
            var size = grid.Region.Size;
            notes.Add(FormattableString.Invariant($"{ChartDiagnosticCodes.GridCoarsened}: grid coarsened from {options.Spacing} m to {grid.Spacing:G6} m to stay under {options.MaxGridProbes} probes: the shapes span {size.X:G6} × {size.Y:G6} × {size.Z:G6} m"));
        }
        if (stability.SpacingFactor > 1f)
            notes.Add(FormattableString.Invariant($"{ChartDiagnosticCodes.StabilityCoarsened}: stability probes laid every {options.Spacing * stability.SpacingFactor:G6} m instead of {options.Spacing} m on faces and edges to stay under {options.MaxStabilityProbes} probes (a large object, one of very many polygons, or a part scaled far past any real object's size); every vertex, face centroid and splitting plane is still probed"));
        return new ChartProbes(probes, grid.Spacing, everything, opening, notes);
    }

    /// <summary>How many probes of a kind were laid.</summary>
    public static int Count(IReadOnlyList<Probe> probes, ProbeKind kind) => probes.Count(p => p.Kind == kind);
}
