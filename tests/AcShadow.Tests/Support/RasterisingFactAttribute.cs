namespace AcShadow.Tests.Support;

/// <summary>
/// A test that rasterises an SVG with rsvg-convert (librsvg): skipped, with the reason and the package to
/// install, on a machine that lacks it (README, "Run all tests", lists it), instead of failing there.
/// </summary>
public sealed class RasterisingFactAttribute : FactAttribute
{
    public const string Tool = "rsvg-convert";

    public RasterisingFactAttribute()
    {
        if (!Installed(Environment.GetEnvironmentVariable("PATH"))) Skip = $"{Tool} is not installed (it rasterises the SVG this test checks): apt-get install librsvg2-bin, brew install librsvg";
    }

    /// <summary>Whether rsvg-convert is in a folder of <paramref name="path"/> (a PATH value).</summary>
    public static bool Installed(string? path) =>
        (path ?? "").Split(Path.PathSeparator, StringSplitOptions.RemoveEmptyEntries)
            .Any(folder => File.Exists(Path.Combine(folder, Tool)));
}
