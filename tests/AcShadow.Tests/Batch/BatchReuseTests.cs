using System.Collections.Concurrent;
using AcShadow.Core.Batch;
using AcShadow.Core.Formats;
using AcShadow.Fixtures.Batch;

namespace AcShadow.Tests.Batch;

/// <summary>
/// The incremental fast path's checks of the previous run's files: each recorded file is read and hashed once a
/// run, however many Setups list it (a GfxObj's dump is listed by every Setup naming the part), and a file that
/// fails its check keeps every Setup listing it from being reused.
/// </summary>
public sealed class BatchReuseTests
{
    private const string Tool = "tool-key";
    private static readonly FileEntry SharedDump = new("gfxobjs/0x01000010.bsp.json", FixtureKind.Bsp, 0x01000010, 0, 12, 400, new string('a', 64));

    private static IncrementalSetup Record(uint setup, params FileEntry[] files)
    {
        uint[] parts = [0x01000010];
        var fingerprint = new BatchReuse(null, Tool, ReadObject, _ => true).Fingerprint(setup, parts);
        return new IncrementalSetup(setup, fingerprint, parts, 0, files);
    }

    private static FileEntry Shadow(uint setup) => new($"setups/0x{setup:X8}.shadow.json", FixtureKind.Shadow, setup, 1, 0, 200, new string('b', 64));

    /// <summary>Every object the test names exists, its bytes its id.</summary>
    private static int ReadObject(uint id, ref byte[] buffer)
    {
        if (buffer.Length < 4) buffer = new byte[4];
        BitConverter.TryWriteBytes(buffer, id);
        return 4;
    }

    [Fact]
    public void A_file_listed_by_several_setups_is_checked_once()
    {
        var checks = new ConcurrentDictionary<string, int>();
        var state = new IncrementalState(Tool, [Record(0x02000001, Shadow(0x02000001), SharedDump), Record(0x02000002, Shadow(0x02000002), SharedDump),
            Record(0x02000003, Shadow(0x02000003), SharedDump)]);
        var reuse = new BatchReuse(state, Tool, ReadObject, file =>
        {
            checks.AddOrUpdate(file.RelativePath, 1, (_, n) => n + 1);
            return true;
        });
        foreach (var setup in new uint[] { 0x02000001, 0x02000002, 0x02000003 })
            Assert.NotNull(reuse.TryReuse(setup));
        Assert.Equal(1, checks[SharedDump.RelativePath]);
        Assert.Equal(4, checks.Count);
        Assert.All(checks.Values, n => Assert.Equal(1, n));
    }

    [Fact]
    public void A_shared_file_that_fails_its_check_keeps_every_setup_listing_it_from_reuse()
    {
        var checks = 0;
        var state = new IncrementalState(Tool, [Record(0x02000001, SharedDump, Shadow(0x02000001)), Record(0x02000002, SharedDump, Shadow(0x02000002))]);
        var reuse = new BatchReuse(state, Tool, ReadObject, file =>
        {
            Interlocked.Increment(ref checks);
            return file != SharedDump;
        });
        Assert.Null(reuse.TryReuse(0x02000001));
        Assert.Null(reuse.TryReuse(0x02000002));
        Assert.Equal(1, checks);
    }
}
