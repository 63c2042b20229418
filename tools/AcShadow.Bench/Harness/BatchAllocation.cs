using System.Diagnostics;
using System.Globalization;
using AcShadow.Core.Batch;
using AcShadow.Core.Dat;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Bench.Harness;

/// <summary>
/// `alloc --dat DIR [--jobs N] [--by-type]`: what `batch --all` allocates, in process. The CLI's own run (the same
/// working set a job; without --incremental, no fingerprints) through <see cref="BatchRunner.Stream"/>
/// with a writer that only counts, so the bytes and collections are the export path's alone. With --by-type,
/// the types that took the most bytes (the runtime's allocation samples).
/// </summary>
public static class BatchAllocation
{
    public static int Run(IReadOnlyList<string> args)
    {
        var a = new BenchArgs(args, "usage: AcShadow.Bench alloc --dat DIR [--jobs N] [--by-type]");
        var jobs = a.PositiveInt("--jobs", 1);
        using var portal = Workloads.Open(a.Required("--dat", "the folder holding client_portal.dat"));
        // As `batch` keeps: BatchCommand.WorkingSetPerJob decoded objects a job.
        var source = new DatDatabase(portal.Archive, cacheCapacity: 16 * jobs);
        var options = new ShapeBuildOptions(ShapePolicy.Retail);
        var selection = new BatchSelection(false, true, null, null);
        var plan = BatchPlanner.Plan(selection, portal, null, []);
        var inputs = new BatchInputs(portal.Info, null, options.Policy, options.EntityScale, selection);

        using var byType = a.Has("--by-type") ? new AllocationByType() : null;
        long files = 0, bytes = 0;
        var gen0 = GC.CollectionCount(0);
        var gen1 = GC.CollectionCount(1);
        var gen2 = GC.CollectionCount(2);
        var pause = GC.GetTotalPauseDuration();
        var before = GC.GetTotalAllocatedBytes(true);
        var clock = Stopwatch.StartNew();
        var summary = BatchRunner.Stream(source, options, plan, inputs, jobs, f =>
        {
            Interlocked.Increment(ref files);
            Interlocked.Add(ref bytes, f.Content.Length);
        }, reuse: null);
        var elapsed = clock.Elapsed;
        var allocated = GC.GetTotalAllocatedBytes(true) - before;
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"files {files} bytes {bytes} index {summary.IndexJson().Length}\nallocated {allocated:N0} B  gen0 {GC.CollectionCount(0) - gen0} gen1 {GC.CollectionCount(1) - gen1} gen2 {GC.CollectionCount(2) - gen2}  pause {(GC.GetTotalPauseDuration() - pause).TotalMilliseconds:F0} ms  wall {elapsed.TotalSeconds:F2} s"));
        if (byType is not null)
        {
            Console.WriteLine("    SOH MB    LOH MB  type (allocation samples)");
            foreach (var (type, small, large) in byType.Top(25))
                Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{small / 1e6,10:F1}{large / 1e6,10:F1}  {type}"));
        }
        return 0;
    }
}
