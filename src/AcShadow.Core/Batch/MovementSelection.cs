namespace AcShadow.Core.Batch;

/// <summary>`batch --movement ID... [--mover ID]`: the object Setups whose movement cases the batch adds, and the mover that walks them.</summary>
public sealed record MovementSelection(IReadOnlyList<uint> Setups, uint Mover);
