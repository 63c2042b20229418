using System.Text.Json;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Cli;

public class DumpCommandTests
{
    [Fact]
    public void Door_dumps_three_bsp_shapes_under_retail_and_one_dump_per_distinct_gfxobj()
    {
        using var outDir = new TempDir();
        var run = CliRun.Of("dump", "--setup", "0x020019FF", "--out", outDir.Path);
        Assert.Equal(0, run.ExitCode);
        Assert.Equal(["gfxobjs/0x010044B5.bsp.json", "gfxobjs/0x010044B6.bsp.json", "setups/0x020019FF.shadow.json"], outDir.Files());
        Assert.Contains("SYNTHETIC sample", run.Error);
        Assert.Equal(3, run.Out.Split('\n').Count(l => l.StartsWith("wrote ")));
        using var doc = JsonDocument.Parse(File.ReadAllText(Path.Combine(outDir.Path, "setups/0x020019FF.shadow.json")));
        var shapes = doc.RootElement.GetProperty("shapes").EnumerateArray().ToArray();
        Assert.Equal(3, shapes.Length);
        Assert.All(shapes, s => Assert.Equal("bsp", s.GetProperty("collisionType").GetString()));
        Assert.Equal(["0x010044B5", "0x010044B6", "0x010044B6"], shapes.Select(s => s.GetProperty("gfxObjId").GetString()));
    }

    [Fact]
    public void A_second_dump_leaves_identical_files_alone_and_rewrites_changed_ones()
    {
        using var outDir = new TempDir();
        Assert.Equal(0, CliRun.Of("dump", "--setup", "0x020019FF", "--out", outDir.Path).ExitCode);
        var shadow = Path.Combine(outDir.Path, "setups/0x020019FF.shadow.json");
        var bsp = Path.Combine(outDir.Path, "gfxobjs/0x010044B5.bsp.json");
        var past = new DateTime(2020, 1, 1, 0, 0, 0, DateTimeKind.Utc);
        File.SetLastWriteTimeUtc(shadow, past);
        File.SetLastWriteTimeUtc(bsp, past);
        var good = File.ReadAllText(bsp);
        File.WriteAllText(bsp, good.Replace("\"stats\"", "\"statz\""));
        File.SetLastWriteTimeUtc(bsp, past);

        var run = CliRun.Of("dump", "--setup", "0x020019FF", "--out", outDir.Path);

        Assert.Equal(0, run.ExitCode);
        Assert.Equal(past, File.GetLastWriteTimeUtc(shadow));
        Assert.Contains($"unchanged {shadow} (", run.Out);
        Assert.NotEqual(past, File.GetLastWriteTimeUtc(bsp));
        Assert.Equal(good, File.ReadAllText(bsp));
        Assert.Contains($"wrote {bsp} (", run.Out);
    }

    [Fact]
    public void Door_dumps_four_shapes_under_union()
    {
        using var outDir = new TempDir();
        var run = CliRun.Of("dump", "--setup", "020019FF", "--policy", "union", "--out", outDir.Path);
        Assert.Equal(0, run.ExitCode);
        using var doc = JsonDocument.Parse(File.ReadAllText(Path.Combine(outDir.Path, "setups/0x020019FF.shadow.json")));
        var types = doc.RootElement.GetProperty("shapes").EnumerateArray().Select(s => s.GetProperty("collisionType").GetString()!).ToArray();
        Assert.Equal(["cylinder", "bsp", "bsp", "bsp"], types);
    }

    [Fact]
    public void Output_is_byte_identical_across_runs_and_dat_sources()
    {
        using var first = new TempDir();
        using var second = new TempDir();
        using var datFolder = SampleDat.WriteToTempFolder();
        Assert.Equal(0, CliRun.Of("dump", "--setup", "0x020019FF", "--out", first.Path).ExitCode);
        Assert.Equal(0, CliRun.Of("dump", "--setup", "0x020019FF", "--out", second.Path, "--dat", datFolder.Path).ExitCode);
        Assert.Equal(first.Files(), second.Files());
        foreach (var f in first.Files())
            Assert.Equal(File.ReadAllBytes(Path.Combine(first.Path, f)), File.ReadAllBytes(Path.Combine(second.Path, f)));
    }

    [Fact]
    public void Dat_comes_from_the_environment_when_no_option_is_given()
    {
        using var outDir = new TempDir();
        using var datFolder = SampleDat.WriteToTempFolder();
        var datFile = Path.Combine(datFolder.Path, "client_portal.dat");
        var run = CliRun.With(name => name == "ACSHADOW_DAT" ? datFile : null, "dump", "--setup", "0x020019FF", "--out", outDir.Path);
        Assert.Equal(0, run.ExitCode);
        Assert.DoesNotContain("SYNTHETIC", run.Error);
    }

