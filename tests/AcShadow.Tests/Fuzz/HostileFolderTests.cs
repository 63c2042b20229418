using System.Diagnostics;
using System.Security.Cryptography;
using System.Text;
using System.Text.Json;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Fuzz;

/// <summary>
/// The hostile-folder cases of issue 32 ("files and trust"), kept as regression cases beside the dat fuzz
/// campaign's saved inputs: folders and files a user (or an attacker) edited by hand, links where folders
/// belong, paths that leave the folder, and re-runs over what an earlier run left. Each case runs the real
/// commands in-process and checks what reaches the disk and the log, not only the exit code.
/// </summary>
public sealed class HostileFolderTests
{
    private const string Door = "setups/0x020019FF.shadow.json";

    private static string Sha(byte[] bytes) => Convert.ToHexStringLower(SHA256.HashData(bytes));

    private static CliRun Batch(string outDir, params string[] args) => CliRun.Of(["batch", "--out", outDir, "--quiet", .. args]);

    /// <summary>A `batch --doors` in ROOT/out (so ROOT has room for files outside the folder); the folder's path.</summary>
    private static string DoorsBatchIn(TempDir root)
    {
        var outDir = Path.Combine(root.Path, "out");
        Assert.Equal(0, Batch(outDir, "--doors").ExitCode);
        return outDir;
    }

    private static string[] FilesUnder(string folder) =>
        Directory.Exists(folder) ? Directory.GetFiles(folder, "*", SearchOption.AllDirectories) : [];

    // Item 2: a same-length edit of a shadow file kept its size, and --incremental reused it unchecked.
    [Fact]
    public void Incremental_reuse_rewrites_a_file_edited_to_the_same_length()
    {
        using var dir = new TempDir();
        Assert.Equal(0, Batch(dir.Path, "--all", "--incremental").ExitCode);
        var path = Path.Combine(dir.Path, Door);
        var original = File.ReadAllBytes(path);
        var text = Encoding.UTF8.GetString(original);
        var at = text.IndexOf("\"radius\": ", StringComparison.Ordinal) + "\"radius\": ".Length;
        var edited = text[..at] + (text[at] == '9' ? '8' : '9') + text[(at + 1)..];
        File.WriteAllText(path, edited);
        Assert.Equal(original.Length, new FileInfo(path).Length);

        var run = Batch(dir.Path, "--all", "--incremental");

        Assert.Equal(0, run.ExitCode);
        Assert.True(original.AsSpan().SequenceEqual(File.ReadAllBytes(path)), $"the edited {Door} was reused, not rewritten:\n{run.Out}");
        using var index = JsonDocument.Parse(File.ReadAllBytes(Path.Combine(dir.Path, "index.json")));
        var entry = index.RootElement.GetProperty("files").EnumerateArray().Single(f => f.GetProperty("path").GetString() == Door);
        Assert.Equal(Sha(File.ReadAllBytes(path)), entry.GetProperty("sha256").GetString());
    }

    // Item 2, the state itself: a hand-edited count in incremental.json went into index.json unchecked.
    [Fact]
    public void An_incremental_state_edited_by_hand_is_not_trusted()
    {
        using var dir = new TempDir();
        Assert.Equal(0, Batch(dir.Path, "--all", "--incremental").ExitCode);
        var state = Path.Combine(dir.Path, "incremental.json");
        var text = File.ReadAllText(state);
        var at = text.IndexOf($"\"path\": \"{Door}\"", StringComparison.Ordinal);
        var shapes = text.IndexOf("\"shapes\": ", at, StringComparison.Ordinal) + "\"shapes\": ".Length;
        File.WriteAllText(state, text[..shapes] + "9" + text[shapes..]);

        var run = Batch(dir.Path, "--all", "--incremental");

        Assert.Equal(0, run.ExitCode);
        var verify = CliRun.Of("verify", "--fixtures", dir.Path);
        Assert.True(verify.ExitCode == 0, verify.Out + verify.Error);
    }

