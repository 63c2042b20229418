using AcShadow.Analysis.Chart;
using AcShadow.Cli.Terminal;
using AcShadow.Forging;

namespace AcShadow.Tests.Cli;

/// <summary>docs/chart.md, "charting a whole dat": the chart's ETA weighs objects by size, so big objects first do not mislead it.</summary>
public class WorkWeightedEtaTests
{
    // 1,000 objects, the first 300 a hundred times the size of the rest; each costs 10 ms plus 1 ms per size unit.
    private static readonly double[] Work = [.. Enumerable.Repeat(100.0, 300), .. Enumerable.Repeat(1.0, 700)];
    private static double Cost(int i) => 0.010 + 0.001 * Work[i];

    /// <param name="warmUp">Seconds the first object takes on top (start-up, JIT, the timer's first long warm-up).</param>
    private static (WorkWeightedEta Eta, double Elapsed, double Left) RunTo(int done, double warmUp = 5)
    {
        var eta = new WorkWeightedEta(Work);
        var elapsed = warmUp;
        for (var i = 0; i < done; i++)
        {
            elapsed += Cost(i);
            eta.Record(i + 1, TimeSpan.FromSeconds(elapsed));
        }
        var left = Enumerable.Range(done, Work.Length - done).Sum(Cost);
        return (eta, elapsed, left);
    }

    [Fact]
    public void Once_sizes_and_counts_part_ways_it_finds_the_time_left_that_counting_objects_overstates_sevenfold()
    {
        var (eta, elapsed, left) = RunTo(350);

        var remaining = eta.Remaining(350)!.Value.TotalSeconds;
        Assert.Equal(left, remaining, left * 0.01);
        // Counting objects: those left at the rate so far.
        var byCount = elapsed / 350 * 650;
        Assert.True(byCount > 7 * left, $"{byCount} against {left}");
    }

    [Fact]
    public void While_only_big_objects_are_done_it_leans_on_size_and_errs_far_less_than_counting()
    {
        var (eta, elapsed, left) = RunTo(200);

        var remaining = eta.Remaining(200)!.Value.TotalSeconds;
        var byCount = elapsed / 200 * 800;
        Assert.True(Math.Abs(remaining - left) < Math.Abs(byCount - left) / 3, $"{remaining} and {byCount} against {left}");
    }

    [Fact]
    public void One_report_is_not_yet_an_estimate_and_the_end_means_none_left()
    {
        var eta = new WorkWeightedEta(Work);
        Assert.Null(eta.Remaining(0));
        // The first report is where counting starts: start-up and one-off warm-ups are not a per-object cost.
        eta.Record(1, TimeSpan.FromSeconds(5));
        Assert.Null(eta.Remaining(1));
        var (run, _, _) = RunTo(999);
        run.Record(1000, TimeSpan.FromSeconds(100));
        Assert.Equal(TimeSpan.Zero, run.Remaining(1000));
    }

    [Fact]
    public void Sizes_come_from_the_dat_directory_a_Setup_weighing_what_its_parts_take()
    {
        var (portal, _) = SampleDats.Build();
        using var dat = Core.Dat.DatDatabase.Open(new MemoryStream(portal), "sample_portal.dat");
        var setups = dat.ListIds(Core.Dat.DatObjectKind.Setup);
        var work = ChartWork.Of(dat, setups, []);

        Assert.Equal(setups.Count, work.Length);
        for (var i = 0; i < setups.Count; i++)
        {
            var setup = dat.ReadSetup(setups[i])!;
            var parts = setup.Parts.Sum(p => (double)(dat.StoredSize(p) ?? 0));
            // Only a Setup flagged HasPhysicsBSP weighs its parts: others' parts are drawing meshes to the chart.
            Assert.Equal(setup.Flags.HasFlag(Core.Dat.Objects.SetupFlags.HasPhysicsBsp) ? parts : 0, work[i]);
        }
        Assert.Contains(setups, id => !dat.ReadSetup(id)!.Flags.HasFlag(Core.Dat.Objects.SetupFlags.HasPhysicsBsp) && dat.ReadSetup(id)!.Parts.Count > 0);
        Assert.Contains(work, w => w > 0);
        // A part the dat lacks weighs nothing (the sample has Setups whose parts are missing on purpose).
        Assert.Contains(setups, id => dat.ReadSetup(id)!.Parts.Any(p => dat.StoredSize(p) is null));
        Assert.Equal([0.0], ChartWork.Of(dat, [0x0200FFFF], []));
    }
}
