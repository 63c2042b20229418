namespace AcShadow.Analysis.Reports;

/// <summary>One CSV field (RFC 4180): quoted, with quotes doubled, when it holds a comma, quote or line break.</summary>
public static class CsvField
{
    public static string Of(string field) =>
        field.IndexOfAny([',', '"', '\n', '\r']) < 0 ? field : "\"" + field.Replace("\"", "\"\"") + "\"";
}
