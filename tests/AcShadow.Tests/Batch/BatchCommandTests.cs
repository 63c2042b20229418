using System.Security.Cryptography;
using System.Text;
using System.Text.Json;
using AcShadow.Core.Catalog;
using AcShadow.Tests.Support;
using static AcShadow.Tests.Batch.BatchRuns;

namespace AcShadow.Tests.Batch;

public class BatchCommandTests
{
    /// <summary>Every Setup the forged sample holds (src/AcShadow.Forging/Sample/sample.json).</summary>
    public static readonly string[] SampleSetups =
    [
        "0x0200024F", "0x02000281", "0x02000311", "0x02001000", "0x02001100", "0x020019FF", "0x02002000", "0x02003000",
        "0x02003100", "0x02003200", "0x02003300", "0x02003400", "0x02003500", "0x02003600", "0x02003700", "0x02003800",
        "0x02003900", "0x02005000", "0x02006000",
    ];

    [Fact]
    public void Output_is_byte_identical_for_one_and_two_jobs()
    {
        var (one, a) = RunBatch("--doors", "--all", "--landblock", "0xA9B4", "--jobs", "1");
        var (two, b) = RunBatch("--doors", "--all", "--landblock", "0xA9B4", "--jobs", "2");
        using (a)
        using (b)
        {
            Assert.Equal(0, one.ExitCode);
            Assert.Equal(0, two.ExitCode);
            var first = ReadAll(a);
            var second = ReadAll(b);
            Assert.Equal(first.Keys.Order(), second.Keys.Order());
            foreach (var (path, bytes) in first) Assert.True(bytes.AsSpan().SequenceEqual(second[path]), $"{path} differs between --jobs 1 and --jobs 2");
        }
    }

    [Fact]
    public void All_writes_every_setup_each_gfxobj_dump_once_and_an_index_with_hashes()
    {
        var (run, dir) = RunBatch("--all");
        using (dir)
        {
            Assert.Equal(0, run.ExitCode);
            var files = dir.Files();
            Assert.Equal(SampleSetups.Select(id => $"setups/{id}.shadow.json"), files.Where(f => f.StartsWith("setups/")));
            Assert.Contains("gfxobjs/0x010044B6.bsp.json", files); // shared by the door's two jambs: dumped once
            Assert.DoesNotContain("scene.json", files);

            using var index = JsonDocument.Parse(Text(dir, "index.json"));
            var listed = index.RootElement.GetProperty("files").EnumerateArray().ToArray();
            Assert.Equal(files.Where(f => f != "index.json"), listed.Select(f => f.GetProperty("path").GetString()));
            foreach (var f in listed)
            {
                var bytes = File.ReadAllBytes(Path.Combine(dir.Path, f.GetProperty("path").GetString()!));
                Assert.Equal(Convert.ToHexStringLower(SHA256.HashData(bytes)), f.GetProperty("sha256").GetString());
                Assert.Equal(bytes.LongLength, f.GetProperty("bytes").GetInt64());
            }
            var inputs = index.RootElement.GetProperty("inputs");
            Assert.Equal("sample/client_portal.dat", inputs.GetProperty("dat").GetProperty("fileName").GetString());
            Assert.Equal(JsonValueKind.Null, inputs.GetProperty("cellDat").ValueKind);
            Assert.Equal("retail", inputs.GetProperty("policy").GetString());
            Assert.True(inputs.GetProperty("selection").GetProperty("all").GetBoolean());
            Assert.Contains("19 setup(s)", run.Out);
            Assert.Contains("wall time", run.Out);
        }
    }

    [Fact]
    public void Selections_combine_as_a_sorted_union()
    {
        var (idsDir, idsPath) = SetupsFile("# two sample Setups, one already a door\n0x02002000\n020019FF  # the door again\n\n");
        var (run, dir) = RunBatch("--doors", "--setups", idsPath);
        using (idsDir)
        using (dir)
        {
            Assert.Equal(0, run.ExitCode);
            // The catalog's sample doors (0x0200024F, 0x02000281, 0x02000311, 0x020019FF) plus the file's item.
            Assert.Equal(["setups/0x0200024F.shadow.json", "setups/0x02000281.shadow.json", "setups/0x02000311.shadow.json", "setups/0x020019FF.shadow.json", "setups/0x02002000.shadow.json"],
                dir.Files().Where(f => f.StartsWith("setups/")));
            using var index = JsonDocument.Parse(Text(dir, "index.json"));
            var selection = index.RootElement.GetProperty("inputs").GetProperty("selection");
            Assert.True(selection.GetProperty("doors").GetBoolean());
            Assert.False(selection.GetProperty("all").GetBoolean());
            Assert.Equal("ids.txt", selection.GetProperty("setupsFile").GetProperty("name").GetString());
            Assert.Equal(["0x020019FF", "0x02002000"], selection.GetProperty("setupsFile").GetProperty("ids").EnumerateArray().Select(e => e.GetString()).Order());
        }
    }

