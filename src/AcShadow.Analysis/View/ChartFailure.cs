using System.Globalization;
using System.Numerics;
using AcShadow.Fixtures.Json;

namespace AcShadow.Analysis.View;

/// <summary>A probe where a model disagreed with the reference, as a chart's failures.csv lists it (entity frame).</summary>
public sealed record ChartFailure(uint ObjectId, string Model, bool FalsePass, Vector3 Center, float Radius)
{
    /// <summary>
    /// The rows of a chart's failures.csv (header <c>setup,model,rank,failure,kind,line,offset_m,x,y,z,radius,…</c>;
    /// docs/chart.md). Columns are found by name, so a later column added to the file does not break this.
    /// </summary>
    public static IReadOnlyList<ChartFailure> ParseCsv(string csv)
    {
        var lines = csv.Split('\n', StringSplitOptions.RemoveEmptyEntries).Select(l => l.TrimEnd('\r')).ToArray();
        if (lines.Length == 0) throw new FormatException("failures.csv is empty: expected its header line");
        var header = lines[0].Split(',');
        int Column(string name) => Array.IndexOf(header, name) is var i and >= 0 ? i : throw new FormatException($"failures.csv has no \"{name}\" column");
        int setup = Column("setup"), model = Column("model"), failure = Column("failure"), x = Column("x"), y = Column("y"), z = Column("z"), radius = Column("radius");
        var rows = new List<ChartFailure>();
        for (var n = 1; n < lines.Length; n++)
        {
            // Model names are plain words, so no field is quoted.
            var f = lines[n].Split(',');
            if (f.Length < header.Length) throw new FormatException($"failures.csv line {n + 1}: {f.Length} fields, the header has {header.Length}");
            if (!AcShadow.Fixtures.Json.JsonIds.TryParse(f[setup], out var id)) throw new FormatException($"failures.csv line {n + 1}: \"{f[setup]}\" is not an id");
            var falsePass = f[failure] switch
            {
                "false_pass" => true,
                "false_block" => false,
                var other => throw new FormatException($"failures.csv line {n + 1}: failure \"{other}\" is not false_pass or false_block"),
            };
            rows.Add(new ChartFailure(id, f[model], falsePass, new Vector3(Num(f[x], n), Num(f[y], n), Num(f[z], n)), Num(f[radius], n)));
        }
        return rows;
    }

    private static float Num(string text, int line) =>
        float.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out var v) && float.IsFinite(v) ? v
            : throw new FormatException($"failures.csv line {line + 1}: \"{text}\" is not a number");
}
