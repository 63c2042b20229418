namespace AcShadow.Core.Verify;

/// <summary>
/// One difference between two JSON documents: where (a JSONPath like "$.shapes[0].radius") and the
/// old and new values as JSON text; null means the value is absent on that side.
/// </summary>
public sealed record JsonDifference(string Path, string? Old, string? New)
{
    public const string AbsentText = "(absent)";

    public override string ToString() => $"{Path}: {Old ?? AbsentText} → {New ?? AbsentText}";
}
