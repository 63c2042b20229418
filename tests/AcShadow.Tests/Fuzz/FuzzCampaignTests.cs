using AcShadow.Fuzz;

namespace AcShadow.Tests.Fuzz;

/// <summary>
/// CI's fixed-seed campaign: 2,200 damaged copies of the sample dats, each run through `dump` and `batch`,
/// every 8th also through `chart` and `verify` (on the batch's fixtures with one byte damaged); every
/// command must end with a documented exit code, a "corrupt dat" message naming the object when one is
/// damaged, whole output files, and within the time and memory limits.
/// </summary>
[Trait("Speed", "Slow")]
public class FuzzCampaignTests
{
    public const long Seed = 20261122;
    /// <summary>
    /// Every 10th case cuts one base at a block boundary, the bases in turn, so the sample's boundaries (portal and
    /// cell, 107 since issue 27's Setups) need 10 x 2 x 107 cases to be cut once each: 2,200 covers them with a little room.
    /// </summary>
    public const int Cases = 2200;

    /// <summary>Chart and verify on every 8th case: 275 of them, so the campaign stays near two minutes on two cores.</summary>
    public const int DeepEvery = 8;

    [Fact]
    public void A_fixed_seed_campaign_of_2200_damaged_dats_finds_no_failure()
    {
        var scratch = ScratchFolder.Create();
        CampaignResult result;
        try
        {
            // A case takes well under a second alone; the limit only has to tell a hang from a machine shared
            // with other work (the suite's other tests, or other builds), where cases have been seen past 30 s.
            result = FuzzCampaign.Run(FuzzBase.All(), new CampaignOptions(Seed, Cases, TimeLimitSeconds: 300, DeepEvery: DeepEvery), scratch);
        }
        finally
        {
            Directory.Delete(scratch, recursive: true);
        }

        Assert.Equal(Cases, result.Cases);
        Assert.Equal(Cases / DeepEvery, result.DeepCases);
        // Deep cases also re-run batch --incremental over the damaged folder and verify it (CaseRunner.Repair).
        Assert.Equal(["batch", "batch (re-run)", "chart", "dump", "verify", "verify (re-run)"], result.CommandTimes.Keys.Order(StringComparer.Ordinal).ToArray());
        Assert.True(result.FailedCases == 0, string.Join("\n", result.Failures.Select(f =>
            $"{f.Failure.Signature} ({result.FailureCounts[f.Failure.Signature]} cases); first: {f.Input.Description}\n{f.Failure.Detail}")));
        // The campaign reaches both the happy path and the refusals: a campaign that never damaged
        // anything, or never got past opening the dat, would prove nothing.
        Assert.True(result.ExitCodeCounts.GetValueOrDefault(0) > Cases / 4, $"exit codes: {string.Join(", ", result.ExitCodeCounts)}");
        Assert.True(result.ExitCodeCounts.GetValueOrDefault(3) > Cases / 20, $"exit codes: {string.Join(", ", result.ExitCodeCounts)}");
    }

    [Fact]
    public void The_same_seed_damages_the_dats_the_same_way()
    {
        var mutator = new DatMutator(FuzzBase.All());
        for (var i = 0; i < 50; i++)
        {
            var a = mutator.Mutate(Seed, i);
            var b = mutator.Mutate(Seed, i);
            Assert.Equal(a.Description, b.Description);
            Assert.Equal(a.Portal, b.Portal);
            Assert.Equal(a.Cell, b.Cell);
        }
    }

