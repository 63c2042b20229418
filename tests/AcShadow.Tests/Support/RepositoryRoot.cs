namespace AcShadow.Tests.Support;

/// <summary>The clone the tests run from: the folder above the test binaries that holds AcShadow.sln.</summary>
internal static class RepositoryRoot
{
    internal static string Path { get; } = Find();

    private static string Find()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
            if (File.Exists(System.IO.Path.Combine(dir.FullName, "AcShadow.sln"))) return dir.FullName;
        throw new InvalidOperationException($"no AcShadow.sln above {AppContext.BaseDirectory}");
    }
}
