using System.Text.Json;

namespace AcShadow.Fuzz;

/// <summary>
/// An output folder is acceptable when every file in it is whole: no temporary file left behind, and every
/// JSON file parses (a truncated JSON is exactly what a collision test must never load).
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
        return null;
    }
}
