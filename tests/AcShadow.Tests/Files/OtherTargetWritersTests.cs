using AcShadow.Files;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Files;

/// <summary>
/// A write in flight holds only its own target's turn: a streamed write whose callback waits for another thread
/// (chart's chart.csv, written while the chart runs, waits for the worker delivering the next object) must not stop
/// that thread's writes of other files. Turns shared by targets whose hashes met deadlocked chart --all --jobs 2
/// within its first few hundred failure maps.
/// </summary>
public class OtherTargetWritersTests
{
    [Fact]
    public void Writes_of_other_targets_go_on_while_a_streamed_write_waits_inside_its_callback()
    {
        using var dir = new TempDir();
        const int Others = 2_000;
        var othersDone = new ManualResetEventSlim();
        Exception? otherFailure = null;
        var finishedInTime = false;

        AtomicFile.Write(Path.Combine(dir.Path, "chart.csv"), stream =>
        {
            stream.Write("model,ns\n"u8);
            var other = new Thread(() =>
            {
                try
                {
                    for (var i = 0; i < Others; i++)
                    {
                        var path = Path.Combine(dir.Path, $"failure-map-0x{0x02000000 + i:X8}.svg");
                        if (i % 2 == 0) AtomicFile.Write(path, "<svg/>"u8, Durability.Renamed);
                        else AtomicFile.Write(path, s => s.Write("<svg/>"u8), Durability.Renamed);
                    }
                }
                catch (Exception e)
                {
                    otherFailure = e;
                }
                othersDone.Set();
            });
            other.Start();
            // Liveness, not speed: a deadlock never sets the event; two thousand small files take well under a second.
            finishedInTime = othersDone.Wait(TimeSpan.FromSeconds(60));
        }, Durability.Renamed);

        Assert.True(finishedInTime, "the other thread's writes waited for the streamed write's turn");
        Assert.Null(otherFailure);
        Assert.Equal(Others + 1, Directory.GetFiles(dir.Path).Length);
        Assert.Equal("model,ns\n", File.ReadAllText(Path.Combine(dir.Path, "chart.csv")));
    }
}
