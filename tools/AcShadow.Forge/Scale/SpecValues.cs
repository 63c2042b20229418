using AcShadow.Forging;
using AcShadow.Forging.Spec;

namespace AcShadow.Forge.Scale;

/// <summary>The small values every part of the scale spec draws or writes the same way.</summary>
internal static class SpecValues
{
    /// <summary>Uniform in [min, max), rounded to three decimals.</summary>
    public static double Range(Random random, double min, double max) => Math.Round(min + random.NextDouble() * (max - min), 3);

    /// <summary><paramref name="min"/> to 30 parts, few parts common: min + 29·u³ for statics, wider for creatures.</summary>
    public static int PartCount(Random random, int min)
    {
        var u = random.NextDouble();
        var spread = min == 1 ? u * u * u : u * u;
        return Math.Min(ScaleSpecGenerator.MaxParts, min + (int)((ScaleSpecGenerator.MaxParts - min + 1) * spread));
    }

    public static FrameSpec Frame(double x, double y, double z, int degrees) =>
        new() { Origin = [x, y, z], Orientation = SampleSpecAuthor.Z(degrees) };

    public static string Hex(uint id) => $"0x{id:X8}";
}
