using System.Text;
using AcShadow.Analysis.Chart.Output;

namespace AcShadow.Tests.Chart.Movement;

/// <summary>The movement chart's files: the same bytes whatever --jobs, one row per object × model, a map per object.</summary>
public class MovementChartFilesTests
{
    private static readonly uint[] Objects = [SampleChart.Door, 0x02001000];

    [Fact]
    public void The_files_are_the_same_bytes_at_one_and_two_jobs()
    {
        var one = SampleMovementChart.Run(Objects, jobs: 1).Files;
        var two = SampleMovementChart.Run(Objects, jobs: 2).Files;
        Assert.Equal(one.Select(f => f.RelativePath), two.Select(f => f.RelativePath));
        for (var i = 0; i < one.Count; i++)
            Assert.True(one[i].Content.Span.SequenceEqual(two[i].Content.Span), $"{one[i].RelativePath} differs between --jobs 1 and 2");
        Assert.Contains(one, f => f.RelativePath == MovementMapSvg.FileName(SampleChart.Door));
        Assert.Contains(one, f => f.RelativePath == MovementWalkSvg.FileName(SampleChart.Door, "fallback-cylinder"));
    }

    [Fact]
    public void Movement_chart_csv_has_a_row_per_object_and_model_with_the_verdict_counts()
    {
        var (charts, files) = SampleMovementChart.Run(Objects);
        var rows = Encoding.UTF8.GetString(files.Single(f => f.RelativePath == MovementFiles.ChartFile).Content.Span).TrimEnd('\n').Split('\n');
        Assert.Equal(MovementChartCsv.Header, rows[0]);
        Assert.Equal(1 + Objects.Length * 8, rows.Length);
        var header = rows[0].Split(',');
        var fallback = rows.Single(r => r.StartsWith("0x020019FF,fallback-cylinder,", StringComparison.Ordinal)).Split(',');
        Assert.True(int.Parse(fallback[Array.IndexOf(header, "false_pass")]) > 0);
        var retail = rows.Single(r => r.StartsWith("0x020019FF,retail,", StringComparison.Ordinal)).Split(',');
        Assert.Equal("616", retail[Array.IndexOf(header, "agree")]);
        Assert.Equal("", retail[Array.IndexOf(header, "first_diverging_frame")]);
        // The counts add up: every non-fragile case has one verdict.
        foreach (var row in rows.Skip(1).Select(r => r.Split(',')))
        {
            var verdicts = Enumerable.Range(Array.IndexOf(header, "agree"), 6).Sum(c => int.Parse(row[c]));
            Assert.Equal(int.Parse(row[Array.IndexOf(header, "cases")]) - int.Parse(row[Array.IndexOf(header, "fragile_cases")]), verdicts);
        }
        Assert.Equal(Objects.Length, charts.Count);
    }

    [Fact]
    public void The_door_story_drawings_in_docs_are_what_chart_movement_draws_now()
    {
        var files = SampleMovementChart.Run([SampleChart.Door]).Files;
        var docs = Path.Combine(Support.RepositoryRoot.Path, "docs", "chart");
        var names = new[] { "fallback-cylinder", "spheres", "union", "part-boxes", "part-hulls", "retail" }
            .Select(m => MovementWalkSvg.FileName(SampleChart.Door, m)).Append(MovementMapSvg.FileName(SampleChart.Door));
        foreach (var name in names)
            Assert.True(File.ReadAllBytes(Path.Combine(docs, name)).AsSpan().SequenceEqual(files.Single(f => f.RelativePath == name).Content.Span),
                $"docs/chart/{name} is stale: run scripts/regenerate-drawings.sh");
    }
}