    // Found by the fuzz campaign's incremental re-run: a state with no Setups is written on one line, and the
    // next --incremental run took that line for another program's file and refused the folder (exit 6).
    [Fact]
    public void An_incremental_state_of_a_run_that_exported_nothing_is_replaced_by_the_next_run()
    {
        using var dir = new TempDir();
        using var ids = new TempDir();
        var list = Path.Combine(ids.Path, "ids.txt");
        File.WriteAllText(list, "0x0200FFF0\n"); // not in the sample: skipped, so no Setup is exported
        Assert.Equal(0, Batch(dir.Path, "--setups", list, "--incremental").ExitCode);

        var rerun = Batch(dir.Path, "--setups", list, "--incremental");

        Assert.True(rerun.ExitCode == 0, rerun.Error);
    }

    // Item 3: incremental.json named files outside the folder for a Setup, which was then "reused".
    [Theory]
    [InlineData("relative")]
    [InlineData("absolute")]
    public void Incremental_state_naming_a_path_outside_the_folder_is_not_trusted(string kind)
    {
        using var root = new TempDir();
        var outDir = Path.Combine(root.Path, "out");
        Assert.Equal(0, Batch(outDir, "--all", "--incremental").ExitCode);
        var shadow = Path.Combine(outDir, Door);
        var original = File.ReadAllBytes(shadow);
        // A victim of the same size, so a size check alone would take it for the shadow file.
        var victim = Path.Combine(root.Path, "victim.txt");
        File.WriteAllBytes(victim, Encoding.ASCII.GetBytes(new string('v', original.Length)));
        var named = kind == "relative" ? "../victim.txt" : victim;
        var state = Path.Combine(outDir, "incremental.json");
        File.WriteAllText(state, File.ReadAllText(state).Replace($"\"path\": \"{Door}\"", $"\"path\": {JsonSerializer.Serialize(named)}"));
        File.Delete(shadow);

        var run = Batch(outDir, "--all", "--incremental");

        Assert.Equal(0, run.ExitCode);
        Assert.True(File.Exists(shadow), $"the deleted {Door} was not written again:\n{run.Out}");
        Assert.True(original.AsSpan().SequenceEqual(File.ReadAllBytes(shadow)));
        var index = File.ReadAllText(Path.Combine(outDir, "index.json"));
        Assert.DoesNotContain("victim", index);
        Assert.Equal(new string('v', original.Length), File.ReadAllText(victim));
    }

    // Item 4: a link inside --out where a subfolder belongs was followed, and files landed outside --out.
    [Theory]
    [InlineData("setups", "batch --all")]
    [InlineData("gfxobjs", "batch --all")]
    [InlineData("cells", "batch --landblock 0xA9B4")]
    [InlineData("setups", "dump --setup 0x020019FF")]
    [InlineData("gfxobjs", "dump --setup 0x020019FF")]
    [InlineData("cells", "dump --cell 0xA9B40100")]
    [InlineData("gfxobjs", "scene --landblock 0xA9B4 --quiet")]
    public void A_link_where_an_output_subfolder_belongs_is_refused_and_nothing_lands_outside(string sub, string command)
    {
        using var root = new TempDir();
        var outDir = Path.Combine(root.Path, "out");
        var elsewhere = Path.Combine(root.Path, "elsewhere");
        Directory.CreateDirectory(outDir);
        Directory.CreateDirectory(elsewhere);
        Directory.CreateSymbolicLink(Path.Combine(outDir, sub), elsewhere);
        var words = command.Split(' ');

        var run = CliRun.Of([words[0], "--out", outDir, .. words[1..]]);

        Assert.True(run.ExitCode == 6, $"exit {run.ExitCode}\n{run.Out}\n{run.Error}");
        Assert.Contains($"--out: {Path.Combine(outDir, sub)} is a symbolic link", run.Error);
        Assert.Contains("nothing was written", run.Error);
        Assert.Empty(FilesUnder(elsewhere));
        Assert.Equal(Path.Combine(outDir, sub), Assert.Single(Directory.GetFileSystemEntries(outDir)));
    }

