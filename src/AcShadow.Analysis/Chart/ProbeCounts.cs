using System.Globalization;

namespace AcShadow.Analysis.Chart;

/// <summary>How many probes were checked, in all and of each kind (grid, doorway, then the stability kinds).</summary>
public sealed record ProbeCounts(int Total, IReadOnlyList<(ProbeKind Kind, int Count)> ByKind)
{
    /// <summary>Every kind, in the order reports list them.</summary>
    public static IReadOnlyList<ProbeKind> Kinds { get; } = [ProbeKind.Grid, ProbeKind.Doorway, .. ProbeKinds.Stability];

    public static ProbeCounts Of(IEnumerable<Probe> probes)
    {
        var counts = new int[Kinds.Count];
        var total = 0;
        foreach (var p in probes)
        {
            total++;
            counts[(int)p.Kind]++;
        }
        return new ProbeCounts(total, [.. Kinds.Select(k => (k, counts[(int)k]))]);
    }

    public int Of(ProbeKind kind) => ByKind.First(k => k.Kind == kind).Count;

    /// <summary>"278506 grid, 333 doorway, 414960 face, …": every kind with its count.</summary>
    public override string ToString() =>
        string.Join(", ", ByKind.Select(k => string.Create(CultureInfo.InvariantCulture, $"{k.Count} {ProbeKinds.Name(k.Kind)}")));
}
