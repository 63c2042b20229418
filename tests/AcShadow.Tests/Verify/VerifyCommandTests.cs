using AcShadow.Tests.Support;
using static AcShadow.Tests.Batch.BatchRuns;

namespace AcShadow.Tests.Verify;

public class VerifyCommandTests
{
    private const string Door = "setups/0x020019FF.shadow.json";

    private static TempDir Fixtures(params string[] args)
    {
        var (run, dir) = RunBatch(args);
        Assert.Equal(0, run.ExitCode);
        return dir;
    }

    [Fact]
    public void A_fresh_batch_verifies()
    {
        using var dir = Fixtures("--doors", "--all", "--landblock", "0xA9B4");
        var run = CliRun.Of("verify", "--fixtures", dir.Path);
        Assert.Equal(0, run.ExitCode);
        Assert.Contains("matches a fresh regeneration", run.Out);
    }

    [Fact]
    public void A_changed_field_is_named_with_file_path_and_both_values()
    {
        using var dir = Fixtures("--doors");
        var path = Path.Combine(dir.Path, Door);
        File.WriteAllText(path, File.ReadAllText(path).Replace("\"radius\": 0.141,", "\"radius\": 0.15,"));
        var run = CliRun.Of("verify", "--fixtures", dir.Path);
        Assert.Equal(5, run.ExitCode);
        Assert.Contains($"changed {Door}", run.Out);
        Assert.Contains($"{Door}: $.setup.radius: 0.15 → 0.141", run.Out);
        Assert.Contains("drifted: 1 changed, 0 missing, 0 extra", Assert.Single(run.ErrorLines, l => !l.Contains("SYNTHETIC")));
    }

    [Fact]
    public void Missing_extra_and_non_json_files_are_reported()
    {
        using var dir = Fixtures("--doors");
        File.Delete(Path.Combine(dir.Path, "gfxobjs/0x010044B5.bsp.json"));
        File.WriteAllText(Path.Combine(dir.Path, "setups/0x02009999.shadow.json"), "{}\n");
        File.WriteAllText(Path.Combine(dir.Path, Door), "not json");
        File.WriteAllText(Path.Combine(dir.Path, "setups/0x0200024F.shadow.json.4242.tmp"), "partial"); // an interrupted write
        var run = CliRun.Of("verify", "--fixtures", dir.Path);
        Assert.Equal(5, run.ExitCode);
        Assert.Contains("missing gfxobjs/0x010044B5.bsp.json", run.Out);
        Assert.Contains("extra setups/0x02009999.shadow.json", run.Out);
        Assert.Contains($"changed {Door}\n  (not JSON", run.Out.Replace("\r", ""));
        Assert.DoesNotContain(".tmp", run.Out);
    }

    [Fact]
    public void A_stale_or_missing_cell_file_is_drift()
    {
        using var dir = Fixtures("--landblock", "0xA9B4");
        var cells = Path.Combine(dir.Path, "cells");
        var written = Directory.GetFiles(cells, "*.cell.json").Order(StringComparer.Ordinal).ToArray();
        Assert.NotEmpty(written);
        // A cell a previous run wrote (or a `--no-cells` re-run left behind) that regeneration does not give.
        File.WriteAllText(Path.Combine(cells, "0xA9B401FF.cell.json"), "{}\n");
        File.Delete(written[0]);
        var run = CliRun.Of("verify", "--fixtures", dir.Path);
        Assert.Equal(5, run.ExitCode);
        Assert.Contains("extra cells/0xA9B401FF.cell.json", run.Out);
        Assert.Contains($"missing cells/{Path.GetFileName(written[0])}", run.Out);
        Assert.Contains("0 changed, 1 missing, 1 extra", Assert.Single(run.ErrorLines, l => !l.Contains("SYNTHETIC")));
    }

    [Fact]
    public void A_different_dat_is_drift_even_when_the_files_agree()
    {
        using var dats = SampleDat.WriteToTempFolder();
        using var dir = Fixtures("--all", "--dat", dats.Path);
        Assert.Equal(0, CliRun.Of("verify", "--fixtures", dir.Path, "--dat", dats.Path).ExitCode);
        // The same objects in a dat of another iteration: other bytes, so another dat.
        using var other = new TempDir();
        File.WriteAllBytes(Path.Combine(other.Path, "client_portal.dat"), AcShadow.Forging.SpecCompiler.Compile(AcShadow.Forging.SampleDats.Spec with { Iteration = 2 }).Portal);
        var run = CliRun.Of("verify", "--fixtures", dir.Path, "--dat", other.Path);
        Assert.Equal(5, run.ExitCode);
        Assert.Contains("dat differs from the one index.json records: dat content: SHA-256 ", run.Out);
        Assert.Contains("dat differs from the one index.json records: dat iteration: 1 → 2", run.Out);
        Assert.Contains("index.json: $.inputs.dat.sha256", run.Out);
        Assert.DoesNotContain(Door, run.Out);
    }

