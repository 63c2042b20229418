using System.Globalization;
using AcShadow.Files;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// What one run has written (files, bytes, folders) and which writes are in flight, so that a run stopped
/// by a signal says truthfully what is on disk and leaves no temporary file: every file acshadow writes goes
/// through the output writer (Output/AtomicOutput), which reports here. The current run's ledger flows with the run
/// (to its worker threads too), so runs side by side in one process (the tests) keep their own counts.
/// </summary>
public sealed class OutputLedger
{
    private static readonly AsyncLocal<OutputLedger?> CurrentRun = new();

    /// <summary>The ledger of the run on this thread (or the run that started this work), if any.</summary>
    public static OutputLedger? Current
    {
        get => CurrentRun.Value;
        set => CurrentRun.Value = value;
    }

    private readonly object _gate = new();
    private readonly HashSet<string> _inFlight = new(StringComparer.Ordinal);
    private readonly SortedSet<string> _folders = new(StringComparer.Ordinal);
    private int _files;
    private long _bytes;
    private bool _closed;

    /// <summary>A write of <paramref name="target"/> starts; refused (as cancelled) once the run is being stopped.</summary>
    public void Begin(string target)
    {
        lock (_gate)
        {
            if (_closed) throw new OperationCanceledException("the run is being stopped: no new file is started");
            _inFlight.Add(target);
        }
    }

    /// <summary>The write ended: whole (its length given) or not at all (null).</summary>
    public void End(string folder, string target, long? written)
    {
        // Made before the lock: every job's every file passes here.
        var fullFolder = Path.GetFullPath(folder);
        lock (_gate)
        {
            _inFlight.Remove(target);
            if (written is { } bytes)
            {
                _files++;
                _bytes += bytes;
                _folders.Add(fullFolder);
            }
            Monitor.PulseAll(_gate);
        }
    }

    /// <summary>
    /// Stops the run's writing: no new file starts; those in flight get up to <paramref name="wait"/> to end
    /// whole; any still unfinished then lose their temporary file (the target keeps its earlier content).
    /// </summary>
    public void Close(TimeSpan wait)
    {
        lock (_gate)
        {
            _closed = true;
            var until = DateTime.UtcNow + wait;
            while (_inFlight.Count > 0 && until - DateTime.UtcNow is { Ticks: > 0 } left) Monitor.Wait(_gate, left);
            foreach (var target in _inFlight)
            {
                try { File.Delete(AtomicFile.TemporaryFor(target)); }
                catch (Exception e) when (e is IOException or UnauthorizedAccessException) { }
            }
        }
    }

    /// <summary>What is on disk, for the line an interrupted run ends with.</summary>
    public string Summary()
    {
        lock (_gate)
        {
            return _files == 0
                ? "nothing was written"
                : string.Create(CultureInfo.InvariantCulture,
                    $"{_files} file(s) ({_bytes} bytes) were written to {string.Join(", ", _folders)}, each whole, and no temporary file is left; the output is incomplete: run the same command again");
        }
    }
}
