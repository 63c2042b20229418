namespace AcShadow.Core.Batch;

/// <summary>How many diagnostics a batch's files carry, and in how many Setups.</summary>
public readonly record struct DiagnosticCount(int Diagnostics, int Setups);
