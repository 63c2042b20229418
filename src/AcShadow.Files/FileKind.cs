namespace AcShadow.Files;

/// <summary>What a path names, without following a final symbolic link.</summary>
public enum FileKind
{
    Missing,
    Regular,
    Folder,
    SymbolicLink,
    Fifo,
    CharacterDevice,
    BlockDevice,
    Socket,
    /// <summary>The platform could not say (the path exists).</summary>
    Unknown,
}
