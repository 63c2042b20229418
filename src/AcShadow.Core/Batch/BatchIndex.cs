namespace AcShadow.Core.Batch;

/// <summary>One file index.json lists.</summary>
public sealed record IndexedFile(string Path, string Kind, string Id, string Sha256);

/// <summary>index.json read back: the inputs to regenerate with, and the files it lists.</summary>
public sealed record BatchIndex(BatchInputs Inputs, IReadOnlyList<IndexedFile> Files);
