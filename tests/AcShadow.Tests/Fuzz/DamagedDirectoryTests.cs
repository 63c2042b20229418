using System.Buffers.Binary;
using AcShadow.Core.Dat;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Fuzz;

/// <summary>
/// Issue 32 item 10: one damaged directory, one answer. The sample's objects are written into a dat large
/// enough for a two-level B-tree, its directory is damaged one way, and every command that opens the dat
/// (dump, batch, audit, doctor, chart, scene, verify) must give the same exit code and the same line.
/// Before, a lookup searched only its own path: a self-loop or an out-of-file branch passed `dump` (exit 0)
/// and failed `batch` (exit 3); a root of 0 listed nothing, so audit and doctor passed a 25 MB dat.
/// </summary>
public class DamagedDirectoryTests
{
    private const string Door = "0x020019FF";
    private const int BlockSize = 1024;
    private const int RootAt = 0x160;

    public enum Damage
    {
        RootOffsetZero,
        DuplicatedBranch,
        SelfLoop,
        BranchOutsideTheFile,
    }

    /// <summary>The sample's objects and 200 small fillers: more than one node holds, so the root has branches.</summary>
    private static byte[] TwoLevelDat()
    {
        using var sample = SampleDat.OpenPortal();
        var objects = sample.Archive.Entries.ToDictionary(e => e.Id, e => sample.Archive.ReadObjectBytes(e.Id)!);
        for (var i = 0u; i < 200; i++) objects[0x0E100000u + i] = BitConverter.GetBytes(0x0E100000u + i);
        return DatArchiveWriter.Write(objects, new DatArchiveWriter.Options(DatFileKind.Portal, BlockSize));
    }

    public static byte[] Damaged(Damage damage)
    {
        var dat = TwoLevelDat();
        var root = BinaryPrimitives.ReadInt32LittleEndian(dat.AsSpan(RootAt));
        // The root node's payload follows its block's 4-byte next pointer: branch i at root + 4 + 4i.
        var branch0 = root + 4;
        Assert.NotEqual(0, BinaryPrimitives.ReadInt32LittleEndian(dat.AsSpan(branch0)));
        switch (damage)
        {
            case Damage.RootOffsetZero: BinaryPrimitives.WriteInt32LittleEndian(dat.AsSpan(RootAt), 0); break;
            case Damage.DuplicatedBranch: dat.AsSpan(branch0, 4).CopyTo(dat.AsSpan(branch0 + 4)); break;
            case Damage.SelfLoop: BinaryPrimitives.WriteInt32LittleEndian(dat.AsSpan(branch0), root); break;
            case Damage.BranchOutsideTheFile: BinaryPrimitives.WriteInt32LittleEndian(dat.AsSpan(branch0), dat.Length + 16 * BlockSize); break;
        }
        return dat;
    }

    [Theory]
    [InlineData(Damage.RootOffsetZero, "the header's directory root is 0 (an empty dat), but the file holds")]
    [InlineData(Damage.DuplicatedBranch, "is reachable twice")]
    [InlineData(Damage.SelfLoop, "is reachable twice")]
    [InlineData(Damage.BranchOutsideTheFile, "outside the")]
    public void Every_command_gives_the_same_exit_code_and_line_for_the_same_damage(Damage damage, string reason)
    {
        using var dir = SampleDat.WriteToTempFolder();
        var fixtures = Path.Combine(dir.Path, "fixtures");
        Assert.Equal(0, CliRun.Of("batch", "--doors", "--dat", dir.Path, "--out", fixtures, "--quiet").ExitCode);
        var dat = Path.Combine(dir.Path, "client_portal.dat");
        File.WriteAllBytes(dat, Damaged(damage));
        var cell = Path.Combine(dir.Path, "client_cell_1.dat");

        string[][] commands =
        [
            ["dump", "--setup", Door, "--dat", dat, "--out", Path.Combine(dir.Path, "dump")],
            ["batch", "--all", "--dat", dat, "--out", Path.Combine(dir.Path, "batch"), "--quiet"],
            ["audit", "--dat", dat],
            ["doctor", "--dat", dat],
            ["chart", "--setup", Door, "--dat", dat, "--out", Path.Combine(dir.Path, "chart"), "--quiet"],
            ["scene", "--landblock", "0xA9B4", "--dat", dat, "--cell-dat", cell, "--out", Path.Combine(dir.Path, "scene"), "--quiet"],
            ["verify", "--fixtures", fixtures, "--dat", dat],
        ];
        var expected = $"acshadow: --dat: {dat} is not a readable dat: client_portal.dat: ";
        foreach (var args in commands)
        {
            var run = CliRun.Of(args);
            Assert.True(run.ExitCode == 3, $"{args[0]}: exit {run.ExitCode}\n{run.Error}");
            var line = Assert.Single(run.ErrorLines, l => l.StartsWith("acshadow: ", StringComparison.Ordinal));
            Assert.StartsWith(expected, line);
            Assert.Contains(reason, line);
            Assert.False(Directory.Exists(Path.Combine(dir.Path, args[0])), $"{args[0]} made its output folder");
        }
        // The same line from each: one decision, in the dat layer.
        Assert.Single(commands.Select(a => CliRun.Of(a).ErrorLines.Single(l => l.StartsWith("acshadow: ", StringComparison.Ordinal))).Distinct());
    }

    [Fact]
    public void The_undamaged_two_level_dat_opens_and_lists_every_object()
    {
        using var archive = DatArchive.Open(new MemoryStream(TwoLevelDat()), "client_portal.dat");
        Assert.Equal(2, archive.DirectoryShape.Levels);
        Assert.True(archive.Contains(0x020019FF));
    }
}
