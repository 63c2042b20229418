namespace AcShadow.Analysis.Chart.Output;

/// <summary>One chart output in memory: its path relative to the output folder ('/' separated) and its bytes (UTF-8).</summary>
public sealed record ChartFile(string RelativePath, byte[] Content);
