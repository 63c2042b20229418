namespace AcShadow.Fuzz;

/// <summary>The ways a case damages a dat ("bit flips, byte runs, truncation at every block
/// boundary, zeroed blocks, shuffled blocks, header fields at their limits").</summary>
public enum MutationKind
{
    BitFlips,
    ByteRun,
    Truncation,
    ZeroedBlock,
    ShuffledBlocks,
    HeaderFieldAtLimit,
    DirectoryFieldAtLimit,
    ObjectFieldAtLimit,
    ChainPointer,
}
