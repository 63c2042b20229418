using AcShadow.Files;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Files;

/// <summary>
/// Threads of one process writing the same target at once: every temporary file is named for the process
/// (<c>NAME.PID.tmp</c>), so without a turn each, one writer's temporary was another's to truncate, delete or
/// rename into place half-written. Each write must end whole, and the target hold one writer's bytes.
/// </summary>
public class SameTargetWritersTests
{
    private static byte[][] Contents(int writers) =>
        [.. Enumerable.Range(0, writers).Select(w => Enumerable.Range(0, 200_000).Select(i => (byte)(i * 13 + w)).ToArray())];

    private static void AssertOneWritersBytesAndNoTemporary(string dir, string target, byte[][] contents)
    {
        var onDisk = File.ReadAllBytes(target);
        Assert.Contains(contents, c => c.AsSpan().SequenceEqual(onDisk));
        Assert.Equal([Path.GetFileName(target)], Directory.GetFileSystemEntries(dir).Select(Path.GetFileName));
    }

    /// <summary>One thread per writer, all let go at once (a thread pool may run them one after another).</summary>
    private static void RunTogether(int writers, Action<int> write)
    {
        using var start = new Barrier(writers);
        var failures = new Exception?[writers];
        var threads = Enumerable.Range(0, writers).Select(w => new Thread(() =>
        {
            start.SignalAndWait();
            try { write(w); }
            catch (Exception e) { failures[w] = e; }
        })).ToArray();
        foreach (var thread in threads) thread.Start();
        foreach (var thread in threads) thread.Join();
        Assert.All(failures, Assert.Null);
    }

    [Fact]
    public void Replacing_writers_of_one_target_all_end_whole()
    {
        using var dir = new TempDir();
        var target = Path.Combine(dir.Path, "chart.csv");
        var contents = Contents(4);

        RunTogether(contents.Length, w =>
        {
            for (var i = 0; i < 200; i++)
                Assert.Equal(contents[w].Length, AtomicFile.Write(target, contents[w], Durability.Renamed));
        });

        AssertOneWritersBytesAndNoTemporary(dir.Path, target, contents);
    }

    [Fact]
    public void New_file_writers_of_one_target_leave_it_to_exactly_one_of_them()
    {
        var contents = Contents(4);
        for (var round = 0; round < 50; round++)
        {
            using var dir = new TempDir();
            var target = Path.Combine(dir.Path, "0x01000001.bsp.json");
            var results = new long?[contents.Length];

            RunTogether(contents.Length, w => results[w] = AtomicFile.WriteNew(target, contents[w], Durability.Renamed));

            var winner = Assert.Single(Enumerable.Range(0, contents.Length), w => results[w] is not null);
            Assert.Equal(contents[winner], File.ReadAllBytes(target));
            AssertOneWritersBytesAndNoTemporary(dir.Path, target, contents);
        }
    }
}
