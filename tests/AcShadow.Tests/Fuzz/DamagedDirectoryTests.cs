using System.Buffers.Binary;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Fuzz;

/// <summary>
/// Issue 32 item 10: one damaged directory, one answer. The sample's objects are written into a dat large
/// enough for a two-level B-tree, its directory is damaged one way on the door's path, and every command
/// (dump, batch, audit, doctor, chart, scene, verify) must give the same exit code and the same line: the
/// listing commands walk the whole directory at open, and a lookup checks every node it reads the same way.
/// Issue 30 item 5: a lookup reads only its own path, so damage off it is found by the walk only (dump of
/// a Setup elsewhere in the dat passes, as the client's own search would); before issue 32 even damage on
/// the path passed `dump`, and a root of 0 listed nothing, so audit and doctor passed a 25 MB dat.
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

    /// <summary>The root's branch slot a lookup of the door follows.</summary>
    private static int DoorSlot(byte[] dat, int root)
    {
        // The node's payload spans two contiguous 1,024-byte blocks, each after its 4-byte next pointer.
        byte[] payload = [.. dat.AsSpan(root + 4, BlockSize - 4), .. dat.AsSpan(root + BlockSize + 4, BlockSize - 4)];
        var node = DatBTreeNode.Read(new DatBinaryReader(payload), root);
        Assert.False(node.IsLeaf);
        var slot = node.Entries.Count(e => e.Id < 0x020019FFu);
        Assert.True(slot == node.Entries.Count || node.Entries[slot].Id != 0x020019FFu, "the door is in the root: its lookup reads no branch");
        return slot;
    }

    /// <summary>The dat damaged in the root's branch slot the door's lookup follows.</summary>
    public static byte[] Damaged(Damage damage)
    {
        var dat = TwoLevelDat();
        var root = BinaryPrimitives.ReadInt32LittleEndian(dat.AsSpan(RootAt));
        var slot = DoorSlot(dat, root);
        var neighbour = slot == 0 ? 1 : slot - 1;
        // Branch i sits at root + 4 + 4i, after the block's 4-byte next pointer.
        var at = root + 4 + 4 * slot;
        Assert.NotEqual(0, BinaryPrimitives.ReadInt32LittleEndian(dat.AsSpan(at)));
        switch (damage)
        {
            case Damage.RootOffsetZero: BinaryPrimitives.WriteInt32LittleEndian(dat.AsSpan(RootAt), 0); break;
            case Damage.DuplicatedBranch: dat.AsSpan(root + 4 + 4 * neighbour, 4).CopyTo(dat.AsSpan(at)); break;
            case Damage.SelfLoop: BinaryPrimitives.WriteInt32LittleEndian(dat.AsSpan(at), root); break;
            case Damage.BranchOutsideTheFile: BinaryPrimitives.WriteInt32LittleEndian(dat.AsSpan(at), dat.Length + 16 * BlockSize); break;
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
    public void Damage_in_a_leaf_off_a_lookups_path_is_found_by_the_listing_commands_only()
    {
        // The last leaf holds only fillers; its entry count beyond what a node holds.
        var bytes = TwoLevelDat();
        var root = BinaryPrimitives.ReadInt32LittleEndian(bytes.AsSpan(RootAt));
        var last = BinaryPrimitives.ReadInt32LittleEndian(bytes.AsSpan(root + 4 + 4 * DatBTreeNode.MaxBranches));
        Assert.NotEqual(last, DoorSlot(bytes, root));
        var leaf = BinaryPrimitives.ReadInt32LittleEndian(bytes.AsSpan(root + 4 + 4 * last));
        BinaryPrimitives.WriteInt32LittleEndian(bytes.AsSpan(leaf + 4 + 4 * DatBTreeNode.MaxBranches), DatBTreeNode.MaxEntries + 1);
        using var dir = new TempDir();
        var dat = Path.Combine(dir.Path, "client_portal.dat");
        File.WriteAllBytes(dat, bytes);

        var dump = CliRun.Of("dump", "--setup", Door, "--dat", dat, "--out", Path.Combine(dir.Path, "dump"));
        var batch = CliRun.Of("batch", "--all", "--dat", dat, "--out", Path.Combine(dir.Path, "batch"), "--quiet");

        Assert.True(dump.ExitCode == 0, dump.Error);
        Assert.Equal(3, batch.ExitCode);
        Assert.Contains($"B-tree node at 0x{leaf:X8} claims 62 entries", Assert.Single(batch.ErrorLines, l => l.StartsWith("acshadow: --dat: ", StringComparison.Ordinal)));
        Assert.False(Directory.Exists(Path.Combine(dir.Path, "batch")));
    }

    [Fact]
    public void The_undamaged_two_level_dat_opens_and_lists_every_object()
    {
        using var archive = DatArchive.Open(new MemoryStream(TwoLevelDat()), "client_portal.dat");
        Assert.Equal(2, archive.DirectoryShape.Levels);
        Assert.True(archive.Contains(0x020019FF));
    }
}