    [Fact]
    public void Ids_the_dat_lacks_are_skipped_with_a_reason_not_fatal()
    {
        var (idsDir, idsPath) = SetupsFile("0x020019FF\n0x0200ABCD\n");
        var (run, dir) = RunBatch("--doors", "--setups", idsPath);
        using (idsDir)
        using (dir)
        {
            Assert.Equal(0, run.ExitCode);
            Assert.Contains("setups/0x020019FF.shadow.json", dir.Files());
            Assert.DoesNotContain("setups/0x0200ABCD.shadow.json", dir.Files());
            Assert.Contains("skipped 1 (not in the dat; from setups-file): 0x0200ABCD", run.Out);
            var missingDoors = DoorCatalog.Entries.Count - 4; // the sample holds 4 catalog doors
            Assert.Contains($"skipped {missingDoors} (not in the dat; from doors)", run.Out);

            using var index = JsonDocument.Parse(Text(dir, "index.json"));
            var skipped = index.RootElement.GetProperty("skipped").EnumerateArray().ToArray();
            Assert.Equal(missingDoors + 1, skipped.Length);
            var custom = Assert.Single(skipped, s => s.GetProperty("id").GetString() == "0x0200ABCD");
            Assert.Equal("not in the dat", custom.GetProperty("reason").GetString());
            Assert.Equal(["setups-file"], custom.GetProperty("from").EnumerateArray().Select(e => e.GetString()));
        }
    }

    [Fact]
    public void Incremental_leaves_unchanged_files_alone()
    {
        var (first, dir) = RunBatch("--doors", "--incremental");
        using (dir)
        {
            Assert.Equal(0, first.ExitCode);
            Assert.Contains("incremental.json", dir.Files());
            var shadow = Path.Combine(dir.Path, "setups/0x020019FF.shadow.json");
            var stamp = new DateTime(2001, 1, 1, 0, 0, 0, DateTimeKind.Utc);
            File.SetLastWriteTimeUtc(shadow, stamp);
            File.WriteAllText(Path.Combine(dir.Path, "setups/0x0200024F.shadow.json"), "stale\n");

            var second = CliRun.Of("batch", "--out", dir.Path, "--doors", "--incremental");
            Assert.Equal(0, second.ExitCode);
            Assert.Equal(stamp, File.GetLastWriteTimeUtc(shadow));
            Assert.StartsWith("{", Text(dir, "setups/0x0200024F.shadow.json"));
            var total = dir.Files().Length;
            // The stale file, and index.json: removed before the run's first write, so a run stopped
            // part-way never leaves an index its files contradict, and written again at the end.
            Assert.Contains($"files: 2 written", second.Out);
            Assert.Contains($"{total - 2} unchanged and left alone", second.Out);
        }
    }

    [Fact]
    public void Into_an_empty_folder_and_into_one_that_holds_a_file_a_batch_writes_the_same_bytes_and_no_temporary()
    {
        // An empty folder takes the way without a look at each path first; one holding a file, the checked way.
        var (fresh, empty) = RunBatch("--doors", "--all", "--landblock", "0xA9B4", "--jobs", "2");
        using var held = new TempDir();
        File.WriteAllText(Path.Combine(held.Path, "notes.txt"), "mine");
        var checkedRun = CliRun.Of("batch", "--out", held.Path, "--doors", "--all", "--landblock", "0xA9B4", "--jobs", "2");
        using (empty)
        {
            Assert.Equal(0, fresh.ExitCode);
            Assert.Equal(0, checkedRun.ExitCode);
            var first = ReadAll(empty);
            var second = ReadAll(held);
            Assert.Equal("mine", Encoding.UTF8.GetString(second["notes.txt"]));
            second.Remove("notes.txt");
            Assert.Equal(first.Keys.Order(), second.Keys.Order());
            foreach (var (path, bytes) in first) Assert.True(bytes.AsSpan().SequenceEqual(second[path]), $"{path} differs");
            Assert.DoesNotContain(first.Keys, path => path.EndsWith(".tmp", StringComparison.Ordinal));
            Assert.Contains($"files: {first.Count} written", fresh.Out);
        }
    }

    [Fact]
    public void A_rerun_leaves_files_holding_their_bytes_alone_and_replaces_the_rest()
    {
        var (first, dir) = RunBatch("--doors");
        using (dir)
        {
            Assert.Equal(0, first.ExitCode);
            var shadow = Path.Combine(dir.Path, "setups/0x020019FF.shadow.json");
            var stale = Path.Combine(dir.Path, "setups/0x0200024F.shadow.json");
            var stamp = new DateTime(2001, 1, 1, 0, 0, 0, DateTimeKind.Utc);
            File.SetLastWriteTimeUtc(shadow, stamp);
            var expected = File.ReadAllText(stale);
            File.WriteAllText(stale, expected.Replace("\"format\"", "\"formaT\"", StringComparison.Ordinal)); // same length, other bytes
            File.SetLastWriteTimeUtc(stale, stamp);

            var second = CliRun.Of("batch", "--out", dir.Path, "--doors");
            Assert.Equal(0, second.ExitCode);
            Assert.Equal(stamp, File.GetLastWriteTimeUtc(shadow));
            Assert.Equal(expected, File.ReadAllText(stale));
            Assert.NotEqual(stamp, File.GetLastWriteTimeUtc(stale));
            // The stale file and index.json (always written when not --incremental); everything else left alone.
            var total = dir.Files().Length;
            Assert.Contains("files: 2 written", second.Out);
            Assert.Contains($"{total - 2} unchanged and left alone", second.Out);
        }
    }

