namespace AcShadow.Core.Formats;

/// <summary>
/// A path of an output folder's file as acshadow records it (index.json, incremental.json): relative,
/// '/'-separated, every segment a plain name. Anything else (a rooted path, "..", ".", an empty segment, a
/// backslash, a drive letter) could lead out of the folder, so a file read back from disk that names one is
/// not trusted: an index or a state file is data, never a licence to read or reuse a file elsewhere.
/// </summary>
public static class RelativeOutputPath
{
    public static bool StaysInside(string? path)
    {
        if (string.IsNullOrEmpty(path) || path.Contains('\\') || path.Contains(':') || path.Contains('\0') || Path.IsPathRooted(path)) return false;
        foreach (var segment in path.Split('/'))
            if (segment is "" or "." or "..") return false;
        return true;
    }
}
