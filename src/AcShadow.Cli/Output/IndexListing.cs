using AcShadow.Core.Batch;
using AcShadow.Core.Formats;
using AcShadow.Files;
using AcShadow.Fixtures.Formats;

namespace AcShadow.Cli.Output;

/// <summary>The paths the folder's own index.json lists: a damaged fixture it lists is still ours to repair.</summary>
public static class IndexListing
{
    /// <summary>Empty when there is no index, it is not a regular file, or it is not an acshadow index.</summary>
    public static IReadOnlySet<string> Read(string root)
    {
        var path = Path.Combine(root, FileFormats.Index.Path);
        try
        {
            if (FileKinds.Of(path) != FileKind.Regular) return new HashSet<string>();
            return BatchIndexReader.Read(File.ReadAllBytes(path)).Files.Select(f => f.Path).ToHashSet(StringComparer.Ordinal);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or FormatException or InvalidOperationException)
        {
            return new HashSet<string>();
        }
    }
}
