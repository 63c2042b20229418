using AcShadow.Fixtures.Batch;

namespace AcShadow.Core.Batch;

/// <summary>index.json read back: the inputs to regenerate with, and the files it lists.</summary>
public sealed record BatchIndex(BatchInputs Inputs, IReadOnlyList<IndexedFile> Files);
