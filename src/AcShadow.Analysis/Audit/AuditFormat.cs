namespace AcShadow.Analysis.Audit;

/// <summary>How an audit is written: an aligned text table (terminals), CSV, JSON or Markdown (files).</summary>
public enum AuditFormat
{
    Table,
    Csv,
    Json,
    Markdown,
}

public static class AuditFormats
{
    public static bool TryParse(string text, out AuditFormat format)
    {
        switch (text.ToLowerInvariant())
        {
            case "table": format = AuditFormat.Table; return true;
            case "csv": format = AuditFormat.Csv; return true;
            case "json": format = AuditFormat.Json; return true;
            case "md" or "markdown": format = AuditFormat.Markdown; return true;
            default: format = default; return false;
        }
    }

    /// <summary>The format a file name's extension implies (.csv, .json, .md), if any.</summary>
    public static AuditFormat? FromExtension(string path) => Path.GetExtension(path).ToLowerInvariant() switch
    {
        ".csv" => AuditFormat.Csv,
        ".json" => AuditFormat.Json,
        ".md" or ".markdown" => AuditFormat.Markdown,
        ".txt" => AuditFormat.Table,
        _ => null,
    };
}
