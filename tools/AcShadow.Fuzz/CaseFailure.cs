namespace AcShadow.Fuzz;

/// <summary>
/// What went wrong in one case. <see cref="Signature"/> is the class of failure and the command
/// (e.g. "batch: internal error: IndexOutOfRangeException"), stable under minimisation; <see cref="Detail"/> says the rest.
/// </summary>
public sealed record CaseFailure(string Signature, string Detail);

/// <summary>One case's result: a failure or null, how long it took, and each command's exit code.</summary>
public sealed record CaseOutcome(CaseFailure? Failure, TimeSpan Elapsed, IReadOnlyList<int> ExitCodes)
{
    /// <summary>How long each command that ran took (a command run by this case once at most).</summary>
    public IReadOnlyDictionary<string, TimeSpan> CommandTimes { get; init; } = new Dictionary<string, TimeSpan>();
}
