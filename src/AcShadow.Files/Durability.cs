namespace AcShadow.Files;

/// <summary>Whether an atomic write waits for its bytes to reach the disk before the rename.</summary>
public enum Durability
{
    /// <summary>
    /// Renamed as soon as written: a killed process leaves the old file or the new one, whole; a power cut
    /// may leave an empty or old file. For many small files that are cheap to make again (acshadow's
    /// output: a batch writes tens of thousands, and a flush each would cost more than the batch).
    /// </summary>
    Renamed,

    /// <summary>
    /// Flushed to the disk, then renamed: whole after a power cut too. For few large files that are costly
    /// to make again (the forge's dats).
    /// </summary>
    Flushed,
}
