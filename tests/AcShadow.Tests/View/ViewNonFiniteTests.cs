using AcShadow.Tests.Fixtures;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.View;

/// <summary>
/// Issue 32 items 8 and 9: view meets non-finite and absurd numbers as the rest of acshadow does, with the
/// documented <c>non-finite</c> warning (or <c>too-far-to-draw</c>) and exit 0, never "internal error"; the
/// shape is left out, the drawing stays valid and says why. And the committed glbs pass the Khronos validator.
/// </summary>
public sealed class ViewNonFiniteTests
{
    private static string Fixtures(TempDir dir, Func<string, string> edit)
    {
        var source = CommittedFixturesTests.RepositoryFixtures();
        var folder = Path.Combine(dir.Path, "fixtures");
        foreach (var f in new[] { "setups/0x020019FF.shadow.json", "gfxobjs/0x010044B5.bsp.json", "gfxobjs/0x010044B6.bsp.json" })
        {
            Directory.CreateDirectory(Path.GetDirectoryName(Path.Combine(folder, f))!);
            var text = File.ReadAllText(Path.Combine(source, f));
            File.WriteAllText(Path.Combine(folder, f), f.StartsWith("setups/", StringComparison.Ordinal) ? edit(text) : text);
        }
        return folder;
    }

    [Theory]
    [InlineData("{\"center\": [0, 0, 0.018], \"radius\": null}", "non-finite")]
    [InlineData("{\"center\": [3.4e38, 0, 0.018], \"radius\": 0.1}", "too-far-to-draw")]
    public void A_null_or_absurd_sphere_is_a_warning_and_the_drawing_stays_valid(string sphere, string code)
    {
        using var dir = new TempDir();
        var folder = Fixtures(dir, json => json.Replace("{\"center\": [0, 0, 0.018], \"radius\": 0.1}", sphere));
        var output = Path.Combine(dir.Path, "out");
        var run = CliRun.Of("view", "--fixtures", folder, "--setup", "0x020019FF", "--out", output);
        Assert.True(run.ExitCode == 0, $"exit {run.ExitCode}: {run.Error}");
        Assert.Contains(run.ErrorLines, l => l.StartsWith("warning: ", StringComparison.Ordinal) && l.Contains($": {code}: ", StringComparison.Ordinal));
        var svg = File.ReadAllText(Path.Combine(output, "0x020019FF.svg"));
        Assert.DoesNotContain("=\"\"", svg);
        Assert.Contains("warning: ", svg);
        Assert.Contains(code, svg);
        GltfValidator.AssertValid(output);
        // A second run into the same folder is not refused.
        Assert.Equal(0, CliRun.Of("view", "--fixtures", folder, "--setup", "0x020019FF", "--out", output).ExitCode);
    }

    [Fact]
    public void A_landblock_object_at_a_null_position_is_left_out_with_a_warning_and_the_rest_is_drawn()
    {
        using var dir = new TempDir();
        var folder = Path.Combine(dir.Path, "fixtures");
        var source = CommittedFixturesTests.RepositoryFixtures();
        foreach (var file in Directory.GetFiles(source, "*", SearchOption.AllDirectories))
        {
            var target = Path.Combine(folder, Path.GetRelativePath(source, file));
            Directory.CreateDirectory(Path.GetDirectoryName(target)!);
            File.Copy(file, target);
        }
        var scene = Path.Combine(folder, "scene.json");
        var json = File.ReadAllText(scene);
        Assert.Contains("\"origin\": [136, 108, 12]", json);
        File.WriteAllText(scene, json.Replace("\"origin\": [136, 108, 12]", "\"origin\": [null, 108, 12]"));
        var output = Path.Combine(dir.Path, "out");
        var run = CliRun.Of("view", "--fixtures", folder, "--landblock", "0xA9B4", "--out", output);
        Assert.True(run.ExitCode == 0, $"exit {run.ExitCode}: {run.Error}");
        Assert.Contains(run.ErrorLines, l => l.StartsWith("warning: #0 Setup 0x020019FF: non-finite: ", StringComparison.Ordinal));
        var svg = File.ReadAllText(Path.Combine(output, "0xA9B4.svg"));
        Assert.Contains("warning: #0 Setup 0x020019FF: non-finite: its placement frame is not finite: not drawn", svg);
        Assert.Contains("#3 GfxObj 0x01005000", svg);
        GltfValidator.AssertValid(output);
    }

    [ValidatorFact]
    public void The_committed_glbs_pass_the_Khronos_glTF_validator_with_no_error_or_warning()
    {
        var (exit, output) = GltfValidator.Run(Path.Combine(RepositoryRoot.Path, "docs", "view"));
        Assert.True(exit == 0, output);
        Assert.Contains("validated 3 glb file(s)", output);
    }
}
