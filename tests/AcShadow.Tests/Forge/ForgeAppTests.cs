using AcShadow.Forge;
using AcShadow.Forging;

namespace AcShadow.Tests.Forge;

/// <summary>The forge CLI, run in-process: exit codes, one-line errors, nothing written on failure.</summary>
public sealed class ForgeAppTests : IDisposable
{
    private readonly string _dir = ForgedFiles.NewDirectory();

    private sealed record Result(int Code, string Out, string Err)
    {
        public string[] ErrLines => Err.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        public string[] OutLines => Out.Split('\n', StringSplitOptions.RemoveEmptyEntries);
    }

    private static Result Forge(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        var code = ForgeApp.Run(args, stdout, stderr);
        return new Result(code, stdout.ToString(), stderr.ToString());
    }

    private string SpecFile(string json)
    {
        var path = Path.Combine(_dir, "spec.json");
        File.WriteAllText(path, json);
        return path;
    }

    private string Out => Path.Combine(_dir, "out");

    [Fact]
    public void Build_of_a_bad_spec_exits_2_prints_one_line_and_writes_nothing()
    {
        var spec = SpecFile("""{ "gfxObjs": [], "setups": [ { "id": "0x02000010", "parts": ["0x0100ABCD"] } ], "landblocks": [] }""");
        var result = Forge("build", spec, "--out", Out);
        Assert.Equal(2, result.Code);
        var line = Assert.Single(result.ErrLines);
        Assert.Equal("forge: setups[0] (0x02000010): part 0x0100ABCD is not a gfxObj in this spec (declare it, or list it in missingParts)", line.TrimEnd());
        Assert.Equal("", result.Out);
        Assert.False(Directory.Exists(Out) && Directory.EnumerateFileSystemEntries(Out).Any());
    }

    [Fact]
    public void Build_of_malformed_json_exits_2_with_one_line()
    {
        var result = Forge("build", SpecFile("{ \"gfxObjs\": [ "), "--out", Out);
        Assert.Equal(2, result.Code);
        Assert.Contains("malformed JSON", Assert.Single(result.ErrLines));
        Assert.False(Directory.Exists(Out));
    }

    [Fact]
    public void Build_of_a_missing_file_exits_2()
    {
        var result = Forge("build", Path.Combine(_dir, "nope.json"), "--out", Out);
        Assert.Equal(2, result.Code);
        Assert.Contains("cannot read the spec", Assert.Single(result.ErrLines));
    }

    [Fact]
    public void Bad_arguments_exit_2_with_one_line()
    {
        Assert.Equal(2, Forge().Code);
        var noOut = Forge("sample");
        Assert.Equal(2, noOut.Code);
        Assert.Single(noOut.ErrLines);
        var badNumber = Forge("scale", "--out", Out, "--setups", "0");
        Assert.Equal(2, badNumber.Code);
        Assert.Single(badNumber.ErrLines);
        Assert.Equal(2, Forge("scale", "--out", Out, "--setups", "many").Code);
        Assert.Equal(2, Forge("frobnicate").Code);
    }

    [Fact]
    public void Verbose_adds_the_stack_trace()
    {
        var spec = SpecFile("""{ "gfxObjs": [ { "id": "bad" } ] }""");
        var result = Forge("build", spec, "--out", Out, "--verbose");
        Assert.Equal(2, result.Code);
        Assert.True(result.ErrLines.Length > 1);
    }

    [Fact]
    public void Build_writes_one_line_per_file_and_only_the_dats()
    {
        var spec = SpecFile("""
            { "gfxObjs": [ { "id": "0x01000001", "physics": true, "vertices": [[0,0,0],[1,0,0],[0,1,0]], "polygons": [ { "vertices": [0,1,2] } ] } ],
              "setups": [ { "id": "0x02000001", "parts": ["0x01000001"] } ],
              "landblocks": [ { "id": "0x0101FFFE", "objects": [ { "id": "0x02000001" } ] } ] }
            """);
        var result = Forge("build", spec, "--out", Out);
        Assert.Equal(0, result.Code);
        Assert.Equal("", result.Err);
        Assert.Equal(2, result.OutLines.Length);
        Assert.Contains("client_portal.dat", result.OutLines[0]);
        Assert.Contains("1 GfxObjs, 1 Setups", result.OutLines[0]);
        Assert.Contains("client_cell_1.dat", result.OutLines[1]);
        Assert.Equal([ForgeApp.CellFileName, ForgeApp.PortalFileName], Directory.GetFiles(Out).Select(Path.GetFileName).Order());
    }

    [Fact]
    public void Sample_can_regenerate_its_spec_and_the_result_builds_the_same_dats()
    {
        var specPath = Path.Combine(_dir, "sample.json");
        var result = Forge("sample", "--out", Out, "--write-spec", specPath);
        Assert.Equal(0, result.Code);
        Assert.Equal(SampleDats.Json, File.ReadAllText(specPath));
        var rebuilt = Forge("build", specPath, "--out", Path.Combine(_dir, "rebuilt"));
        Assert.Equal(0, rebuilt.Code);
        Assert.Equal(File.ReadAllBytes(Path.Combine(Out, ForgeApp.PortalFileName)), File.ReadAllBytes(Path.Combine(_dir, "rebuilt", ForgeApp.PortalFileName)));
    }

    [Fact]
    public void Existing_files_are_replaced_whole_and_no_temp_file_remains()
    {
        Directory.CreateDirectory(Out);
        File.WriteAllText(Path.Combine(Out, ForgeApp.PortalFileName), "old");
        Assert.Equal(0, Forge("sample", "--out", Out).Code);
        Assert.Equal(SampleDats.Build().Portal, File.ReadAllBytes(Path.Combine(Out, ForgeApp.PortalFileName)));
        Assert.Equal(2, Directory.GetFiles(Out).Length);
    }

    public void Dispose()
    {
        try { Directory.Delete(_dir, recursive: true); } catch (IOException) { }
    }
}
