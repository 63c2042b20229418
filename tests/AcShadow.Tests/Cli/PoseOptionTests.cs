using System.Text.Json;
using AcShadow.Files;
using AcShadow.Forge;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Cli;

/// <summary>
/// Issue 32 item 14: the pose options say what they do or refuse. An absent --motion-table is exit 4 (README:
/// an id not in the dat); --state open on a door whose open motion retail refuses is written as retail shows
/// it (closed, not ethereal, with a warning); --state on a non-door or with --pose placement is a usage
/// error, not silence; doctor --out and audit --out take the folder lock like every folder-writing command.
/// </summary>
public class PoseOptionTests
{
    private const string Door = "0x020019FF";

    [Fact]
    public void A_motion_table_the_dat_lacks_is_exit_4()
    {
        using var outDir = new TempDir();
        var run = CliRun.Of("dump", "--setup", Door, "--motion-table", "0x0900FFFF", "--out", outDir.Path);
        Assert.Equal(4, run.ExitCode);
        Assert.Contains("acshadow: --motion-table: MotionTable 0x0900FFFF is not in ", run.Error);
        Assert.Empty(outDir.Files());
    }

    [Fact]
    public void State_open_on_a_door_whose_open_motion_retail_refuses_is_written_closed_with_a_warning()
    {
        using var outDir = new TempDir();
        var id = $"0x{SampleSpecAuthor.SinglePartDoorSetup:X8}";
        var run = CliRun.Of("dump", "--setup", id, "--state", "open", "--out", outDir.Path);
        Assert.Equal(0, run.ExitCode);
        Assert.Contains("retail refuses this door's open motion, so it stays closed", run.Error);
        using var shadow = JsonDocument.Parse(File.ReadAllText(Path.Combine(outDir.Path, "setups", $"{id}.shadow.json")));
        var pose = shadow.RootElement.GetProperty("pose");
        Assert.Equal("closed", pose.GetProperty("doorState").GetString());
        Assert.False(pose.TryGetProperty("ethereal", out var ethereal) && ethereal.GetBoolean());
    }

    [Fact]
    public void State_open_on_a_door_that_opens_is_still_open_and_ethereal()
    {
        using var outDir = new TempDir();
        Assert.Equal(0, CliRun.Of("dump", "--setup", Door, "--state", "open", "--out", outDir.Path).ExitCode);
        using var shadow = JsonDocument.Parse(File.ReadAllText(Path.Combine(outDir.Path, "setups", $"{Door}.shadow.json")));
        Assert.Equal("open", shadow.RootElement.GetProperty("pose").GetProperty("doorState").GetString());
        Assert.True(shadow.RootElement.GetProperty("pose").GetProperty("ethereal").GetBoolean());
    }

    [Fact]
    public void State_open_on_a_setup_that_is_no_door_is_a_usage_error()
    {
        using var outDir = new TempDir();
        var id = $"0x{SampleSpecAuthor.StaticSetup:X8}";
        var run = CliRun.Of("dump", "--setup", id, "--state", "open", "--out", outDir.Path);
        Assert.Equal(2, run.ExitCode);
        Assert.Contains($"--state open: Setup {id} is not a door", run.Error);
        Assert.Empty(outDir.Files());
    }

    [Theory]
    [InlineData("--state", "open")]
    [InlineData("--state", "closed")]
    [InlineData("--motion-table", "0x09000202")]
    public void A_motion_option_with_the_placement_pose_is_a_usage_error(string option, string value)
    {
        using var outDir = new TempDir();
        var run = CliRun.Of("dump", "--setup", Door, "--pose", "placement", option, value, "--out", outDir.Path);
        Assert.Equal(2, run.ExitCode);
        Assert.Contains($"acshadow: {option} {value}", run.Error);
        Assert.Contains("--pose placement", run.Error);
    }

    [Theory]
    [InlineData("doctor", "doctor.json")]
    [InlineData("audit", "audit.csv")]
    public void A_report_is_not_written_into_a_folder_another_run_holds(string command, string name)
    {
        using var dir = new TempDir();
        using var held = FolderLock.TryAcquire(dir.Path)!;
        var target = Path.Combine(dir.Path, name);
        var run = CliRun.Of(command, "--out", target);
        Assert.Equal(6, run.ExitCode);
        Assert.Contains($"another acshadow run is writing into {dir.Path}", run.Error);
        Assert.False(File.Exists(target));
    }
}