    // Item 5: verify read a shadow file through a link to a credentials file and printed its values.
    [Fact]
    public void Verify_reports_a_linked_fixture_as_a_link_and_never_prints_what_it_leads_to()
    {
        using var root = new TempDir();
        var outDir = DoorsBatchIn(root);
        var secrets = Path.Combine(root.Path, "credentials.json");
        File.WriteAllText(secrets, "{\n  \"format\": \"acshadow.shadow/2\",\n  \"apiToken\": \"tok-3141592653\",\n  \"password\": \"hunter2-secret\"\n}\n");
        File.Delete(Path.Combine(outDir, Door));
        File.CreateSymbolicLink(Path.Combine(outDir, Door), secrets);

        var run = CliRun.Of("verify", "--fixtures", outDir);

        Assert.Equal(5, run.ExitCode);
        Assert.DoesNotContain("tok-3141592653", run.Out + run.Error);
        Assert.DoesNotContain("hunter2-secret", run.Out + run.Error);
        Assert.Single(run.Out.Split('\n'), l => l.StartsWith($"link {Door}", StringComparison.Ordinal));
    }

    // Item 5: a folder link loop inside the fixtures gave hundreds of "extra" lines.
    [Fact]
    public void Verify_names_a_folder_link_loop_once_and_does_not_walk_it()
    {
        using var root = new TempDir();
        var outDir = DoorsBatchIn(root);
        Directory.CreateSymbolicLink(Path.Combine(outDir, "gfxobjs", "loop"), "..");

        var run = CliRun.Of("verify", "--fixtures", outDir);

        Assert.Equal(5, run.ExitCode);
        var lines = run.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Equal("link gfxobjs/loop -> .. (a symbolic link loop: it leads back into the folder; not followed)", Assert.Single(lines));
    }

    // Item 5: file names holding ESC and newline reached the terminal raw.
    [Fact]
    public void Verify_escapes_control_characters_in_the_names_it_prints()
    {
        using var root = new TempDir();
        var outDir = DoorsBatchIn(root);
        File.WriteAllText(Path.Combine(outDir, "setups", "red\u001b[31m.json"), "{}\n");
        File.WriteAllText(Path.Combine(outDir, "setups", "two\nlines.json"), "{}\n");

        var run = CliRun.Of("verify", "--fixtures", outDir);

        Assert.Equal(5, run.ExitCode);
        Assert.DoesNotContain('\u001b', run.Out + run.Error);
        Assert.Contains("extra setups/red\\x1B[31m.json", run.Out);
        Assert.Contains("extra setups/two\\nlines.json", run.Out);
    }

    // Item 6: scene wrote compiled-scene.json first; a re-run that failed after it left the new scene with the old dumps.
    [Fact]
    public void A_scene_rerun_that_fails_never_leaves_its_new_compiled_scene_beside_the_old_dumps()
    {
        using var dir = new TempDir();
        var first = CliRun.Of("scene", "--landblock", "0xA9B4", "--out", dir.Path, "--quiet");
        Assert.True(first.ExitCode == 0, first.Error);
        var scenePath = Path.Combine(dir.Path, "compiled-scene.json");
        var before = File.ReadAllBytes(scenePath);
        var cells = Path.Combine(dir.Path, "cells");
        Assert.NotEmpty(Directory.GetFiles(cells, "*.bsp.json"));
        // The cells' dumps cannot be written: a file stands where their folder belongs.
        Directory.Delete(cells, recursive: true);
        File.WriteAllText(cells, "not a folder\n");

        var second = CliRun.Of("scene", "--landblock", "0xA9B4", "--out", dir.Path, "--quiet", "--mover-radius", "0.3");

        Assert.Equal(6, second.ExitCode);
        Assert.True(!File.Exists(scenePath) || before.AsSpan().SequenceEqual(File.ReadAllBytes(scenePath)),
            "the failed re-run left its own compiled-scene.json, naming dumps it never wrote");
    }

    // Item 7, for scene: a re-run that models more objects cheaply left the dumps only the previous compile named.
    [Fact]
    public void A_scene_rerun_removes_the_dumps_its_compile_no_longer_names()
    {
        using var dir = new TempDir();
        Assert.Equal(0, CliRun.Of("scene", "--landblock", "0xA9B4", "--out", dir.Path, "--quiet").ExitCode);
        string[] Dumps() => [.. Directory.GetFiles(Path.Combine(dir.Path, "gfxobjs"), "*.bsp.json").Select(f => "gfxobjs/" + Path.GetFileName(f)).Order(StringComparer.Ordinal)];
        string[] Named() => [.. Dumps().Where(File.ReadAllText(Path.Combine(dir.Path, "compiled-scene.json")).Contains)];
        var first = Dumps();
        Assert.NotEmpty(first);

        // Every false block tolerated: the objects take cheaper models, which need no dump.
        var rerun = CliRun.Of("scene", "--landblock", "0xA9B4", "--out", dir.Path, "--quiet", "--tolerance", "100");

        Assert.Equal(0, rerun.ExitCode);
        Assert.NotEqual(first, Dumps());
        Assert.Equal(Named(), Dumps());
    }

