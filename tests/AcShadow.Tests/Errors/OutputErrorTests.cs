using AcShadow.Core.Json;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Errors;

/// <summary>docs/errors.md, "the output": a folder that cannot be created or written, a full disk, files that are not ours.</summary>
public class OutputErrorTests
{
    public static TheoryData<string> Writers => new() { "dump", "batch", "chart" };

    private static string[] Args(string command, string outDir) => command switch
    {
        "dump" => ["dump", "--setup", "0x020019FF", "--out", outDir],
        "batch" => ["batch", "--doors", "--out", outDir, "--quiet"],
        "chart" => ["chart", "--setup", "0x020019FF", "--out", outDir, "--spacing", "1", "--quiet"],
        _ => throw new ArgumentOutOfRangeException(nameof(command)),
    };

    private static string ErrorLine(CliRun run) =>
        Assert.Single(run.ErrorLines, l => !l.Contains("SYNTHETIC") && !l.Contains("Debug build") && !l.StartsWith("warning:"));

    [Theory]
    [MemberData(nameof(Writers))]
    public void An_output_folder_that_cannot_be_created_is_exit_6(string command)
    {
        // /proc takes no new folders, whoever asks.
        var run = CliRun.Of(Args(command, "/proc/acshadow-test/out"));
        Assert.Equal(6, run.ExitCode);
        Assert.Contains("--out: cannot create folder /proc/acshadow-test/out", ErrorLine(run));
    }

    [Theory]
    [MemberData(nameof(Writers))]
    public void An_output_path_that_is_a_file_is_exit_6(string command)
    {
        using var dir = new TempDir();
        var file = Path.Combine(dir.Path, "taken");
        File.WriteAllText(file, "x");
        var run = CliRun.Of(Args(command, file));
        Assert.Equal(6, run.ExitCode);
        Assert.Contains($"--out: {file} is a file: pass a folder", ErrorLine(run));
        Assert.Equal(["taken"], dir.Files());
    }

    [Theory]
    [InlineData("dump", "--setup", "0x0200FFFF")]
    [InlineData("batch", "--landblock", "0x0101")]
    [InlineData("chart", "--setup", "0x0200FFFF")]
    [InlineData("scene", "--landblock", "0x0101")]
    [InlineData("view", "--setup", "0x0200FFFF")]
    public void Every_folder_writer_refuses_a_file_as_out_before_reading_the_dat(string command, string option, string missing)
    {
        using var dir = new TempDir();
        var file = Path.Combine(dir.Path, "taken");
        File.WriteAllText(file, "x");
        // The object is not in the dat (exit 4 once the dat is read): the --out is found wrong first.
        var run = CliRun.Of(command, option, missing, "--out", file);
        Assert.Equal(6, run.ExitCode);
        Assert.Equal($"acshadow: --out: {file} is a file: pass a folder (it is created when missing)", Assert.Single(run.ErrorLines));
        Assert.Equal(["taken"], dir.Files());
    }

    [Fact]
    public void An_output_folder_without_write_permission_is_exit_6_before_any_work_is_written()
    {
        using var dir = new TempDir();
        BuiltCli.OpenToEveryone(dir.Path);
        var locked = Path.Combine(dir.Path, "locked");
        Directory.CreateDirectory(locked);
        BuiltCli.OpenToEveryone(locked); // r-x for everyone: nobody may not create files in it

        var (code, _, stderr) = BuiltCli.Run(BuiltCli.AsUnprivilegedUser(), "batch", "--doors", "--out", locked, "--quiet");

        Assert.Equal(6, code);
        Assert.Contains($"--out: cannot write in folder {locked}: Access to the path", stderr);
        Assert.Empty(Directory.GetFileSystemEntries(locked));
    }

