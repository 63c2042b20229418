namespace AcShadow.Fuzz;

/// <summary>
/// Where cases write their dats and output: a fresh folder in memory-backed /dev/shm when the machine has
/// one (each case writes and deletes some 40 files; on a disk that costs more than the case), else in the temp folder.
/// </summary>
public static class ScratchFolder
{
    private const string SharedMemory = "/dev/shm";

    public static string Create()
    {
        if (Directory.Exists(SharedMemory))
        {
            try
            {
                return Directory.CreateDirectory(Path.Combine(SharedMemory, $"acshadow-fuzz-{Environment.ProcessId}-{Guid.NewGuid():N}")).FullName;
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                // Not writable here: the temp folder will do.
            }
        }
        return Directory.CreateTempSubdirectory("acshadow-fuzz-").FullName;
    }
}
