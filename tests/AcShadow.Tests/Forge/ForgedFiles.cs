using AcShadow.Core.Dat;
using AcShadow.Files;
using AcShadow.Forge;
using AcShadow.Forging;

namespace AcShadow.Tests.Forge;

/// <summary>
/// Dat files the forge actually wrote to disk (through its CLI entry point), opened with the real reader.
/// </summary>
public sealed class ForgedFiles : IDisposable
{
    public string Directory { get; }
    public DatDatabase Portal { get; }
    public DatDatabase? Cell { get; }

    private ForgedFiles(string directory)
    {
        Directory = directory;
        Portal = Open(Path.Combine(directory, ForgeApp.PortalFileName));
        var cell = Path.Combine(directory, ForgeApp.CellFileName);
        Cell = File.Exists(cell) ? Open(cell) : null;
    }

    public static string NewDirectory() => System.IO.Directory.CreateTempSubdirectory("forge-test-").FullName;

    /// <summary>Runs `forge ARGS --out DIR` in-process and opens what it wrote; fails the test if it did not succeed.</summary>
    public static ForgedFiles Run(params string[] args)
    {
        var dir = NewDirectory();
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        var code = ForgeApp.Run([.. args, "--out", dir], stdout, stderr);
        Assert.True(code == 0, $"forge {string.Join(' ', args)} exited {code}: {stderr}");
        return new ForgedFiles(dir);
    }

    /// <summary>Writes bytes the compiler produced to disk and opens them, as the CLI would.</summary>
    public static ForgedFiles Write(ForgedDats dats)
    {
        var dir = NewDirectory();
        AtomicFile.Write(Path.Combine(dir, ForgeApp.PortalFileName), dats.Portal, Durability.Flushed);
        if (dats.Cell is { } cell) AtomicFile.Write(Path.Combine(dir, ForgeApp.CellFileName), cell, Durability.Flushed);
        return new ForgedFiles(dir);
    }

    private static DatDatabase Open(string path) =>
        DatDatabase.Open(new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read), Path.GetFileName(path));

    public void Dispose()
    {
        Portal.Dispose();
        Cell?.Dispose();
        try { System.IO.Directory.Delete(Directory, recursive: true); } catch (IOException) { }
    }
}

/// <summary>The built-in sample, forged once per test class through `forge sample`.</summary>
public sealed class SampleFixture : IDisposable
{
    public ForgedFiles Files { get; } = ForgedFiles.Run("sample");
    public void Dispose() => Files.Dispose();
}

/// <summary>A small scale spec (120 Setups), forged once per test class through `forge scale`.</summary>
public sealed class SmallScaleFixture : IDisposable
{
    public const int Setups = 120, Seed = 7;
    public ForgedFiles Files { get; } = ForgedFiles.Run("scale", "--setups", Setups.ToString(), "--seed", Seed.ToString());
    public void Dispose() => Files.Dispose();
}
