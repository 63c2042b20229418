using System.Text.Json;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures;
using AcShadow.Tests.Fixtures;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Schemas;

/// <summary>
/// Every JSON file the tool writes validates against its schema under schemas/, and carries the format
/// its schema names (acdream's files excepted: acdream fixes their fields and they have no format field).
/// </summary>
public sealed class SchemaValidationTests : IClassFixture<SchemaValidationTests.Outputs>
{
    private readonly Outputs _outputs;

    public SchemaValidationTests(Outputs outputs) => _outputs = outputs;

    /// <summary>What a user gets from dump, batch (both formats, with a scene) audit --format json (doors, with the chart columns), doctor and move (the door and the static) on the sample.</summary>
    public sealed class Outputs : IDisposable
    {
        public TempDir Dir { get; } = new();

        public Outputs()
        {
            Run("dump", "--setup", "0x020019FF", "--format", "both", "--out", Path.Combine(Dir.Path, "dump"));
            Run("batch", "--doors", "--all", "--landblock", "0xA9B4", "--format", "both", "--out", Path.Combine(Dir.Path, "batch"), "--quiet");
            Run("audit", "--doors", "--chart", "--format", "json", "--out", Path.Combine(Dir.Path, "audit.json"));
            Run("doctor", "--out", Path.Combine(Dir.Path, "doctor.json"));
            Run("move", "--setup", "0x020019FF", "--out", Path.Combine(Dir.Path, "move"));
            Run("move", "--setup", "0x02003000", "--out", Path.Combine(Dir.Path, "move"));
        }

        private static void Run(params string[] args)
        {
            var run = CliRun.Of(args);
            if (run.ExitCode != 0) throw new InvalidOperationException($"{string.Join(' ', args)}: exit {run.ExitCode}: {run.Error}");
        }

        public void Dispose() => Dir.Dispose();
    }

    internal static string SchemasFolder() => Path.Combine(Path.GetDirectoryName(CommittedFixturesTests.RepositoryFixtures())!, "schemas");

    internal static SchemaValidator LoadSchemas()
    {
        var validator = new SchemaValidator();
        foreach (var file in Directory.GetFiles(SchemasFolder(), "*.schema.json"))
        {
            using var doc = JsonDocument.Parse(File.ReadAllText(file));
            validator.Add(doc.RootElement);
        }
        return validator;
    }

    internal static FileFormat FormatOf(string path)
    {
        var name = Path.GetFileName(path);
        var kind = name switch
        {
            _ when name.EndsWith(".shadow.json") => "shadow",
            _ when name.EndsWith(".bsp.json") => "bsp",
            _ when name.EndsWith(".gfxobj.json") => "acdream",
            _ when name.EndsWith(".cell.json") => "cell",
            _ when name.EndsWith(".movement.json") => "movement",
            _ when Path.GetFileName(Path.GetDirectoryName(path)) == "cells" => "acdream-cell",
            "scene.json" => "scene",
            "compiled-scene.json" => "compiled-scene",
            "index.json" => "index",
            "audit.json" => "audit",
            "doctor.json" => "doctor",
            _ => throw new InvalidOperationException($"no format for {path}"),
        };
        return FileFormats.All.Single(f => f.Name == kind);
    }

    [Fact]
    public void Every_format_has_a_schema_whose_id_and_format_match()
    {
        var files = Directory.GetFiles(SchemasFolder(), "*.schema.json");
        Assert.Equal(FileFormats.All.Count, files.Length);
        foreach (var format in FileFormats.All)
        {
            var file = files.Single(f => JsonDocument.Parse(File.ReadAllText(f)).RootElement.GetProperty("$id").GetString() == format.SchemaId);
            using var doc = JsonDocument.Parse(File.ReadAllText(file));
            Assert.Equal("https://json-schema.org/draft/2020-12/schema", doc.RootElement.GetProperty("$schema").GetString());
            if (format.Name is "acdream" or "acdream-cell")
                Assert.False(doc.RootElement.GetProperty("properties").TryGetProperty("format", out _));
            else
                Assert.Equal(format.Format, doc.RootElement.GetProperty("properties").GetProperty("format").GetProperty("const").GetString());
        }
    }

    [Fact]
    public void Every_file_the_tool_writes_validates_against_its_schema_and_names_its_format()
    {
        var validator = LoadSchemas();
        var files = Directory.GetFiles(_outputs.Dir.Path, "*.json", SearchOption.AllDirectories);
        Assert.Equal(["acdream", "acdream-cell", "audit", "bsp", "cell", "doctor", "index", "movement", "scene", "shadow"], files.Select(f => FormatOf(f).Name).Distinct().Order());
        foreach (var file in files)
        {
            var format = FormatOf(file);
            using var doc = JsonDocument.Parse(File.ReadAllText(file));
            var errors = validator.Validate(doc.RootElement, format.SchemaId!);
            Assert.True(errors.Count == 0, $"{file}:\n{string.Join('\n', errors.Take(10))}");
            if (format.Name is not ("acdream" or "acdream-cell")) Assert.Equal(format.Format, doc.RootElement.GetProperty("format").GetString());
        }
    }

    [Fact]
    public void The_committed_fixtures_validate()
    {
        var validator = LoadSchemas();
        foreach (var file in Directory.GetFiles(CommittedFixturesTests.RepositoryFixtures(), "*.json", SearchOption.AllDirectories))
        {
            using var doc = JsonDocument.Parse(File.ReadAllText(file));
            var errors = validator.Validate(doc.RootElement, FormatOf(file).SchemaId!);
            Assert.True(errors.Count == 0, $"{file}:\n{string.Join('\n', errors.Take(10))}");
        }
    }

    [Theory]
    [InlineData("dump/setups/0x020019FF.shadow.json", "\"format\": \"acshadow.shadow/2\"", "\"format\": \"acshadow.shadow/1\"", "/format: const:")]
    [InlineData("dump/setups/0x020019FF.shadow.json", "\"collisionType\": \"bsp\"", "\"collisionType\": \"box\"", "/shapes/0/collisionType: enum:")]
    [InlineData("dump/gfxobjs/0x010044B5.bsp.json", "\"gfxObjId\": \"0x010044B5\"", "\"gfxObjId\": \"0x10044B5\"", "/gfxObjId: pattern:")]
    [InlineData("dump/gfxobjs/0x010044B5.gfxobj.json", "\"NumPoints\": 4", "\"NumPoints\": \"4\"", "/NumPoints: type:")]
    [InlineData("dump/gfxobjs/0x010044B5.gfxobj.json", "\"GfxObjId\": 16794805", "\"GfxObjId\": 16794805, \"format\": \"x\"", "/format: : All values fail against the false schema")]
    [InlineData("batch/index.json", "\"kind\": \"acdream\"", "\"kind\": \"gfxobj\"", ": enum:")]
    [InlineData("batch/scene.json", "\"landblockId\": \"0xA9B4FFFE\",", "", ": required:")]
    [InlineData("move/movement/0x020019FF.movement.json", "\"class\": \"blocked\"", "\"class\": \"stopped\"", ": enum:")]
    public void A_file_that_breaks_its_schema_is_reported(string file, string from, string to, string expected)
    {
        var validator = LoadSchemas();
        var text = File.ReadAllText(Path.Combine(_outputs.Dir.Path, file));
        Assert.Contains(from, text);
        using var doc = JsonDocument.Parse(text.Replace(from, to));
        var errors = validator.Validate(doc.RootElement, FormatOf(file).SchemaId!);
        Assert.Contains(errors, e => e.Contains(expected));
    }
}
