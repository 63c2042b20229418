namespace AcShadow.Fixtures.Shapes;

/// <summary>Something the builder skipped or could not resolve. Reported, never fatal.</summary>
public sealed record Diagnostic(string Code, string Message)
{
    public override string ToString() => $"{Code}: {Message}";
}

/// <summary>The diagnostic codes, stable for consumers that filter on them.</summary>
public static class DiagnosticCodes
{
    public const string MissingGfxObj = "missing-gfxobj";
    public const string NoPose = "no-pose";
    public const string FrameCount = "frame-count";
    public const string FlagMismatch = "flag-mismatch";
    public const string NoShapes = "no-shapes";
    public const string NonUniformScale = "non-uniform-scale";
    public const string DefaultScaleCount = "default-scale-count";
    public const string ZeroRadius = "zero-radius";
    public const string NonFinite = "non-finite";
    public const string UnreadableGfxObj = "unreadable-gfxobj";
}
