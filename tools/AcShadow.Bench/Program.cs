using BenchmarkDotNet.Running;

// dotnet run -c Release --project tools/AcShadow.Bench -- --filter '*'
BenchmarkSwitcher.FromAssembly(typeof(Program).Assembly).Run(args);
