using AcShadow.Core.Dat;
using AcShadow.Forge;

namespace AcShadow.Bench;

/// <summary>The realistic-scale forged dat (the forge's `scale` spec), built once per process.</summary>
public static class ScaleDat
{
    private static readonly Lazy<byte[]> Bytes = new(() => SpecCompiler.Compile(ScaleSpecGenerator.Generate()).Portal);

    public static byte[] PortalBytes => Bytes.Value;

    public static DatDatabase Open() => DatDatabase.Open(new MemoryStream(PortalBytes, writable: false), "scale/client_portal.dat");
}
