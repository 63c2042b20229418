using AcShadow.Core.Dat;
using AcShadow.Forge.Scale;
using AcShadow.Forging;

namespace AcShadow.Bench;

/// <summary>
/// A scale dat for the BenchmarkDotNet micro-benchmarks, built once per benchmark process: 2,000 Setups
/// (about 11,000 GfxObjs, a few seconds to forge) rather than the harness's full 7,000, because
/// BenchmarkDotNet starts a process per benchmark.
/// </summary>
public static class ScaleDat
{
    public const int Setups = 2000;
    private static readonly Lazy<byte[]> Bytes = new(() => SpecCompiler.Compile(ScaleSpecGenerator.Generate(Setups)).Portal);

    public static byte[] PortalBytes => Bytes.Value;

    public static DatDatabase Open() => DatDatabase.Open(new MemoryStream(PortalBytes, writable: false), "scale/client_portal.dat");
}