    /// <summary>
    /// A 64 KiB tmpfs (mounted in a private mount namespace) when this machine allows it: the write fails
    /// with ENOSPC. Otherwise a 50 KiB file-size limit (ulimit -f), which fails the same write with EFBIG.
    /// Either way a real write fails part-way through the batch.
    /// </summary>
    [Fact]
    public void A_write_that_fails_for_lack_of_space_is_exit_6_and_leaves_only_whole_files_and_no_index()
    {
        using var dir = new TempDir();
        var copy = Path.Combine(dir.Path, "after");
        var mount = Path.Combine(dir.Path, "tiny");
        Directory.CreateDirectory(mount);
        var acshadow = $"dotnet '{BuiltCli.Dll}' batch --doors --all --landblock 0xA9B4 --quiet --out '{mount}/out'";
        var canMount = BuiltCli.RunShell(["unshare", "-m"], $"mount -t tmpfs -o size=64k tmpfs '{mount}'").ExitCode == 0;
        var script = canMount
            ? $"mount -t tmpfs -o size=64k tmpfs '{mount}' && {{ {acshadow}; rc=$?; cp -a '{mount}/out' '{copy}'; exit $rc; }}"
            : $"trap '' XFSZ; ulimit -f 50; {acshadow}; rc=$?; cp -a '{mount}/out' '{copy}'; exit $rc";
        var (code, _, stderr) = BuiltCli.RunShell(canMount ? ["unshare", "-m"] : [], script);

        Assert.Equal(6, code);
        var line = Assert.Single(stderr.Split('\n', StringSplitOptions.RemoveEmptyEntries), l => !l.Contains("SYNTHETIC"));
        Assert.Contains("acshadow: cannot write ", line);
        Assert.Contains(canMount ? "No space left on device" : "too large", line);
        var files = Directory.GetFiles(copy, "*", SearchOption.AllDirectories);
        Assert.NotEmpty(files);
        Assert.DoesNotContain(files, f => f.EndsWith(".tmp", StringComparison.Ordinal));
        Assert.DoesNotContain(Path.Combine(copy, "index.json"), files);
        foreach (var file in files.Where(f => f.EndsWith(".shadow.json", StringComparison.Ordinal))) ShadowFileReader.Read(File.ReadAllText(file));
        foreach (var file in files.Where(f => f.EndsWith(".bsp.json", StringComparison.Ordinal))) BspFileReader.Read(File.ReadAllText(file));
    }

    [Fact]
    public void Dump_refuses_to_replace_a_file_that_is_not_acshadow_output_and_writes_nothing()
    {
        using var dir = new TempDir();
        Directory.CreateDirectory(Path.Combine(dir.Path, "setups"));
        var mine = Path.Combine(dir.Path, "setups", "0x020019FF.shadow.json");
        File.WriteAllText(mine, "{\n  \"name\": \"my own door notes\"\n}\n");

        var run = CliRun.Of("dump", "--setup", "0x020019FF", "--out", dir.Path);

        Assert.Equal(6, run.ExitCode);
        Assert.Contains($"--out: {mine} would be replaced but is not acshadow output: move it away or pass another folder; nothing was written", ErrorLine(run));
        Assert.Equal(["setups/0x020019FF.shadow.json"], dir.Files());
        Assert.Contains("my own door notes", File.ReadAllText(mine));
    }

    [Fact]
    public void Batch_refuses_a_foreign_index_json_before_writing_anything()
    {
        using var dir = new TempDir();
        var index = Path.Combine(dir.Path, "index.json");
        File.WriteAllText(index, "{\"pages\": [1, 2, 3]}\n");

        var run = CliRun.Of("batch", "--doors", "--out", dir.Path, "--quiet");

        Assert.Equal(6, run.ExitCode);
        Assert.Contains($"{index} would be replaced but is not acshadow output", ErrorLine(run));
        Assert.Equal(["index.json"], dir.Files());
    }

    [Fact]
    public void Chart_refuses_a_foreign_csv_and_a_folder_where_a_file_belongs()
    {
        using var dir = new TempDir();
        File.WriteAllText(Path.Combine(dir.Path, "chart.csv"), "date,amount\n2024-01-01,3\n");
        Directory.CreateDirectory(Path.Combine(dir.Path, "summary.csv"));

        var run = CliRun.Of(Args("chart", dir.Path));

        Assert.Equal(6, run.ExitCode);
        Assert.Contains("chart.csv and 1 more would be replaced but are not acshadow output", ErrorLine(run));
        Assert.Equal(["chart.csv"], dir.Files());
    }

