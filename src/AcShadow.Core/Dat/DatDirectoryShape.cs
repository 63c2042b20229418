namespace AcShadow.Core.Dat;

/// <summary>
/// The directory B-tree as read: how many nodes, how many levels (0 for an empty dat), and what its unused
/// branch slots hold (<see cref="BranchFill"/>: retail's zeros, DatReaderWriter's 0xCDCDCDCD, or both).
/// </summary>
public sealed record DatDirectoryShape(int Nodes, int Levels, BranchFill Fill);
