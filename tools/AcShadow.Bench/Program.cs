using AcShadow.Bench.Harness;
using BenchmarkDotNet.Running;

// dotnet run -c Release --project tools/AcShadow.Bench -- harness --cli PATH [--small]   (scripts/bench.sh)
// dotnet run -c Release --project tools/AcShadow.Bench -- alloc --dat DIR [--jobs N] [--by-type]  (what batch --all allocates)
// dotnet run -c Release --project tools/AcShadow.Bench -- --filter '*'                   (BenchmarkDotNet)
switch (args.FirstOrDefault())
{
    case "harness":
        try
        {
            var report = BenchHarness.Run(HarnessOptions.Parse(args[1..]), Console.Out);
            return report.Checks.All(c => c.Passed) ? 0 : 1;
        }
        catch (ArgumentException e)
        {
            Console.Error.WriteLine($"bench: {e.Message}");
            return 2;
        }
    case "alloc" or "floor" or "naive":
        try
        {
            return args[0] == "alloc" ? BatchAllocation.Run(args) : Workloads.Run(args);
        }
        catch (ArgumentException e)
        {
            Console.Error.WriteLine($"bench: {e.Message}");
            return 2;
        }
    default:
        BenchmarkSwitcher.FromAssembly(typeof(Program).Assembly).Run(args);
        return 0;
}
