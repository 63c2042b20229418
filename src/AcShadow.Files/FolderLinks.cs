namespace AcShadow.Files;

/// <summary>
/// Whether a path under a folder stays in it on disk: a symbolic link (or a file) where one of its folders
/// belongs leads elsewhere, so nothing is read or written through it. The folder itself is the caller's to
/// name and may be reached through a link; below it, nothing is followed.
/// </summary>
public static class FolderLinks
{
    /// <summary>
    /// The first folder of <paramref name="relative"/> ('/'-separated, under <paramref name="root"/>) that is
    /// not a folder on disk — a symbolic link, a file, a device — with what it is; null when every folder on
    /// the way is a real folder or not there yet. With <paramref name="includeLast"/>, the last segment is
    /// looked at too, and only a link counts there.
    /// </summary>
    public static (string Path, FileKind Kind)? FirstDetour(string root, string relative, bool includeLast = false)
    {
        var segments = relative.Split('/');
        var path = root;
        for (var i = 0; i < segments.Length; i++)
        {
            path = Path.Combine(path, segments[i]);
            var last = i == segments.Length - 1;
            if (last && !includeLast) break;
            var kind = FileKinds.Of(path);
            if (kind == FileKind.Missing) return null;
            if (last ? kind == FileKind.SymbolicLink : kind is not (FileKind.Folder or FileKind.Unknown)) return (path, kind);
        }
        return null;
    }

    /// <summary>What a symbolic link holds (its target as written), or null when <paramref name="path"/> is none.</summary>
    public static string? TargetOf(string path)
    {
        try
        {
            return new FileInfo(path).LinkTarget;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return null;
        }
    }
}