    [Fact]
    public void Landblock_without_dat_options_uses_the_sample_cell_dat()
    {
        var (run, dir) = RunBatch("--landblock", "0xA9B4FFFE");
        using (dir)
        {
            Assert.Equal(0, run.ExitCode);
            Assert.Contains("scene.json", dir.Files());
            using var index = JsonDocument.Parse(Text(dir, "index.json"));
            var inputs = index.RootElement.GetProperty("inputs");
            Assert.Equal("sample/client_cell_1.dat", inputs.GetProperty("cellDat").GetProperty("fileName").GetString());
            Assert.Equal("0xA9B4FFFE", inputs.GetProperty("selection").GetProperty("landblock").GetString());
        }
    }

    [Fact]
    public void Dat_and_cell_dat_from_a_folder_give_the_same_files_as_the_sample()
    {
        using var dats = SampleDat.WriteToTempFolder();
        var (fromSample, a) = RunBatch("--all", "--landblock", "0xA9B4");
        var (fromFiles, b) = RunBatch("--all", "--landblock", "0xA9B4", "--dat", dats.Path, "--cell-dat", dats.Path);
        using (a)
        using (b)
        {
            Assert.Equal(0, fromSample.ExitCode);
            Assert.Equal(0, fromFiles.ExitCode);
            var first = ReadAll(a);
            var second = ReadAll(b);
            foreach (var (path, bytes) in first.Where(f => f.Key != "index.json"))
                Assert.True(bytes.AsSpan().SequenceEqual(second[path]), $"{path} differs");
            Assert.Contains("\"fileName\": \"client_portal.dat\"", Text(b, "index.json"));
        }
    }

    [Theory]
    [InlineData(2, "choose what to export")]
    [InlineData(2, "--jobs: '0'", "--all", "--jobs", "0")]
    [InlineData(2, "--jobs: 'many'", "--all", "--jobs", "many")]
    [InlineData(2, "not a policy", "--all", "--policy", "best")]
    [InlineData(2, "not a positive number", "--all", "--scale", "0")]
    [InlineData(2, "--landblock: 'A9B4X'", "--landblock", "A9B4X")]
    [InlineData(2, "--landblock: '0x12345678'", "--landblock", "0x12345678")]
    [InlineData(2, "--setups: /nonexistent/ids.txt does not exist", "--setups", "/nonexistent/ids.txt")]
    [InlineData(4, "landblock 0x0101 has no LandBlockInfo", "--landblock", "0x0101")]
    [InlineData(3, "does not exist", "--all", "--dat", "/nonexistent/client_portal.dat")]
    [InlineData(3, "does not exist", "--landblock", "0xA9B4", "--cell-dat", "/nonexistent/client_cell_1.dat")]
    public void Bad_input_exits_with_its_code_one_line_and_no_files(int code, string message, params string[] args)
    {
        var (run, dir) = RunBatch(args);
        using (dir)
        {
            Assert.Equal(code, run.ExitCode);
            var line = Assert.Single(run.ErrorLines, l => !l.Contains("SYNTHETIC"));
            Assert.Contains(message, line);
            Assert.Empty(dir.Files());
            Assert.Equal("", run.Out);
        }
    }

    [Fact]
    public void A_setups_file_line_that_is_not_an_id_is_a_usage_error_naming_the_line()
    {
        var (idsDir, idsPath) = SetupsFile("0x020019FF\nthe door\n");
        var (run, dir) = RunBatch("--setups", idsPath);
        using (idsDir)
        using (dir)
        {
            Assert.Equal(2, run.ExitCode);
            Assert.Contains("ids.txt line 2: 'the door' is not a Setup id", Assert.Single(run.ErrorLines));
            Assert.Empty(dir.Files());
        }
    }

    [Fact]
    public void Landblock_with_a_dat_but_no_cell_dat_is_a_usage_error()
    {
        using var dats = SampleDat.WriteToTempFolder();
        // The portal dat's file: a folder holding both dats gives the cell dat too (issue 32 item 16).
        var (run, dir) = RunBatch("--landblock", "0xA9B4", "--dat", Path.Combine(dats.Path, "client_portal.dat"));
        using (dir)
        {
            Assert.Equal(2, run.ExitCode);
            Assert.Contains("pass --cell-dat", Assert.Single(run.ErrorLines));
            Assert.Empty(dir.Files());
        }
    }

    [Fact]
    public void Out_that_is_a_file_fails_with_the_output_code_and_writes_nothing()
    {
        using var dir = new TempDir();
        var file = Path.Combine(dir.Path, "taken");
        File.WriteAllText(file, "x");
        var run = CliRun.Of("batch", "--out", file, "--all");
        Assert.Equal(6, run.ExitCode);
        Assert.Contains("is a file", Assert.Single(run.ErrorLines));
        Assert.Equal(["taken"], dir.Files());
    }
}