    [Theory]
    [MemberData(nameof(Writers))]
    public void A_second_run_replaces_the_first_runs_files(string command)
    {
        using var dir = new TempDir();
        Assert.Equal(0, CliRun.Of(Args(command, dir.Path)).ExitCode);
        var first = dir.Files();
        var again = CliRun.Of(Args(command, dir.Path));
        Assert.Equal(0, again.ExitCode);
        Assert.Equal(first, dir.Files());
    }

    [Fact]
    public void Files_of_an_older_format_version_and_acdream_files_are_ours_to_replace()
    {
        using var dir = new TempDir();
        Assert.Equal(0, CliRun.Of("dump", "--setup", "0x020019FF", "--format", "both", "--out", dir.Path).ExitCode);
        var shadow = Path.Combine(dir.Path, "setups", "0x020019FF.shadow.json");
        File.WriteAllText(shadow, File.ReadAllText(shadow).Replace("acshadow.shadow/2", "acshadow.shadow/0"));
        var acdream = Path.Combine(dir.Path, "gfxobjs", "0x010044B5.gfxobj.json");
        File.WriteAllText(acdream, "{\n  \"GfxObjId\": 1,\n}\n");

        var run = CliRun.Of("dump", "--setup", "0x020019FF", "--format", "both", "--out", dir.Path);

        Assert.Equal(0, run.ExitCode);
        Assert.Contains("acshadow.shadow/2", File.ReadAllText(shadow));
        Assert.Contains("\"GfxObjId\": 16794805", File.ReadAllText(acdream));
    }

    [Fact]
    public void Temporary_files_of_a_run_that_died_are_removed_and_a_live_runs_are_kept()
    {
        using var dir = new TempDir();
        Directory.CreateDirectory(Path.Combine(dir.Path, "setups"));
        var deadPid = Enumerable.Range(4_000_000, 100_000).First(p => !Directory.Exists($"/proc/{p}"));
        var dead = Path.Combine(dir.Path, "setups", $"0x020019FF.shadow.json.{deadPid}.tmp");
        var live = Path.Combine(dir.Path, "setups", $"0x02000001.shadow.json.{Environment.ProcessId}.tmp");
        var notOurs = Path.Combine(dir.Path, "setups", $"notes.{deadPid}.tmp");
        foreach (var f in new[] { dead, live, notOurs }) File.WriteAllText(f, "{\n  \"form");

        Assert.Equal(0, CliRun.Of("dump", "--setup", "0x020019FF", "--out", dir.Path).ExitCode);

        Assert.False(File.Exists(dead));
        Assert.True(File.Exists(live));
        Assert.True(File.Exists(notOurs));
    }

    [Fact]
    public void A_leftover_temporary_file_under_this_processs_own_id_is_replaced_not_an_error()
    {
        // A killed run whose process id this one now has: its temporary file is not "abandoned" (the id is
        // alive), and the write creates its temporary new, so the leftover must be replaced.
        using var dir = new TempDir();
        Directory.CreateDirectory(Path.Combine(dir.Path, "setups"));
        var shadow = Path.Combine(dir.Path, "setups", "0x020019FF.shadow.json");
        var leftover = $"{shadow}.{Environment.ProcessId}.tmp";
        File.WriteAllText(leftover, "{\n  \"form");

        var run = CliRun.Of("dump", "--setup", "0x020019FF", "--out", dir.Path);

        Assert.Equal(0, run.ExitCode);
        Assert.False(File.Exists(leftover));
        Assert.StartsWith("{\n  \"format\": \"acshadow.shadow/2\"", File.ReadAllText(shadow));
        Assert.EndsWith("}\n", File.ReadAllText(shadow));
    }
}
