using AcShadow.Forging.Spec;

namespace AcShadow.Forging;

/// <summary>
/// The built-in sample (Sample/sample.json, embedded in this assembly) and its dats, built in memory,
/// so acshadow's own CLI and tests can open the sample without running the forge executable.
/// </summary>
public static class SampleDats
{
    public const string ResourceName = "AcShadow.Forging.Sample.sample.json";

    /// <summary>The sample's person-sized two-sphere mover Setup: `acshadow move`'s default mover on the sample.</summary>
    public const uint MoverSetup = 0x02001100;

    private static readonly Lazy<string> JsonText = new(() =>
    {
        using var stream = typeof(SampleDats).Assembly.GetManifestResourceStream(ResourceName)
            ?? throw new InvalidOperationException($"embedded resource {ResourceName} is missing from the AcShadow.Forging assembly");
        using var reader = new StreamReader(stream);
        return reader.ReadToEnd();
    });

    private static readonly Lazy<ForgedDats> Built = new(() => SpecCompiler.Compile(Spec));

    /// <summary>The sample spec's JSON text as embedded.</summary>
    public static string Json => JsonText.Value;

    /// <summary>The sample spec, parsed from the embedded JSON (a fresh copy each call; records are immutable anyway).</summary>
    public static ForgeSpec Spec => SpecJson.Parse(Json, "sample.json");

    /// <summary>Portal and cell dat bytes of the sample. Built once; callers must not modify the arrays.</summary>
    public static (byte[] Portal, byte[] Cell) Build()
    {
        var dats = Built.Value;
        return (dats.Portal, dats.Cell ?? throw new InvalidOperationException("the sample spec has no landblocks"));
    }
}