    [Theory]
    [InlineData(0, Cases)]      // the sample: every boundary within CI's campaign
    [InlineData(1, 4 * Cases)]  // the two-level directory has twice the blocks: within the long campaign
    public void Truncation_cases_cut_at_every_block_boundary_of_both_dats(int baseIndex, int cases)
    {
        var bases = FuzzBase.All();
        var source = bases[baseIndex];
        var mutator = new DatMutator(bases);
        var portalCuts = new HashSet<int>();
        var cellCuts = new HashSet<int>();
        for (var i = 0; i < cases; i += 10)
        {
            var input = mutator.Mutate(Seed, i);
            if (input.From != source) continue;
            if (input.Portal.Length < source.Portal.Length) portalCuts.Add(input.Portal.Length);
            if (input.Cell.Length < source.Cell.Length) cellCuts.Add(input.Cell.Length);
        }
        for (var b = 0; b < source.PortalLayout.BlockCount; b++) Assert.Contains(source.PortalLayout.BlockStart(b), portalCuts);
        for (var b = 0; b < source.CellLayout.BlockCount; b++) Assert.Contains(source.CellLayout.BlockStart(b), cellCuts);
    }

    [Fact]
    public void The_second_base_has_a_two_level_directory()
    {
        var deep = FuzzBase.SampleWithDeepDirectory();
        Assert.True(deep.PortalLayout.NodeChains.Count > 1, $"{deep.PortalLayout.NodeChains.Count} B-tree node(s)");
        Assert.Equal(FuzzBase.Sample().SetupIds, deep.SetupIds);
    }

    [Fact]
    public void The_oracle_fails_an_internal_error_a_partial_file_and_an_unnamed_corrupt_object()
    {
        Assert.NotNull(CaseRunner.Judge("dump", 1, "acshadow: internal error: boom (run with --verbose ...)\nSystem.OverflowException: boom\n"));
        Assert.NotNull(CaseRunner.Judge("dump", 6, "acshadow: cannot write x\n"));
        Assert.NotNull(CaseRunner.Judge("dump", 3, "acshadow: corrupt dat: needs 4 more byte(s) at offset 3\n"));
        Assert.NotNull(CaseRunner.Judge("batch", 0, "warning: 0x02000001: unreadable-gfxobj: part 0 (GfxObj 0x01000001) cannot be read: block chain loops\n"));
        Assert.Null(CaseRunner.Judge("dump", 3, "acshadow: corrupt dat: Setup 0x02000001 in client_portal.dat: needs 4 more byte(s)\n"));
        Assert.Null(CaseRunner.Judge("dump", 3, "acshadow: --dat: x.dat is not a readable dat: magic\n"));
        Assert.Null(CaseRunner.Judge("batch", 3, "acshadow: --cell-dat: c.dat is a dat of data set 2560, not a cell dat (client_cell_1.dat): pass client_cell_1.dat there\n"));
        Assert.NotNull(CaseRunner.Judge("batch", 3, "acshadow: reading the dat failed: Unable to read beyond the end of the stream.\n"));
        Assert.Null(CaseRunner.Judge("dump", 4, "acshadow: Setup 0x02000001 is not in x\n"));

        using var folder = new Support.TempDir();
        Assert.Null(OutputCheck.Problem(folder.Path));
        File.WriteAllText(Path.Combine(folder.Path, "a.json"), "{\"shapes\": [1, 2");
        Assert.Contains("not whole JSON", OutputCheck.Problem(folder.Path));
        File.WriteAllText(Path.Combine(folder.Path, "a.json"), "{}");
        File.WriteAllText(Path.Combine(folder.Path, "b.json.123.tmp"), "{}");
        Assert.Contains("temporary file", OutputCheck.Problem(folder.Path));
        File.Delete(Path.Combine(folder.Path, "b.json.123.tmp"));
        var sha = Convert.ToHexStringLower(System.Security.Cryptography.SHA256.HashData("{}"u8));
        File.WriteAllText(Path.Combine(folder.Path, "index.json"), $"{{\"files\": [{{\"path\": \"a.json\", \"sha256\": \"{sha}\"}}]}}");
        Assert.Null(OutputCheck.Problem(folder.Path));
        File.WriteAllText(Path.Combine(folder.Path, "a.json"), "[]");
        Assert.Contains("does not have the bytes", OutputCheck.Problem(folder.Path));
        File.Delete(Path.Combine(folder.Path, "a.json"));
        Assert.Contains("not there", OutputCheck.Problem(folder.Path));
    }
}
