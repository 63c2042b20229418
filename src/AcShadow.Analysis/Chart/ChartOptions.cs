using System.Globalization;

namespace AcShadow.Analysis.Chart;

/// <summary>
/// How the chart probes and measures. The defaults are sized for a human player: a query sphere of
/// radius 0.5 m (retail player spheres are about 0.48 m), a grid every 0.25 m, the map slice at walking
/// height (the centre of a sphere standing on z = 0, i.e. z = probe radius).
/// </summary>
public sealed record ChartOptions
{
    public const float DefaultProbeRadius = 0.5f;
    public const float DefaultSpacing = 0.25f;

    /// <summary>Radius of every query sphere (metres).</summary>
    public float ProbeRadius { get; init; } = DefaultProbeRadius;

    /// <summary>Distance between grid probes along each axis (metres).</summary>
    public float Spacing { get; init; } = DefaultSpacing;

    /// <summary>How far the grid reaches past the object's bounds; null = probe radius + spacing.</summary>
    public float? Margin { get; init; }

    /// <summary>Height of the failure-map slice and the doorway lines; null = probe radius.</summary>
    public float? WalkHeight { get; init; }

    /// <summary>Doorway lines: lateral offsets from the opening's centre, as fractions of its half-width.</summary>
    public IReadOnlyList<float> DoorwayOffsets { get; init; } = [-0.9f, -0.75f, -0.5f, -0.25f, 0f, 0.25f, 0.5f, 0.75f, 0.9f];

    /// <summary>Step between probes along a doorway line (metres).</summary>
    public float DoorwayStep { get; init; } = 0.05f;

    /// <summary>Grid probes at most; a larger grid is coarsened (spacing doubled until it fits) and says so.</summary>
    public int MaxGridProbes { get; init; } = 250_000;

    /// <summary>
    /// Stability probes at most per object, the grid's budget; past it they are laid on faces and edges at a
    /// coarser spacing (doubled until they fit) and a note says so, while every vertex, face centroid and
    /// splitting plane is still probed. On the scale dat, 100 random Setups laid 16.7 million probes at the old
    /// budget of 2,000,000, four-fifths of them points on faces, 1.0-1.5 million for each of the six largest
    /// (50-100 m halls): broad walls, where a model and retail part ways at edges and vertices instead.
    /// </summary>
    public int MaxStabilityProbes { get; init; } = 250_000;

    /// <summary>False passes and, separately, false blocks listed per model and object, nearest the boundary first.</summary>
    public int FailuresPerModel { get; init; } = 10;

    /// <summary>Probes in the timed sample (evenly strided over all probes).</summary>
    public int TimingProbes { get; init; } = 4096;

    /// <summary>Untimed passes over the sample before measuring (JIT, caches).</summary>
    public int WarmupPasses { get; init; } = 3;

    /// <summary>Timed passes; the median, p10 and p90 are over these.</summary>
    public int TimingBatches { get; init; } = 31;

    /// <summary>Further mover radii the stability probes are placed for, besides <see cref="ProbeRadius"/> (metres).</summary>
    public IReadOnlyList<float> MoverRadii { get; init; } = [];

    /// <summary>How far short of and past each boundary a stability probe sits (metres): half of retail's ε.</summary>
    public float StabilityOffset { get; init; } = 1e-4f;

    /// <summary>
    /// The tie band (metres): how far from the client's answer acshadow's own arithmetic can put a point in a part's
    /// frame. Cells and parts move points bit for bit as the client does, but a placed object's part is reached in two
    /// steps (landblock to entity, entity to part) where the client takes one (the part's Frame::combine frame); the two
    /// differ by at most 1.1e-5 m (docs/chart.md, "Moving points between frames"). A boundary within this of a probe is a
    /// tie whose answer acshadow cannot promise, so <see cref="StabilityOffset"/> must be more than it.
    /// </summary>
    public const float FrameArithmeticTie = 2e-5f;

    /// <summary>Every mover radius probed: <see cref="ProbeRadius"/> first, then <see cref="MoverRadii"/> not already listed.</summary>
    public IReadOnlyList<float> Radii => [.. new[] { ProbeRadius }.Concat(MoverRadii).Distinct()];

    public float EffectiveMargin => Margin ?? ProbeRadius + Spacing;
    public float EffectiveWalkHeight => WalkHeight ?? ProbeRadius;

    /// <summary>The first problem with these options, or null.</summary>
    public string? Problem()
    {
        if (!float.IsFinite(ProbeRadius) || ProbeRadius <= 0f) return $"probe radius must be a positive number of metres, not {F(ProbeRadius)}";
        if (!float.IsFinite(Spacing) || Spacing < 0.01f) return $"spacing must be at least 0.01 m, not {F(Spacing)}";
        if (Margin is { } m && (!float.IsFinite(m) || m < 0f)) return $"margin must be zero or more metres, not {F(m)}";
        if (WalkHeight is { } w && !float.IsFinite(w)) return $"walking height must be a number of metres, not {F(w)}";
        foreach (var r in MoverRadii)
            if (!(float.IsFinite(r) && r > 0f)) return $"mover radius must be a positive number of metres, not {F(r)}";
        if (!float.IsFinite(StabilityOffset) || StabilityOffset <= FrameArithmeticTie)
            return $"stability offset must be more than {F(FrameArithmeticTie)} m (the tie band of frame arithmetic, docs/chart.md), not {F(StabilityOffset)}";
        if (!float.IsFinite(DoorwayStep) || DoorwayStep < 0.005f) return $"doorway step must be at least 0.005 m, not {F(DoorwayStep)}";
        if (DoorwayOffsets.Any(o => !float.IsFinite(o))) return "doorway offsets must be numbers";
        if (MaxGridProbes < 1 || MaxStabilityProbes < 1 || TimingProbes < 1 || TimingBatches < 1 || WarmupPasses < 0 || FailuresPerModel < 0) return "probe, timing and failure counts must be positive";
        return null;
    }

    private static string F(float v) => v.ToString(CultureInfo.InvariantCulture);
}
