using AcShadow.Cli.Infrastructure;
using AcShadow.Files;

namespace AcShadow.Cli.Output;

/// <summary>
/// A run's hold on its output folder (<see cref="FolderLock"/>): a second writer into the same folder is
/// refused before it writes anything, and a folder moved or deleted while the run wrote is found before
/// the run says it succeeded.
/// </summary>
public sealed class OutputFolderLock : IDisposable
{
    private readonly FolderLock _lock;
    private readonly string _root;

    private OutputFolderLock(FolderLock held, string root)
    {
        _lock = held;
        _root = root;
    }

    public static OutputFolderLock Acquire(string root, string option = "--out")
    {
        FolderLock? held;
        try
        {
            held = FolderLock.TryAcquire(root);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException(ExitCodes.OutputFailed, $"{option}: cannot lock folder {root}: {e.Message} (pass a folder you can write to)");
        }
        return held is null
            ? throw new CliException(ExitCodes.OutputFailed, $"{option}: another acshadow run is writing into {root}: wait for it to finish or pass another folder; nothing was written")
            : new OutputFolderLock(held, root);
    }

    /// <summary>Fails (exit 6) when the folder at the path is no longer the one this run locked and wrote into.</summary>
    public void RequireStillInPlace()
    {
        if (!_lock.StillInPlace())
            throw new CliException(ExitCodes.OutputFailed,
                $"--out: {_root} was moved or deleted while this run wrote into it: what it wrote is not all at {_root}; run again");
    }

    public void Dispose() => _lock.Dispose();
}
