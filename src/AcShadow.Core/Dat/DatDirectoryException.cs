namespace AcShadow.Core.Dat;

/// <summary>
/// The dat's directory B-tree is damaged: the whole dat is refused, not one object. Its own type, not a
/// <see cref="Binary.DatFormatException"/>, so code that skips one unreadable object (a part, a placed
/// object) cannot swallow it when a lookup meets the damage after the dat opened (the directory is read a
/// path at a time, <see cref="DatDirectory"/>). The message starts with the dat's name, as at open.
/// </summary>
public sealed class DatDirectoryException(DatArchive archive, string message, Exception? inner = null) : Exception(message, inner)
{
    /// <summary>The archive whose directory is damaged (the CLI names its file from it).</summary>
    public DatArchive Archive { get; } = archive;
}
