namespace AcShadow.Core.Batch;

/// <summary>How far a batch run is: work items done of the total (one per Setup, one per scene).</summary>
public readonly record struct BatchProgress(int Done, int Total);
