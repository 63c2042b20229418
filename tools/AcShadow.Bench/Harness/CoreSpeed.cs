using System.Diagnostics;
using System.Runtime.InteropServices;

namespace AcShadow.Bench.Harness;

/// <summary>
/// How fast each core runs one fixed integer loop right now, the harness's thread pinned to it in turn. On a shared
/// VM a core can run far slower than its neighbour while another tenant uses the same physical core (seen on the
/// project's VM: one loop 1.4 s on one core and 2.4 s on the other, minutes later 1.4 s on both), which no load
/// average shows and which caps what a second job can buy. Measured at the start and the end of a run, as one of its
/// conditions. Linux only (sched_setaffinity); elsewhere, or where pinning is refused, nothing is measured.
/// </summary>
public static class CoreSpeed
{
    /// <summary>Iterations of the loop: about 70 ms on the project's 2.1 GHz VM.</summary>
    private const int Iterations = 40_000_000;

    /// <summary>Milliseconds the loop took on each core (at most 64 cores), in core order; empty when it cannot pin.</summary>
    public static IReadOnlyList<double> Measure()
    {
        if (!OperatingSystem.IsLinux()) return [];
        var cores = Math.Min(Environment.ProcessorCount, 64);
        var times = new double[cores];
        // The thread's own set, restored afterwards (a run under taskset keeps its cores).
        var own = 0UL;
        if (!Affinity(ref own)) return [];
        try
        {
            for (var core = 0; core < cores; core++)
            {
                if ((own & 1UL << core) == 0 || !Pin(1UL << core)) return [];
                Loop(Iterations / 10);
                var watch = Stopwatch.StartNew();
                Sink += Loop(Iterations);
                times[core] = Math.Round(watch.Elapsed.TotalMilliseconds, 1);
            }
        }
        finally
        {
            Pin(own);
        }
        return times;
    }

    /// <summary>Read so the loop is not optimised away.</summary>
    public static ulong Sink { get; private set; }

    private static ulong Loop(int n)
    {
        var x = 88172645463325252UL;
        for (var i = 0; i < n; i++)
        {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
        }
        return x;
    }

    private static bool Pin(ulong mask)
    {
        try
        {
            return SchedSetAffinity(0, (nint)sizeof(ulong), ref mask) == 0;
        }
        catch (DllNotFoundException) { return false; }
        catch (EntryPointNotFoundException) { return false; }
    }

    private static bool Affinity(ref ulong mask)
    {
        try
        {
            return SchedGetAffinity(0, (nint)sizeof(ulong), ref mask) == 0 && mask != 0;
        }
        catch (DllNotFoundException) { return false; }
        catch (EntryPointNotFoundException) { return false; }
    }

    /// <summary>sched_getaffinity(2) for the calling thread (pid 0): fails on a machine with more than 64 CPUs, where nothing is measured.</summary>
    [DllImport("libc", EntryPoint = "sched_getaffinity")]
    private static extern int SchedGetAffinity(int pid, nint size, ref ulong mask);

    /// <summary>sched_setaffinity(2) for the calling thread (pid 0).</summary>
    [DllImport("libc", EntryPoint = "sched_setaffinity")]
    private static extern int SchedSetAffinity(int pid, nint size, ref ulong mask);
}
