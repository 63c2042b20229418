namespace AcShadow.Analysis.Doctor;

/// <summary>Everything `acshadow doctor` found: the dats' shape (sizes, counts) and one entry per check.</summary>
public sealed record DoctorReport(string ToolVersion, DoctorDatFacts Portal, DoctorDatFacts? Cell, IReadOnlyList<DoctorCheck> Checks)
{
    public int Count(DoctorVerdict verdict) => Checks.Count(c => c.Verdict == verdict);

    public DoctorCheck Check(string key) => Checks.First(c => c.Key == key);
}

/// <summary>
/// The facts of one dat file that identify its version without holding its content: sizes, the block
/// size, the iteration, and how many directory entries each id range has (the high byte of the id).
/// </summary>
public sealed record DoctorDatFacts(
    string Kind,
    long FileLength,
    long HeaderFileSize,
    int BlockSize,
    int Entries,
    int MaxEntryIteration,
    IReadOnlyList<KeyValuePair<string, long>> EntriesByType);
