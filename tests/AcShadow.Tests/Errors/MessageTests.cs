using System.Text;
using System.Text.Json.Nodes;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Errors;

/// <summary>
/// Issue 32 item 18: messages a new user trips on, each one line that says what is wrong in the user's terms.
/// </summary>
public class MessageTests
{
    private static string Line(CliRun run) => Assert.Single(run.ErrorLines, l => l.StartsWith("acshadow: ", StringComparison.Ordinal) && !l.Contains("SYNTHETIC", StringComparison.Ordinal));

    [Theory]
    [InlineData("doctor", "doctor.json")]
    [InlineData("audit", "audit.csv")]
    public void An_empty_report_path_asks_for_a_file_name_not_a_folder(string command, string example)
    {
        var run = CliRun.Of(command, "--out", "");
        Assert.Equal(2, run.ExitCode);
        Assert.Equal($"acshadow: --out: the path is empty: pass a file name (e.g. --out {example})", Line(run));
    }

    [Theory]
    [InlineData("chart")]
    [InlineData("scene")]
    public void A_refused_spacing_names_its_option(string command)
    {
        using var dir = new TempDir();
        string[] what = command == "chart" ? ["--setup", "0x020019FF"] : ["--landblock", "0xA9B4"];
        var run = CliRun.Of([command, .. what, "--spacing", "1e-9", "--out", Path.Combine(dir.Path, "out")]);
        Assert.Equal(2, run.ExitCode);
        Assert.StartsWith("acshadow: --spacing: spacing must be at least 0.01 m", Line(run));
    }

    [Fact]
    public void A_landblock_id_given_as_a_cell_says_it_is_a_landblock()
    {
        using var dir = new TempDir();
        var run = CliRun.Of("dump", "--cell", "0xA9B4", "--out", dir.Path);
        Assert.Equal(2, run.ExitCode);
        Assert.Contains("--cell: 0xA9B4 is a landblock id (0xXXYY), not a cell's: its indoor cells are 0xA9B40100 and up", Line(run));
    }

    /// <summary>A compiled scene of the sample landblock, edited by <paramref name="edit"/>, viewed: exit 2 and the reason.</summary>
    private static string ViewEditedScene(Action<JsonNode> edit)
    {
        using var dir = new TempDir();
        var scene = Path.Combine(dir.Path, "scene");
        Assert.Equal(0, CliRun.Of("scene", "--landblock", "0xA9B4", "--out", scene, "--quiet").ExitCode);
        var path = Path.Combine(scene, "compiled-scene.json");
        var json = JsonNode.Parse(File.ReadAllText(path))!;
        edit(json);
        File.WriteAllText(path, json.ToJsonString());
        var run = CliRun.Of("view", "--scene", scene, "--out", Path.Combine(dir.Path, "view"));
        Assert.Equal(2, run.ExitCode);
        Assert.False(Directory.Exists(Path.Combine(dir.Path, "view")) && Directory.GetFiles(Path.Combine(dir.Path, "view"), "*.svg").Length > 0);
        return Line(run);
    }

    private static JsonNode Hull(JsonNode scene) =>
        scene["objects"]!.AsArray().SelectMany(o => o!["shapes"]!.AsArray()).First(s => (string?)s!["type"] == "hull")!;

    [Fact]
    public void A_null_hull_vertex_is_named_not_a_raw_runtime_message()
    {
        var line = ViewEditedScene(scene => Hull(scene)["vertices"]!.AsArray()[0] = null);
        Assert.Contains("a vector is an array of 3 numbers, not null", line);
        Assert.DoesNotContain("requested operation", line);
    }

    [Theory]
    [InlineData(0.0)]
    [InlineData(-1.0)]
    public void A_hull_scaled_by_zero_or_less_is_refused(double scale)
    {
        var line = ViewEditedScene(scene => Hull(scene)["pose"]!["scale"] = scale);
        Assert.Contains("a part's pose scale must be a positive number", line);
    }

    [Fact]
    public void A_zero_quaternion_is_refused()
    {
        var line = ViewEditedScene(scene =>
        {
            var orientation = scene["objects"]![0]!["landblockFrame"]!["orientation"]!;
            foreach (var axis in new[] { "x", "y", "z", "w" }) orientation[axis] = 0;
        });
        Assert.Contains("must be a unit quaternion (length 1), not one of length 0", line);
    }

    [Fact]
    public void A_shadow_file_named_for_another_setup_is_refused_by_view()
    {
        using var dir = new TempDir();
        var fixtures = Path.Combine(dir.Path, "fixtures");
        Assert.Equal(0, CliRun.Of("dump", "--setup", "0x020019FF", "--out", fixtures).ExitCode);
        File.Copy(Path.Combine(fixtures, "setups", "0x020019FF.shadow.json"), Path.Combine(fixtures, "setups", "0x02000001.shadow.json"));
        var run = CliRun.Of("view", "--fixtures", fixtures, "--out", Path.Combine(dir.Path, "view"));
        Assert.Equal(2, run.ExitCode);
        Assert.Contains("holds Setup 0x020019FF, not the 0x02000001 its name says", Line(run));
    }

    /// <summary>A batch of the sample's doors with one shadow file rewritten by <paramref name="rewrite"/>; verify's output.</summary>
    private static CliRun VerifyRewritten(Func<byte[], byte[]> rewrite)
    {
        using var dats = SampleDat.WriteToTempFolder();
        var fixtures = Path.Combine(dats.Path, "fixtures");
        Assert.Equal(0, CliRun.Of("batch", "--doors", "--dat", dats.Path, "--out", fixtures, "--quiet").ExitCode);
        var shadow = Path.Combine(fixtures, "setups", "0x020019FF.shadow.json");
        File.WriteAllBytes(shadow, rewrite(File.ReadAllBytes(shadow)));
        var run = CliRun.Of("verify", "--fixtures", fixtures, "--dat", dats.Path);
        Assert.Equal(5, run.ExitCode);
        return run;
    }

    [Fact]
    public void A_fixture_with_its_keys_reordered_is_changed_with_a_reason()
    {
        var run = VerifyRewritten(bytes =>
        {
            var json = JsonNode.Parse(bytes)!.AsObject();
            var reordered = new JsonObject();
            foreach (var (key, value) in json.Reverse().ToArray())
            {
                json.Remove(key);
                reordered[key] = value;
            }
            return Encoding.UTF8.GetBytes(reordered.ToJsonString());
        });
        Assert.Contains("changed setups/0x020019FF.shadow.json: the same JSON values laid out differently (key order", run.Out);
    }

    [Fact]
    public void A_fixture_with_a_byte_order_mark_is_read_as_the_library_reads_it()
    {
        var run = VerifyRewritten(bytes => [0xEF, 0xBB, 0xBF, .. bytes]);
        Assert.Contains("changed setups/0x020019FF.shadow.json: it starts with a UTF-8 byte-order mark", run.Out);
        Assert.DoesNotContain("not JSON", run.Out);
    }
}
