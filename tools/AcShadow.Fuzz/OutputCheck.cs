using System.Security.Cryptography;
using System.Text.Json;

namespace AcShadow.Fuzz;

/// <summary>
/// An output folder is acceptable when every file in it is whole: no temporary file left behind, every JSON
/// file parses (a truncated JSON is exactly what a collision test must never load), and an index.json lists
/// only files that are there with the bytes it hashed.
/// </summary>
public static class OutputCheck
{
    public static string? Problem(string folder)
    {
        if (!Directory.Exists(folder)) return null;
        foreach (var file in Directory.EnumerateFiles(folder, "*", SearchOption.AllDirectories).Order(StringComparer.Ordinal))
        {
            var name = Path.GetRelativePath(folder, file);
            if (file.EndsWith(".tmp", StringComparison.Ordinal)) return $"temporary file left behind: {name}";
            if (!file.EndsWith(".json", StringComparison.Ordinal)) return $"unexpected file: {name}";
            try
            {
                using var document = JsonDocument.Parse(File.ReadAllBytes(file));
            }
            catch (JsonException e)
            {
                return $"{name} is not whole JSON: {e.Message}";
            }
        }
        return IndexProblem(folder);
    }

    /// <summary>index.json, written last, must describe files that are all there with the bytes it hashed.</summary>
    private static string? IndexProblem(string folder)
    {
        var index = Path.Combine(folder, "index.json");
        if (!File.Exists(index)) return null;
        using var document = JsonDocument.Parse(File.ReadAllBytes(index));
        if (!document.RootElement.TryGetProperty("files", out var files)) return "index.json has no files list";
        foreach (var entry in files.EnumerateArray())
        {
            var path = entry.GetProperty("path").GetString() ?? "";
            var file = Path.Combine(folder, path);
            if (!File.Exists(file)) return $"index.json lists {path}, which is not there";
            var hash = Convert.ToHexStringLower(SHA256.HashData(File.ReadAllBytes(file)));
            if (hash != entry.GetProperty("sha256").GetString()) return $"{path} does not have the bytes index.json hashed";
        }
        return null;
    }
}
