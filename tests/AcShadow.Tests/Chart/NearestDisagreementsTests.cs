using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Models;

namespace AcShadow.Tests.Chart;

/// <summary>
/// The chart keeps only the disagreements nearest the boundary and rules the rest out with a bounded
/// distance search. What it keeps must be exactly what measuring every disagreement in full and ranking
/// them all gives: same probes, same order, same gap bits, for every model, with room for few (1, 3) and
/// for many (50).
/// </summary>
public class NearestDisagreementsTests
{
    private static readonly uint[] Setups = [0x0200024F, 0x02000281, 0x02001000, 0x020019FF, 0x02002000, 0x02003000, 0x02003300, 0x02005000, 0x02006000];

    [Theory]
    [InlineData(1)]
    [InlineData(3)]
    [InlineData(50)]
    public void The_kept_disagreements_are_the_nearest_of_all_of_them(int perKind)
    {
        var options = new ChartOptions { FailuresPerModel = perKind, Spacing = 0.5f };
        var compared = 0;
        foreach (var id in Setups)
        {
            var subject = SampleChart.Subjects.Value.For(id)!;
            var chart = ChartRunner.Chart(subject, options, ShapeModels.All, new FixedTimer());
            var probes = chart.Probes.ToArray();
            var reference = ShapeModels.All[0].Prepare(subject).Shapes;
            for (var m = 0; m < ShapeModels.All.Count; m++)
            {
                var outcome = chart.Models[m];
                var shapes = ShapeModels.All[m].Prepare(subject).Shapes;
                var every = Enumerable.Range(0, probes.Length).Where(i => outcome.Answers[i] != chart.Reference[i])
                    .Select(i => new Disagreement(i, probes[i], chart.Reference[i], BoundaryGap.Of(reference, probes[i].Center, probes[i].Radius), BoundaryGap.Of(shapes, probes[i].Center, probes[i].Radius)))
                    .ToArray();
                var expected = every.Where(d => d.FalsePass).OrderBy(d => d.Nearness).ThenBy(d => d.ProbeIndex).Take(perKind)
                    .Concat(every.Where(d => !d.FalsePass).OrderBy(d => d.Nearness).ThenBy(d => d.ProbeIndex).Take(perKind))
                    .OrderBy(d => d.Nearness).ThenBy(d => d.ProbeIndex).ToArray();
                Assert.Equal(Describe(expected), Describe(outcome.Nearest));
                if (every.Length > perKind) compared++;
            }
        }
        // The cut-off only matters where a model has more disagreements than are kept.
        Assert.True(compared >= 10, $"only {compared} model charts had more disagreements than kept");
    }

    private static string[] Describe(IEnumerable<Disagreement> disagreements) => disagreements.Select(d =>
        $"{d.ProbeIndex} {d.FalsePass} {BitConverter.SingleToInt32Bits(d.GapToReference):X8} {BitConverter.SingleToInt32Bits(d.GapToModel):X8}").ToArray();
}
