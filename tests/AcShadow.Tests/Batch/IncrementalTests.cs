using AcShadow.Forge;
using AcShadow.Forging;
using AcShadow.Forging.Spec;
using AcShadow.Tests.Support;
using static AcShadow.Tests.Batch.BatchRuns;

namespace AcShadow.Tests.Batch;

/// <summary>
/// The --incremental fast path: Setups whose dat entries (and their parts') did not change are not
/// re-exported, and the folder still ends up exactly as a fresh run would write it.
/// </summary>
public sealed class IncrementalTests
{
    /// <summary>The sample's Setups: 15, and the four pose-rule Setups of issue 27.</summary>
    private const int SampleSetups = 19;

    /// <summary>An incremental batch of the sample, <paramref name="between"/> done to its folder, then the same batch again, whose run <paramref name="check"/> sees.</summary>
    private static void SampleTwice(Action<TempDir> between, Action<TempDir, CliRun> check)
    {
        using var dat = ForgeDat(SampleDats.Spec);
        var (first, dir) = RunBatch("--all", "--dat", dat.Path, "--incremental");
        using (dir)
        {
            Assert.Equal(0, first.ExitCode);
            between(dir);
            var second = CliRun.Of("batch", "--out", dir.Path, "--all", "--dat", dat.Path, "--incremental");
            Assert.Equal(0, second.ExitCode);
            Assert.Contains($"{SampleSetups} setup(s) unchanged in the dat and not re-exported", second.Out);
            check(dir, second);
        }
    }

    [Fact]
    public void A_second_run_with_nothing_changed_reexports_nothing_and_writes_nothing()
    {
        Dictionary<string, byte[]> before = [];
        SampleTwice(dir => before = ReadAll(dir), (dir, second) =>
        {
            Assert.Contains("files: 0 written", second.Out);
            AssertSame(before, ReadAll(dir));
        });
    }

    [Fact]
    public void A_state_laid_out_by_hand_is_trusted_by_its_checksum_and_written_again_as_the_writer_lays_it_out()
    {
        var written = "";
        SampleTwice(dir =>
        {
            var state = Path.Combine(dir.Path, "incremental.json");
            written = File.ReadAllText(state);
            // The same JSON, indented with tabs: its checksum (over the canonical body) still holds.
            File.WriteAllText(state, written.Replace("  ", "\t", StringComparison.Ordinal));
        }, (dir, _) => Assert.Equal(written, File.ReadAllText(Path.Combine(dir.Path, "incremental.json"))));
    }

    [Fact]
    public void A_changed_gfxobj_reexports_only_the_setups_that_use_it_and_the_result_equals_a_fresh_run()
    {
        using var original = ForgeDat(SampleDats.Spec);
        using var changed = ForgeDat(MoveHouseVertex(SampleDats.Spec));
        var (first, dir) = RunBatch("--all", "--dat", original.Path, "--incremental");
        var (fresh, expected) = RunBatch("--all", "--dat", changed.Path);
        using (dir)
        using (expected)
        {
            Assert.Equal(0, first.ExitCode);
            Assert.Equal(0, fresh.ExitCode);
            var second = CliRun.Of("batch", "--out", dir.Path, "--all", "--dat", changed.Path, "--incremental");
            Assert.Equal(0, second.ExitCode);
            // Only the house's Setup uses the house GfxObj.
            Assert.Contains($"{SampleSetups - 1} setup(s) unchanged in the dat and not re-exported", second.Out);
            var actual = ReadAll(dir);
            actual.Remove("incremental.json");
            AssertSame(ReadAll(expected), actual);
        }
    }

    [Fact]
    public void A_deleted_output_file_is_written_again()
    {
        using var dat = ForgeDat(SampleDats.Spec);
        var (first, dir) = RunBatch("--all", "--dat", dat.Path, "--incremental");
        using (dir)
        {
            Assert.Equal(0, first.ExitCode);
            var before = ReadAll(dir);
            File.Delete(Path.Combine(dir.Path, "gfxobjs", $"0x{SampleSpecAuthor.House:X8}.bsp.json"));
            var second = CliRun.Of("batch", "--out", dir.Path, "--all", "--dat", dat.Path, "--incremental");
            Assert.Equal(0, second.ExitCode);
            // The deleted file, and index.json (removed before the run's first write, written again last).
            Assert.Contains("files: 2 written", second.Out);
            AssertSame(before, ReadAll(dir));
        }
    }

    private static void AssertSame(Dictionary<string, byte[]> expected, Dictionary<string, byte[]> actual)
    {
        Assert.Equal(expected.Keys.Order(), actual.Keys.Order());
        foreach (var (path, bytes) in expected) Assert.True(bytes.AsSpan().SequenceEqual(actual[path]), $"{path} differs");
    }

    /// <summary>The house's first vertex 1 cm higher: same byte length, so no other dat entry moves.</summary>
    private static ForgeSpec MoveHouseVertex(ForgeSpec spec) => spec with
    {
        GfxObjs = spec.GfxObjs.Select(g => g.Id != $"0x{SampleSpecAuthor.House:X8}" ? g : g with
        {
            Vertices = g.Vertices.Select((v, i) => i == 0 ? new[] { v![0], v[1], v[2] + 0.01 } : v).ToArray(),
        }).ToArray(),
    };

    private static TempDir ForgeDat(ForgeSpec spec)
    {
        var dir = new TempDir();
        File.WriteAllBytes(Path.Combine(dir.Path, ForgeApp.PortalFileName), SpecCompiler.Compile(spec).Portal);
        return dir;
    }
}