    // Item 7: a --no-cells re-run left the first run's cells (and the objects only they placed), and verify failed.
    [Fact]
    public void A_batch_rerun_removes_the_files_it_no_longer_writes()
    {
        using var dir = new TempDir();
        Assert.Equal(0, Batch(dir.Path, "--landblock", "0xA9B4").ExitCode);
        Assert.NotEmpty(Directory.GetFiles(Path.Combine(dir.Path, "cells")));
        var notes = Path.Combine(dir.Path, "cells", "notes.txt"); // the user's: not listed, never removed

        File.WriteAllText(notes, "mine\n");
        var rerun = Batch(dir.Path, "--landblock", "0xA9B4", "--no-cells");
        Assert.Equal(0, rerun.ExitCode);
        Assert.Equal(["cells/notes.txt"], FilesUnder(Path.Combine(dir.Path, "cells")).Select(f => Path.GetRelativePath(dir.Path, f)));
        File.Delete(notes);

        var verify = CliRun.Of("verify", "--fixtures", dir.Path);
        Assert.True(verify.ExitCode == 0, verify.Out + verify.Error);
    }

    // Item 7: verify reports an extra file under cells/ (a stale cell a --no-cells re-run left).
    [Fact]
    public void Verify_reports_extra_files_under_cells()
    {
        using var dir = new TempDir();
        Assert.Equal(0, Batch(dir.Path, "--landblock", "0xA9B4", "--no-cells").ExitCode);
        Directory.CreateDirectory(Path.Combine(dir.Path, "cells"));
        File.WriteAllText(Path.Combine(dir.Path, "cells", "0xA9B40100.cell.json"), "{}\n");
        var run = CliRun.Of("verify", "--fixtures", dir.Path);
        Assert.Equal(5, run.ExitCode);
        Assert.Contains("extra cells/0xA9B40100.cell.json", run.Out);
    }

    // Item 7: an earlier (interrupted) chart's failure maps stayed beside the next run's chart.csv.
    [Fact]
    public void A_chart_rerun_removes_failure_maps_of_objects_it_does_not_chart()
    {
        using var dir = new TempDir();
        Assert.Equal(0, CliRun.Of("chart", "--setup", "0x020019FF", "--setup", "0x02001000", "--out", dir.Path, "--quiet").ExitCode);
        Assert.True(File.Exists(Path.Combine(dir.Path, "failure-map-0x02001000.svg")));
        File.WriteAllText(Path.Combine(dir.Path, "failure-map-notes.svg"), "<svg>mine</svg>\n");

        var rerun = CliRun.Of("chart", "--setup", "0x020019FF", "--out", dir.Path, "--quiet");

        Assert.Equal(0, rerun.ExitCode);
        Assert.False(File.Exists(Path.Combine(dir.Path, "failure-map-0x02001000.svg")), "a map chart.csv does not describe was left");
        Assert.True(File.Exists(Path.Combine(dir.Path, "failure-map-0x020019FF.svg")));
        Assert.True(File.Exists(Path.Combine(dir.Path, "failure-map-notes.svg")), "a file that is not acshadow's was removed");
    }

    // Item 11: the committed fixtures name the built-in sample; a byte-identical dat with another name is the same dat.
    [Fact]
    public void The_committed_fixtures_verify_against_a_freshly_forged_sample_under_another_name()
    {
        using var dats = SampleDat.WriteToTempFolder();
        var run = CliRun.Of("verify", "--fixtures", Path.Combine(RepositoryRoot.Path, "fixtures"),
            "--dat", Path.Combine(dats.Path, "client_portal.dat"), "--cell-dat", Path.Combine(dats.Path, "client_cell_1.dat"));
        Assert.True(run.ExitCode == 0, $"exit {run.ExitCode}\n{run.Out}\n{run.Error}");
    }

