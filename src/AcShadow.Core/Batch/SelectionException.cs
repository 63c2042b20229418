namespace AcShadow.Core.Batch;

/// <summary>Why a selection cannot be planned at all (unlike a missing Setup id, which is skipped).</summary>
public enum SelectionProblem
{
    /// <summary>The landblock is not in the cell dat.</summary>
    NotInDat,
    /// <summary>A landblock was asked for but no cell dat is open.</summary>
    NeedsCellDat,
}

/// <summary>A selection that cannot be planned; the message is one line naming what to fix.</summary>
public sealed class SelectionException(SelectionProblem problem, string message) : Exception(message)
{
    public SelectionProblem Problem { get; } = problem;
}
