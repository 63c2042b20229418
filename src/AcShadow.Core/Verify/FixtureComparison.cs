namespace AcShadow.Core.Verify;

/// <summary>
/// A file whose bytes differ: the JSON differences (null when a side is not JSON), and, when the JSON values
/// are the same, why the bytes differ all the same (<see cref="Reason"/>).
/// </summary>
public sealed record ChangedFile(string Path, IReadOnlyList<JsonDifference>? Differences, bool OnlyLineEndings = false, string? Reason = null);

/// <summary>
/// How a fixtures folder compares with a fresh regeneration. Missing: regeneration writes it, the
/// folder lacks it. Extra: the folder has it, regeneration does not write it. Changed: both, different
/// bytes. Dat: how the dat differs from the one index.json recorded (empty when it is the same).
/// </summary>
public sealed record FixtureComparison(
    IReadOnlyList<string> Missing,
    IReadOnlyList<string> Extra,
    IReadOnlyList<ChangedFile> Changed,
    IReadOnlyList<string> DatDifferences,
    int Compared)
{
    public bool IsIdentical => Missing.Count == 0 && Extra.Count == 0 && Changed.Count == 0 && DatDifferences.Count == 0;
}
