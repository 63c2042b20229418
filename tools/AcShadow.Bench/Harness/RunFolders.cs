namespace AcShadow.Bench.Harness;

/// <summary>
/// The empty output folder each timed run writes into. On disk every run gets a folder of its own and
/// nothing is deleted until the workloads of one place are done: ext4 skips, one by one, each inode
/// freed in the last minute when it looks for a free one (ialloc.c, recently_deleted), so deleting the
/// previous run's 22,000 files just before a run made creating 22,000 new ones quadratic in the kernel
/// (5 to 23 s of system time for the same run). The caller deletes disk folders when the bench ends. In
/// memory (tmpfs) a folder is emptied and reused.
/// </summary>
public sealed class RunFolders(string root, bool onDisk)
{
    private readonly List<string> _made = [];

    /// <summary>An empty folder for run <paramref name="run"/> (-1 the warm-up) of <paramref name="workload"/>; file systems flushed.</summary>
    public string Empty(string workload, int run)
    {
        var dir = Path.Combine(root, onDisk ? $"{workload}-run{run + 2}" : workload);
        BenchHarness.Reset(dir);
        if (!_made.Contains(dir)) _made.Add(dir);
        return dir;
    }

    /// <summary>Deletes every folder handed out.</summary>
    public void Clear()
    {
        foreach (var dir in _made)
            if (Directory.Exists(dir)) Directory.Delete(dir, true);
        _made.Clear();
    }
}
