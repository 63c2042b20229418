namespace AcShadow.Analysis.Doctor;

/// <summary>
/// One claim checked on the user's dat, and what was found: counts, the first ids that break it, and
/// for some checks a histogram or measured figures. Holds ids, counts, hashes and verdicts only: never
/// geometry, names or bytes of the dat.
/// </summary>
/// <param name="Key">Stable name tooling compares by, e.g. "bsp.planes".</param>
/// <param name="Section">"reading", "retail" or "tool".</param>
/// <param name="Claim">What the check tests, in one sentence (fixed text).</param>
/// <param name="Headline">The summary line's figures, e.g. "1210/1210 planes reproduced".</param>
/// <param name="Counts">Named counts, in a fixed order.</param>
/// <param name="Examples">The smallest ids of objects that break the claim (up to <see cref="Finding.MaxExamples"/>).</param>
/// <param name="ExampleKind">What the example ids are: "gfxobj", "setup", "landblockinfo", "node", "object".</param>
public sealed record DoctorCheck(
    string Key,
    string Section,
    string Claim,
    DoctorVerdict Verdict,
    string Headline,
    IReadOnlyList<KeyValuePair<string, long>> Counts,
    IReadOnlyList<uint> Examples,
    string ExampleKind)
{
    /// <summary>Named buckets (a ULP histogram, counts by hook type, failures by reason), when the check has them.</summary>
    public IReadOnlyList<KeyValuePair<string, long>>? Histogram { get; init; }

    /// <summary>What the histogram counts, e.g. "ulpDistance".</summary>
    public string? HistogramName { get; init; }

    /// <summary>Figures measured on this machine (seconds, MiB): they vary run to run, unlike everything else.</summary>
    public IReadOnlyList<KeyValuePair<string, double>>? Measured { get; init; }

    /// <summary>Hex digests (SHA-256) the check compares.</summary>
    public IReadOnlyList<KeyValuePair<string, string>>? Digests { get; init; }
}
