using System.Globalization;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>Number formatting for chart files: invariant culture, fixed decimals, "inf"/"-inf" for infinities, empty for NaN.</summary>
internal static class ChartFormat
{
    public static string F(double value, int decimals)
    {
        if (double.IsNaN(value)) return "";
        if (double.IsPositiveInfinity(value)) return "inf";
        if (double.IsNegativeInfinity(value)) return "-inf";
        var text = value.ToString("F" + decimals.ToString(CultureInfo.InvariantCulture), CultureInfo.InvariantCulture);
        // "-0.00" and "0.00" are the same number; write one of them.
        return text.StartsWith('-') && text.Trim('-', '0', '.').Length == 0 ? text[1..] : text;
    }

    public static string I(long value) => value.ToString(CultureInfo.InvariantCulture);

    public static string Id(uint id) => Fixtures.Json.JsonIds.Format(id);

    public static string Csv(string field) => Reports.CsvField.Of(field);

    /// <summary>Time with a unit for labels: 850 ns, 1.2 µs, 35 µs.</summary>
    public static string Time(double ns)
    {
        if (double.IsNaN(ns)) return "not measured";
        if (ns < 1000) return F(ns, ns < 10 ? 1 : 0) + " ns";
        if (ns < 1e6) return F(ns / 1e3, ns < 1e4 ? 1 : 0) + " µs";
        return F(ns / 1e6, 1) + " ms";
    }
}
