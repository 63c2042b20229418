using AcShadow.Tests.Support;

namespace AcShadow.Tests.Batch;

/// <summary>Helpers for batch tests: run batch into a temp folder and read what it wrote.</summary>
internal static class BatchRuns
{
    public static (CliRun Run, TempDir Out) RunBatch(params string[] args)
    {
        var dir = new TempDir();
        var run = CliRun.Of(["batch", "--out", dir.Path, .. args]);
        return (run, dir);
    }

    public static Dictionary<string, byte[]> ReadAll(TempDir dir) =>
        dir.Files().ToDictionary(f => f, f => File.ReadAllBytes(Path.Combine(dir.Path, f)));

    public static string Text(TempDir dir, string relative) => File.ReadAllText(Path.Combine(dir.Path, relative));

    /// <summary>A setups file in its own temp folder.</summary>
    public static (TempDir Dir, string Path) SetupsFile(string text)
    {
        var dir = new TempDir();
        var path = System.IO.Path.Combine(dir.Path, "ids.txt");
        File.WriteAllText(path, text);
        return (dir, path);
    }
}
