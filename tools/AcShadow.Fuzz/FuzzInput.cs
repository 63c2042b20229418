namespace AcShadow.Fuzz;

/// <summary>
/// One case's dats (the portal dat and the cell dat its landblock scene reads), what was done to them,
/// which Setup `dump` is asked for and which landblock (0xXXYY) `batch` exports; <see cref="From"/> is the
/// intact base it was made from (null for a reproducer loaded from disk).
/// </summary>
public sealed record FuzzInput(byte[] Portal, byte[] Cell, uint DumpSetup, uint Landblock, string Description)
{
    public FuzzBase? From { get; init; }

    /// <summary>`--policy` for both commands: retail or union.</summary>
    public string Policy { get; init; } = "retail";

    /// <summary>`--format` for both commands: canonical, acdream or both.</summary>
    public string Format { get; init; } = "canonical";
}