    // The guard of item 1, for the folder writers: a dat the run reads, where the folder's index lists a file of its own.
    [Theory]
    [InlineData("--dat")]
    [InlineData("ACSHADOW_DAT")]
    public void A_batch_never_writes_over_a_dat_it_reads(string how)
    {
        using var dir = new TempDir();
        Assert.Equal(0, Batch(dir.Path, "--doors").ExitCode);
        var dat = Path.Combine(dir.Path, Door);
        File.WriteAllBytes(dat, SampleDat.PortalBytes);
        var before = Sha(SampleDat.PortalBytes);

        var run = how == "--dat"
            ? Batch(dir.Path, "--doors", "--dat", dat)
            : CliRun.With(name => name == "ACSHADOW_DAT" ? dat : null, "batch", "--out", dir.Path, "--quiet", "--doors");

        Assert.True(run.ExitCode == 6, $"exit {run.ExitCode}\n{run.Out}\n{run.Error}");
        Assert.Contains($"--out: {dat} is a dat this run reads: acshadow never writes over its input", run.Error);
        Assert.Equal(before, Sha(File.ReadAllBytes(dat)));
    }

    // The folder's survey looks at each path once: a hard link is the dat by its identity, a symbolic link by where it leads.
    [Theory]
    [InlineData("hard")]
    [InlineData("symbolic")]
    public void A_batch_never_writes_over_a_dat_it_reads_through_a_link_its_index_lists(string link)
    {
        using var dats = SampleDat.WriteToTempFolder();
        using var dir = new TempDir();
        var portal = Path.Combine(dats.Path, "client_portal.dat");
        Assert.Equal(0, Batch(dir.Path, "--doors", "--dat", portal).ExitCode);
        var listed = Path.Combine(dir.Path, Door);
        File.Delete(listed);
        if (link == "symbolic") File.CreateSymbolicLink(listed, portal);
        else
        {
            using var ln = Process.Start("ln", [portal, listed])!;
            ln.WaitForExit();
            Assert.Equal(0, ln.ExitCode);
        }
        var before = Sha(File.ReadAllBytes(portal));

        var run = Batch(dir.Path, "--doors", "--dat", portal);

        Assert.True(run.ExitCode == 6, $"exit {run.ExitCode}\n{run.Out}\n{run.Error}");
        Assert.Contains($"--out: {listed} is a dat this run reads: acshadow never writes over its input", run.Error);
        // Refused by the survey before the first write, not by the last look before that file's own write.
        Assert.Contains("or pass another folder; nothing was written", run.Error);
        Assert.Equal(before, Sha(File.ReadAllBytes(portal)));
    }

    [Fact]
    public void A_landblock_batch_never_writes_over_the_cell_dat_it_reads()
    {
        using var dats = SampleDat.WriteToTempFolder();
        using var dir = new TempDir();
        var portal = Path.Combine(dats.Path, "client_portal.dat");
        Assert.Equal(0, Batch(dir.Path, "--landblock", "0xA9B4", "--dat", portal, "--cell-dat", dats.Path).ExitCode);
        var cellDat = Path.Combine(dir.Path, "cells", "0xA9B40100.cell.json");
        File.WriteAllBytes(cellDat, SampleDat.CellBytes!);

        var run = Batch(dir.Path, "--landblock", "0xA9B4", "--dat", portal, "--cell-dat", cellDat);

        Assert.True(run.ExitCode == 6, $"exit {run.ExitCode}\n{run.Out}\n{run.Error}");
        Assert.Contains($"--out: {cellDat} is a dat this run reads", run.Error);
        Assert.Equal(Sha(SampleDat.CellBytes!), Sha(File.ReadAllBytes(cellDat)));
    }