    [Theory]
    [InlineData(2, "'door' is not a Setup id", "--setup", "door")]
    [InlineData(2, "is a GfxObj id, not a Setup id", "--setup", "0x010044B5")]
    [InlineData(2, "outside the Setup range", "--setup", "1234")]
    [InlineData(2, "not a policy", "--setup", "0x020019FF", "--policy", "best")]
    [InlineData(2, "not a positive number", "--setup", "0x020019FF", "--scale", "-1")]
    [InlineData(2, "not a positive number", "--setup", "0x020019FF", "--scale", "abc")]
    [InlineData(2, "--setup", "--policy", "retail")]
    [InlineData(4, "0x0200FFFF is not in", "--setup", "0x0200FFFF")]
    [InlineData(3, "does not exist", "--setup", "0x020019FF", "--dat", "/nonexistent/client_portal.dat")]
    public void Bad_input_exits_with_its_code_one_line_and_no_files(int code, string message, params string[] args)
    {
        using var outDir = new TempDir();
        var run = CliRun.Of(["dump", .. args, "--out", outDir.Path]);
        Assert.Equal(code, run.ExitCode);
        var errors = run.ErrorLines.Where(l => !l.Contains("SYNTHETIC")).ToArray();
        var line = Assert.Single(errors);
        Assert.Contains(message, line);
        Assert.DoesNotContain("   at ", run.Error);
        Assert.Empty(outDir.Files());
    }

    [Fact]
    public void A_file_that_is_not_a_dat_is_refused_with_exit_3()
    {
        using var outDir = new TempDir();
        using var datDir = new TempDir();
        var notDat = Path.Combine(datDir.Path, "client_portal.dat");
        File.WriteAllBytes(notDat, new byte[5000]);
        var run = CliRun.Of("dump", "--setup", "0x020019FF", "--dat", notDat, "--out", outDir.Path);
        Assert.Equal(3, run.ExitCode);
        Assert.Contains("not a readable dat", Assert.Single(run.ErrorLines));
        Assert.Empty(outDir.Files());
    }

    [Fact]
    public void A_cell_dat_passed_as_the_portal_dat_is_named_as_such()
    {
        using var outDir = new TempDir();
        using var datFolder = SampleDat.WriteToTempFolder();
        var run = CliRun.Of("dump", "--setup", "0x020019FF", "--dat", Path.Combine(datFolder.Path, "client_cell_1.dat"), "--out", outDir.Path);
        Assert.Equal(3, run.ExitCode);
        Assert.Contains("is a cell dat, not a portal dat (its header says so): pass client_portal.dat", Assert.Single(run.ErrorLines));
        Assert.Empty(outDir.Files());
    }

    [Fact]
    public void Verbose_adds_the_stack_trace()
    {
        using var outDir = new TempDir();
        using var datDir = new TempDir();
        var notDat = Path.Combine(datDir.Path, "client_portal.dat");
        File.WriteAllBytes(notDat, new byte[5000]);
        var run = CliRun.Of("dump", "--setup", "0x020019FF", "--dat", notDat, "--out", outDir.Path, "--verbose");
        Assert.Equal(3, run.ExitCode);
        Assert.Contains("   at ", run.Error);
    }
}

public class DumpCultureTests
{
    [Fact]
    public void Output_does_not_depend_on_the_current_culture()
    {
        using var invariant = new TempDir();
        using var german = new TempDir();
        var previous = System.Globalization.CultureInfo.CurrentCulture;
        try
        {
            System.Globalization.CultureInfo.CurrentCulture = System.Globalization.CultureInfo.InvariantCulture;
            Assert.Equal(0, CliRun.Of("dump", "--setup", "0x020019FF", "--out", invariant.Path).ExitCode);
            System.Globalization.CultureInfo.CurrentCulture = new System.Globalization.CultureInfo("de-DE");
            Assert.Equal(0, CliRun.Of("dump", "--setup", "0x020019FF", "--out", german.Path).ExitCode);
            // Option values are invariant too: "1.5" means one and a half even where the comma is decimal.
            using var scaled = new TempDir();
            Assert.Equal(0, CliRun.Of("dump", "--setup", "0x020019FF", "--out", scaled.Path, "--scale", "1.5").ExitCode);
            Assert.Contains("\"entityScale\": 1.5,", File.ReadAllText(Path.Combine(scaled.Path, "setups/0x020019FF.shadow.json")));
        }
        finally
        {
            System.Globalization.CultureInfo.CurrentCulture = previous;
        }
        foreach (var f in invariant.Files())
            Assert.Equal(File.ReadAllBytes(Path.Combine(invariant.Path, f)), File.ReadAllBytes(Path.Combine(german.Path, f)));
    }
}
