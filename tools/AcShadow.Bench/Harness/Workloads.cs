using System.Text.Json;
using AcShadow.Core.Dat;

namespace AcShadow.Bench.Harness;

/// <summary>
/// The two baselines the harness runs as whole processes, like the CLI, so start-up and peak memory are
/// measured the same way: `floor` and `naive` (AcShadow.Bench floor|naive --dat DIR [--jobs N] [--out DIR]).
/// </summary>
public static class Workloads
{
    private const string Usage = "usage: AcShadow.Bench floor|naive --dat DIR [--jobs N] [--out DIR]";

    public static int Run(IReadOnlyList<string> args)
    {
        var a = new BenchArgs(args, Usage);
        var jobs = a.PositiveInt("--jobs", 1);
        using var database = Open(a.Required("--dat", "the folder holding client_portal.dat"));
        long count = args[0] switch
        {
            "floor" => Floor(database, jobs),
            "naive" => Naive(database, a.Value("--out") ?? "naive-out"),
            _ => throw new ArgumentException($"unknown workload {args[0]}"),
        };
        Console.WriteLine(count.ToString(System.Globalization.CultureInfo.InvariantCulture));
        return 0;
    }

    /// <summary>Opened as the CLI opens a dat: a random-access file stream under the one reader.</summary>
    public static DatDatabase Open(string dir)
    {
        var path = Directory.Exists(dir) ? Path.Combine(dir, "client_portal.dat") : dir;
        return DatDatabase.Open(new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read, 1 << 16, FileOptions.RandomAccess), Path.GetFileName(path));
    }

    /// <summary>
    /// The floor: every Setup `batch --all` exports and every GfxObj its parts name, read and decoded once
    /// through the dat layer (IDatSource) and discarded. Nothing that uses the same reader can be faster.
    /// </summary>
    public static long Floor(IDatSource dat, int jobs)
    {
        long parts = 0;
        Parallel.ForEach(dat.ListIds(DatObjectKind.Setup), new ParallelOptions { MaxDegreeOfParallelism = jobs }, id =>
        {
            var setup = dat.ReadSetup(id);
            if (setup is null) return;
            foreach (var part in setup.Parts)
                if (dat.ReadGfxObj(part) is not null) Interlocked.Increment(ref parts);
        });
        return parts;
    }

    /// <summary>
    /// What a user writes in an afternoon: a loop that serialises each Setup and each GfxObj with a
    /// PhysicsBSP its parts name (once) with System.Text.Json's reflection defaults, to one file each.
    /// Fields included (Vector3 and Quaternion are fields), the depth limit raised (BSP trees are deep) and
    /// animation hooks (whose constructor takes a span) written by a small converter, because without them the output is empty or the
    /// serialiser throws: the three fixes the first run of such a loop asks for.
    /// </summary>
    public static long Naive(IDatSource dat, string outDir)
    {
        var options = new JsonSerializerOptions { IncludeFields = true, MaxDepth = 1024, Converters = { new HookConverter() } };
        Directory.CreateDirectory(Path.Combine(outDir, "setups"));
        Directory.CreateDirectory(Path.Combine(outDir, "gfxobjs"));
        var done = new HashSet<uint>();
        long files = 0;
        foreach (var id in dat.ListIds(DatObjectKind.Setup))
        {
            var setup = dat.ReadSetup(id);
            if (setup is null) continue;
            File.WriteAllText(Path.Combine(outDir, "setups", $"0x{id:X8}.json"), JsonSerializer.Serialize(setup, options));
            files++;
            foreach (var part in setup.Parts)
            {
                if (!done.Add(part)) continue;
                var gfx = dat.ReadGfxObj(part);
                if (gfx?.PhysicsBsp is null) continue;
                File.WriteAllText(Path.Combine(outDir, "gfxobjs", $"0x{part:X8}.json"), JsonSerializer.Serialize(gfx, options));
                files++;
            }
        }
        return files;
    }

    private sealed class HookConverter : System.Text.Json.Serialization.JsonConverter<AcShadow.Core.Dat.Objects.AnimationHook>
    {
        public override AcShadow.Core.Dat.Objects.AnimationHook Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options) =>
            throw new NotSupportedException("the naive exporter only writes");

        public override void Write(Utf8JsonWriter writer, AcShadow.Core.Dat.Objects.AnimationHook value, JsonSerializerOptions options)
        {
            writer.WriteStartObject();
            writer.WriteNumber("Type", (uint)value.Type);
            writer.WriteNumber("Direction", value.Direction);
            writer.WriteBase64String("Payload", value.Payload.Span);
            writer.WriteEndObject();
        }
    }
}