    // Item 3, at the reader: a state naming any path that could leave the folder is no state at all.
    [Theory]
    [InlineData("../victim.txt")]
    [InlineData("/etc/hostname")]
    [InlineData("setups/../../x.json")]
    [InlineData("setups//x.json")]
    [InlineData("setups\\x.json")]
    [InlineData("C:x.json")]
    public void An_incremental_state_naming_a_path_that_leaves_the_folder_is_unreadable(string path)
    {
        using var dir = new TempDir();
        Assert.Equal(0, Batch(dir.Path, "--doors", "--incremental").ExitCode);
        var state = AcShadow.Core.Batch.IncrementalStateFile.TryRead(File.ReadAllBytes(Path.Combine(dir.Path, "incremental.json")));
        Assert.NotNull(state);
        // Written by the writer itself, so its own SHA-256 holds: only the path is wrong.
        var hostile = state with
        {
            Setups = [.. state.Setups.Select(s => s with { Files = [.. s.Files.Select(f => f.RelativePath == Door ? f with { RelativePath = path } : f)] })],
        };
        Assert.NotNull(AcShadow.Core.Batch.IncrementalStateFile.TryRead(AcShadow.Core.Batch.IncrementalStateFile.Write(state)));
        Assert.Contains(JsonSerializer.Serialize(path), Encoding.UTF8.GetString(AcShadow.Core.Batch.IncrementalStateFile.Write(hostile)));
        Assert.Null(AcShadow.Core.Batch.IncrementalStateFile.TryRead(AcShadow.Core.Batch.IncrementalStateFile.Write(hostile)));
    }

    // Item 5: an index.json that is a link is not read through.
    [Fact]
    public void Verify_refuses_an_index_that_is_a_link()
    {
        using var root = new TempDir();
        var outDir = DoorsBatchIn(root);
        var elsewhere = Path.Combine(root.Path, "index.json");
        File.Move(Path.Combine(outDir, "index.json"), elsewhere);
        File.CreateSymbolicLink(Path.Combine(outDir, "index.json"), elsewhere);

        var run = CliRun.Of("verify", "--fixtures", outDir);

        Assert.Equal(2, run.ExitCode);
        Assert.Contains($"--fixtures: {Path.Combine(outDir, "index.json")} is a symbolic link (to {elsewhere}): verify reads no file through a link", run.Error);
    }

    // Item 5: the error line escapes what a path carries, as verify's report does.
    [Fact]
    public void An_error_line_escapes_control_characters_in_a_path()
    {
        using var root = new TempDir();
        var outPath = Path.Combine(root.Path, "red\u001b[31m");
        File.WriteAllText(outPath, "a file where the folder belongs\n");

        var run = CliRun.Of("batch", "--doors", "--out", outPath);

        Assert.Equal(6, run.ExitCode);
        Assert.DoesNotContain('\u001b', run.Error);
        Assert.Contains("red\\x1B[31m is a file", run.Error);
    }

    // Item 6, the order itself: the file that names the dumps is the last one written.
    [Fact]
    public void The_compiled_scene_is_written_after_every_dump_it_names()
    {
        var files = AcShadow.Analysis.Compile.CompiledSceneFiles.Render(Scenes.SceneCompileTests.Exact.Value,
            id => Chart.SampleChart.Subjects.Value.GfxObj(id) is { } g ? AcShadow.Core.Bsp.BspExtractor.Extract(g) : null);
        Assert.Contains(files, f => f.RelativePath.EndsWith(".bsp.json", StringComparison.Ordinal));
        Assert.Equal("compiled-scene.json", files[^1].RelativePath);
    }

    // Item 11: an index written before dats were hashed still verifies against its dat (compared by size and iteration).
    [Fact]
    public void An_index_without_the_dats_hash_still_verifies()
    {
        using var dir = new TempDir();
        Assert.Equal(0, Batch(dir.Path, "--doors").ExitCode);
        var index = Path.Combine(dir.Path, "index.json");
        var text = File.ReadAllText(index);
        var at = text.IndexOf(",\n      \"sha256\": \"", StringComparison.Ordinal);
        Assert.True(at > 0);
        File.WriteAllText(index, text[..at] + text[text.IndexOf('"', at + ",\n      \"sha256\": \"".Length)..][1..]);
        Assert.DoesNotContain("\"sha256\": \"" + Sha(SampleDat.PortalBytes), File.ReadAllText(index));

        var run = CliRun.Of("verify", "--fixtures", dir.Path);

        Assert.True(run.ExitCode == 0, run.Out + run.Error);
    }

    // The path rule refuses what leaves the folder, not what a file name may hold: a report named with a colon is written.
    [Fact]
    public void A_report_whose_name_holds_a_colon_is_still_written()
    {
        using var dir = new TempDir();
        var report = Path.Combine(dir.Path, "audit:doors.csv");
        var run = CliRun.Of("audit", "--doors", "--format", "csv", "--out", report);
        Assert.True(run.ExitCode == 0, run.Error);
        Assert.True(new FileInfo(report).Length > 0);
    }
}
