using System.CommandLine;
using AcShadow.Files;
using AcShadow.Forge.Scale;
using AcShadow.Forging;
using AcShadow.Forging.Spec;

namespace AcShadow.Forge;

/// <summary>
/// The forge command line. Exit codes: 0 success; 2 bad input (spec errors, bad arguments);
/// 1 unexpected failure. Errors are one line on stderr (plus the stack trace with --verbose).
/// Nothing is written unless everything compiled: dats are built in memory first, then each file is
/// written atomically.
/// </summary>
public static class ForgeApp
{
    public const int Success = 0, Failure = 1, BadInput = 2;
    public const string PortalFileName = "client_portal.dat", CellFileName = "client_cell_1.dat";

    /// <summary>Thrown for a bad argument value the parser cannot check (exit 2).</summary>
    private sealed class UsageException(string message) : Exception(message);

    public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var verbose = new Option<bool>("--verbose") { Description = "Show stack traces for errors", Recursive = true };
        var outDir = new Option<string>("--out") { Description = "Directory to write the dat files into (created if missing)", Required = true };
        var writeSpec = new Option<string?>("--write-spec") { Description = "Also write the spec as JSON to this file" };

        var specArgument = new Argument<string>("spec") { Description = "The spec JSON file (see docs/forge-spec.md)" };
        var build = new Command("build", "Forge dats from a spec file") { specArgument, outDir };
        build.SetAction(parse => Guard(parse.GetValue(verbose), stderr, () =>
            WriteDats(SpecCompiler.Compile(SpecJson.Load(parse.GetValue(specArgument)!)), parse.GetValue(outDir)!, stdout)));

        var sample = new Command("sample", "Forge the built-in sample (doors, statics, creatures, a house, a landblock)") { outDir, writeSpec };
        sample.SetAction(parse => Guard(parse.GetValue(verbose), stderr, () =>
        {
            // The authored spec first: regenerating Sample/sample.json must not depend on the embedded copy.
            if (parse.GetValue(writeSpec) is { } path) WriteSpec(SampleSpecAuthor.Create(), path, stdout);
            var (portal, cell) = SampleDats.Build();
            var spec = SampleDats.Spec;
            WriteDats(new ForgedDats(portal, cell, spec.GfxObjs.Count, spec.Setups.Count, spec.Landblocks.Count), parse.GetValue(outDir)!, stdout);
        }));

        var setupCount = new Option<int>("--setups") { Description = "How many Setups", DefaultValueFactory = _ => ScaleSpecGenerator.DefaultSetups };
        var gfxObjCount = new Option<int?>("--gfxobjs") { Description = $"How many GfxObjs (default: {ScaleSpecGenerator.DefaultGfxObjs} for {ScaleSpecGenerator.DefaultSetups} Setups, in proportion otherwise)" };
        var seed = new Option<int>("--seed") { Description = "Random seed; same seed and counts, same bytes", DefaultValueFactory = _ => ScaleSpecGenerator.DefaultSeed };
        var scale = new Command("scale", "Forge a realistic-scale dat for benchmarks") { outDir, setupCount, gfxObjCount, seed, writeSpec };
        scale.SetAction(parse => Guard(parse.GetValue(verbose), stderr, () =>
        {
            var n = parse.GetValue(setupCount);
            if (n < 1 || n > ScaleSpecGenerator.MaxSetups) throw new UsageException($"--setups {n}: give 1-{ScaleSpecGenerator.MaxSetups}");
            var m = parse.GetValue(gfxObjCount) ?? ScaleSpecGenerator.GfxObjsFor(n);
            if (m < ScaleSpecGenerator.MinGfxObjs(n) || m > ScaleSpecGenerator.MaxGfxObjs)
                throw new UsageException($"--gfxobjs {m}: give {ScaleSpecGenerator.MinGfxObjs(n)}-{ScaleSpecGenerator.MaxGfxObjs} for {n} Setups (the doors alone need a leaf each)");
            var clock = System.Diagnostics.Stopwatch.StartNew();
            var spec = ScaleSpecGenerator.Generate(n, parse.GetValue(seed), m);
            var generated = clock.Elapsed;
            var dats = SpecCompiler.Compile(spec);
            var compiled = clock.Elapsed;
            WriteDats(dats, parse.GetValue(outDir)!, stdout);
            stdout.WriteLine(string.Create(System.Globalization.CultureInfo.InvariantCulture,
                $"generated in {clock.Elapsed.TotalSeconds:0.0} s (spec {generated.TotalSeconds:0.0} s, BSPs and dat {(compiled - generated).TotalSeconds:0.0} s on {Environment.ProcessorCount} core(s), writing {(clock.Elapsed - compiled).TotalSeconds:0.0} s)"));
            if (parse.GetValue(writeSpec) is { } path) WriteSpec(spec, path, stdout);
        }));

        var root = new RootCommand("forge: writes real-format Asheron's Call dat files (client_portal.dat, client_cell_1.dat) from a JSON spec")
        {
            build, sample, scale, verbose,
        };

        var result = root.Parse(args);
        if (result.Errors.Count > 0)
        {
            stderr.WriteLine($"forge: {result.Errors[0].Message} (see forge --help)");
            return BadInput;
        }
        return result.Invoke(new InvocationConfiguration { Output = stdout, Error = stderr, EnableDefaultExceptionHandler = false });
    }

    private static int Guard(bool verbose, TextWriter stderr, Action action)
    {
        try
        {
            action();
            return Success;
        }
        catch (Exception e) when (e is SpecException or UsageException)
        {
            stderr.WriteLine($"forge: {e.Message}");
            if (verbose) stderr.WriteLine(e.StackTrace);
            return BadInput;
        }
        catch (Exception e)
        {
            stderr.WriteLine($"forge: unexpected failure: {e.GetType().Name}: {e.Message.ReplaceLineEndings(" ")}");
            if (verbose) stderr.WriteLine(e);
            return Failure;
        }
    }

    private static void WriteDats(ForgedDats dats, string dir, TextWriter stdout)
    {
        Directory.CreateDirectory(dir);
        var portalPath = Path.Combine(dir, PortalFileName);
        // Flushed: a dat is a few large files, costly to forge again, that a power cut must not leave empty.
        AtomicFile.Write(portalPath, dats.Portal, Durability.Flushed);
        stdout.WriteLine($"wrote {portalPath} ({dats.Portal.Length} bytes; {dats.GfxObjCount} GfxObjs, {dats.SetupCount} Setups{(dats.EnvironmentCount > 0 ? $", {dats.EnvironmentCount} Environments" : "")})");
        if (dats.Cell is { } cell)
        {
            var cellPath = Path.Combine(dir, CellFileName);
            AtomicFile.Write(cellPath, cell, Durability.Flushed);
            stdout.WriteLine($"wrote {cellPath} ({cell.Length} bytes; {dats.LandblockCount} LandBlockInfos{(dats.EnvCellCount > 0 ? $", {dats.EnvCellCount} EnvCells" : "")})");
        }
    }

    private static void WriteSpec(ForgeSpec spec, string path, TextWriter stdout)
    {
        var json = SpecJson.Serialize(spec);
        var full = Path.GetFullPath(path);
        Directory.CreateDirectory(Path.GetDirectoryName(full)!);
        AtomicFile.Write(full, System.Text.Encoding.UTF8.GetBytes(json), Durability.Flushed);
        stdout.WriteLine($"wrote {path} ({json.Length} chars; spec with {spec.GfxObjs.Count} GfxObjs, {spec.Setups.Count} Setups, {spec.Landblocks.Count} landblocks)");
    }
}
