namespace AcShadow.Fixtures.Batch;

/// <summary>One file index.json lists: its output-relative path, its kind, its id, its SHA-256 (lower-case hex).</summary>
public sealed record IndexedFile(string Path, FixtureKind Kind, string Id, string Sha256);
