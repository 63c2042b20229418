using System.Globalization;

namespace AcShadow.Fuzz;

/// <summary>
/// `acshadow-fuzz [--seed N] [--cases N] [--start N] [--deep-every N] [--time-limit SECONDS] [--memory-limit MIB] [--save DIR] [--trace FILE]`:
/// runs a campaign on the built-in sample and prints cases/second, time per command, failures and the
/// slowest case. Every case runs dump and batch; every Nth (--deep-every, default 1: all) also chart and verify, and an incremental re-run that must repair the damaged fixture. With
/// --save, each kind of failure is minimised and saved there as a reproducer; with --trace, the index of the
/// case about to run is written to FILE (what a crash of the whole process leaves). Exit 0 when nothing failed.
/// </summary>
public static class Program
{
    public static int Main(string[] args)
    {
        var options = new CampaignOptions(Seed: 1, Cases: 2000);
        string? save = null;
        string? trace = null;
        for (var i = 0; i < args.Length; i++)
        {
            var value = i + 1 < args.Length ? args[i + 1] : null;
            switch (args[i])
            {
                case "--seed": options = options with { Seed = long.Parse(Need(value, args[i]), CultureInfo.InvariantCulture) }; i++; break;
                case "--cases": options = options with { Cases = int.Parse(Need(value, args[i]), CultureInfo.InvariantCulture) }; i++; break;
                case "--deep-every": options = options with { DeepEvery = int.Parse(Need(value, args[i]), CultureInfo.InvariantCulture) }; i++; break;
                case "--start": options = options with { Start = int.Parse(Need(value, args[i]), CultureInfo.InvariantCulture) }; i++; break;
                case "--time-limit": options = options with { TimeLimitSeconds = double.Parse(Need(value, args[i]), CultureInfo.InvariantCulture) }; i++; break;
                case "--memory-limit": options = options with { MemoryLimitBytes = long.Parse(Need(value, args[i]), CultureInfo.InvariantCulture) << 20 }; i++; break;
                case "--save": save = Need(value, args[i]); i++; break;
                case "--trace": trace = Need(value, args[i]); i++; break;
                default:
                    Console.Error.WriteLine($"acshadow-fuzz: unknown argument '{args[i]}' (use --seed, --cases, --start, --deep-every, --time-limit, --memory-limit, --save, --trace)");
                    return 2;
            }
        }

        var scratch = ScratchFolder.Create();
        try
        {
            var bases = FuzzBase.All();
            Console.WriteLine($"fuzz: seed {options.Seed}, cases {options.Start}..{options.Start + options.Cases - 1} (chart and verify on every {Math.Max(1, options.DeepEvery)}), " +
                $"time limit {options.TimeLimitSeconds:0.###} s, memory limit {options.MemoryLimitBytes >> 20} MiB per case");
            var step = Math.Max(1, options.Cases / 20);
            var done = 0;
            var result = FuzzCampaign.Run(bases, options, scratch, (index, outcome) =>
            {
                if (outcome.Failure is { } f) Console.WriteLine($"FAIL case {index}: {f.Signature}");
                if (++done % step == 0) Console.WriteLine($"  {done}/{options.Cases} cases");
            }, trace is null ? null : index => File.WriteAllText(trace, $"case {index} (seed {options.Seed})\n"));
            Print(result);
            if (save is not null && result.Failures.Count > 0)
            {
                var minimiser = new InputMinimiser(new CaseRunner(scratch, options.TimeLimit, options.MemoryLimitBytes));
                foreach (var group in result.Failures.GroupBy(f => f.Failure.Signature))
                {
                    var (found, small) = group
                        .Select(f => (Found: f, Small: minimiser.Minimise(f.Input, f.Failure)))
                        .MinBy(m => m.Small.Portal.Length + m.Small.Cell.Length);
                    var folder = ReproducerStore.Save(save, $"seed{options.Seed}-case{found.CaseIndex}", small, found.Failure);
                    Console.WriteLine($"saved {folder} ({small.Portal.Length} + {small.Cell.Length} bytes): {found.Failure.Signature}");
                }
            }
            return result.FailedCases == 0 ? 0 : 1;
        }
        finally
        {
            try { Directory.Delete(scratch, recursive: true); } catch (IOException) { }
        }
    }

    private static void Print(CampaignResult r)
    {
        Console.WriteLine($"cases: {r.Cases} in {r.Elapsed.TotalSeconds:0.0} s = {r.CasesPerSecond:0.0} cases/s ({r.DeepCases} also ran chart and verify)");
        Console.WriteLine($"time per command: {string.Join(", ", r.CommandTimes.Select(kv => $"{kv.Key} {kv.Value.TotalSeconds:0.0} s"))}");
        Console.WriteLine($"exit codes (dump, batch, chart, verify per case): {string.Join(", ", r.ExitCodeCounts.Select(kv => $"{kv.Key}: {kv.Value}"))}");
        Console.WriteLine($"slowest: case {r.SlowestCase} in {r.SlowestTime.TotalMilliseconds:0} ms: {r.SlowestDescription}");
        Console.WriteLine($"failures: {r.FailedCases} case(s), {r.FailureCounts.Count} kind(s)");
        foreach (var found in r.Failures.DistinctBy(f => f.Failure.Signature))
        {
            Console.WriteLine($"  {r.FailureCounts[found.Failure.Signature]} × {found.Failure.Signature}; first: {found.Input.Description}");
            Console.WriteLine($"    {found.Failure.Detail.Split('\n').FirstOrDefault(l => l.Length > 0)?.Trim()}");
        }
    }

    private static string Need(string? value, string option) =>
        value ?? throw new ArgumentException($"{option} needs a value");
}
