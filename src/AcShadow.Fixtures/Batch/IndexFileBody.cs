using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures.Batch;

/// <summary>index.json's body as <see cref="IndexFileReader"/> read it.</summary>
internal sealed record IndexFileBody<TInputs>(ShapePolicy Policy, float EntityScale, TInputs Inputs, IReadOnlyList<IndexedFile> Files);