    [Fact]
    public void A_byte_identical_dat_under_another_name_is_the_same_dat()
    {
        using var dats = SampleDat.WriteToTempFolder();
        using var dir = Fixtures("--all", "--dat", dats.Path);
        var run = CliRun.Of("verify", "--fixtures", dir.Path); // the built-in sample: the same bytes, named sample/client_portal.dat
        Assert.True(run.ExitCode == 0, run.Out + run.Error);
        Assert.Contains("\"sha256\": \"" + Convert.ToHexStringLower(System.Security.Cryptography.SHA256.HashData(SampleDat.PortalBytes)) + "\"",
            File.ReadAllText(Path.Combine(dir.Path, "index.json")));
    }

    [Fact]
    public void Inputs_come_from_the_index_policy_scale_and_a_setups_file_that_is_gone()
    {
        var (idsDir, idsPath) = SetupsFile("0x020019FF\n0x02001000\n");
        using var dir = Fixtures("--setups", idsPath, "--policy", "union", "--scale", "1.5");
        idsDir.Dispose();
        var run = CliRun.Of("verify", "--fixtures", dir.Path);
        Assert.Equal(0, run.ExitCode);
        Assert.Contains("\"policy\": \"union\"", File.ReadAllText(Path.Combine(dir.Path, Door)));
    }

    [Fact]
    public void A_scene_needs_the_cell_dat_when_a_dat_is_given()
    {
        using var dats = SampleDat.WriteToTempFolder();
        using var dir = Fixtures("--landblock", "0xA9B4", "--dat", dats.Path, "--cell-dat", dats.Path);
        Assert.Equal(0, CliRun.Of("verify", "--fixtures", dir.Path, "--dat", dats.Path, "--cell-dat", dats.Path).ExitCode);
        // The folder --dat names holds the cell dat too: found there (issue 32 item 16).
        Assert.Equal(0, CliRun.Of("verify", "--fixtures", dir.Path, "--dat", dats.Path).ExitCode);
        // The portal dat's file alone gives no cell dat.
        var run = CliRun.Of("verify", "--fixtures", dir.Path, "--dat", Path.Combine(dats.Path, "client_portal.dat"));
        Assert.Equal(2, run.ExitCode);
        Assert.Contains("pass --cell-dat", Assert.Single(run.ErrorLines));
    }

    [Fact]
    public void An_unreadable_dat_or_a_missing_landblock_exit_with_their_codes()
    {
        using var dir = Fixtures("--doors", "--landblock", "0xA9B4");
        var noDat = CliRun.Of("verify", "--fixtures", dir.Path, "--dat", "/nonexistent/client_portal.dat");
        Assert.Equal(3, noDat.ExitCode);
        Assert.Contains("does not exist", Assert.Single(noDat.ErrorLines));

        var index = Path.Combine(dir.Path, "index.json");
        File.WriteAllText(index, File.ReadAllText(index).Replace("\"landblock\": \"0xA9B4FFFE\"", "\"landblock\": \"0x0101FFFE\""));
        var noLandblock = CliRun.Of("verify", "--fixtures", dir.Path);
        Assert.Equal(4, noLandblock.ExitCode);
        Assert.Contains("landblock 0x0101 has no LandBlockInfo", Assert.Single(noLandblock.ErrorLines, l => !l.Contains("SYNTHETIC")));
        Assert.Equal("", noLandblock.Out);
    }

    [Theory]
    [InlineData("no-folder", 2, "is not a folder")]
    [InlineData("empty", 2, "has no index.json")]
    [InlineData("not-json", 2, "is not a batch index: not JSON")]
    [InlineData("wrong-format", 2, "$.format is \"acshadow.shadow/1\"")]
    [InlineData("no-policy", 2, "$.inputs.policy is missing")]
    public void Bad_fixture_folders_exit_with_a_usage_error_and_write_nothing(string kind, int code, string message)
    {
        using var root = new TempDir();
        var folder = Path.Combine(root.Path, "fixtures");
        if (kind != "no-folder") Directory.CreateDirectory(folder);
        var index = Path.Combine(folder, "index.json");
        switch (kind)
        {
            case "not-json": File.WriteAllText(index, "{"); break;
            case "wrong-format": File.WriteAllText(index, """{"format": "acshadow.shadow/1"}"""); break;
            case "no-policy": File.WriteAllText(index, """{"format": "acshadow.index/1", "inputs": {"dat": {}}}"""); break;
        }
        var before = root.Files();
        var run = CliRun.Of("verify", "--fixtures", folder);
        Assert.Equal(code, run.ExitCode);
        Assert.Contains(message, Assert.Single(run.ErrorLines));
        Assert.Equal(before, root.Files());
        Assert.Equal("", run.Out);
    }
}
