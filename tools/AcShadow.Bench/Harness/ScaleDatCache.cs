using System.Diagnostics;
using System.Globalization;
using AcShadow.Forge;
using AcShadow.Forge.Scale;
using AcShadow.Forging;

namespace AcShadow.Bench.Harness;

/// <summary>A forged scale dat in the cache, and what making it cost (measured when it was made).</summary>
public sealed record CachedDat(string Directory, int Setups, int GfxObjs, int Seed, long PortalBytes, double GenerationSeconds, bool WasCached);

/// <summary>
/// Forged scale dats cached by their parameters and the forge build (DIR/scale-s{N}-g{M}-seed{S}-forge{V}/,
/// V from the deterministic module ids of the forge and AcShadow.Forging): the forge is deterministic, so a folder's name says
/// everything about its bytes, and a changed generator never measures a stale dat. Made in a temporary folder and renamed, so an
/// interrupted run never leaves a half-written dat in the cache.
/// </summary>
public static class ScaleDatCache
{
    private const string GenerationFile = "generation-seconds.txt";

    /// <summary>Both assemblies that decide the bytes: the scale spec's (the forge) and the compiler's (AcShadow.Forging).</summary>
    private static string ForgeVersion => Build(typeof(ScaleSpecGenerator)) + Build(typeof(SpecCompiler));

    private static string Build(Type type) => type.Assembly.ManifestModule.ModuleVersionId.ToString("N")[..8];

    public static CachedDat Get(string cacheDir, int setups, int gfxObjs, int seed, TextWriter log)
    {
        var dir = Path.Combine(cacheDir, string.Create(CultureInfo.InvariantCulture, $"scale-s{setups}-g{gfxObjs}-seed{seed}-forge{ForgeVersion}"));
        var portal = Path.Combine(dir, ForgeApp.PortalFileName);
        if (File.Exists(portal) && File.Exists(Path.Combine(dir, GenerationFile)))
        {
            var seconds = double.Parse(File.ReadAllText(Path.Combine(dir, GenerationFile)), CultureInfo.InvariantCulture);
            return new CachedDat(dir, setups, gfxObjs, seed, new FileInfo(portal).Length, seconds, true);
        }
        log.WriteLine($"forging scale dat: {setups} Setups, {gfxObjs} GfxObjs, seed {seed} -> {dir}");
        var clock = Stopwatch.StartNew();
        var dats = SpecCompiler.Compile(ScaleSpecGenerator.Generate(setups, seed, gfxObjs));
        var generation = clock.Elapsed.TotalSeconds;
        var temp = dir + $".{Environment.ProcessId}.tmp";
        if (Directory.Exists(temp)) Directory.Delete(temp, true);
        Directory.CreateDirectory(temp);
        File.WriteAllBytes(Path.Combine(temp, ForgeApp.PortalFileName), dats.Portal);
        if (dats.Cell is { } cell) File.WriteAllBytes(Path.Combine(temp, ForgeApp.CellFileName), cell);
        File.WriteAllText(Path.Combine(temp, GenerationFile), generation.ToString("0.###", CultureInfo.InvariantCulture));
        if (Directory.Exists(dir)) Directory.Delete(dir, true);
        Directory.Move(temp, dir);
        log.WriteLine(string.Create(CultureInfo.InvariantCulture, $"  forged in {generation:0.0} s ({dats.Portal.Length / 1048576.0:0.0} MiB portal dat)"));
        return new CachedDat(dir, setups, gfxObjs, seed, dats.Portal.Length, generation, false);
    }
}
