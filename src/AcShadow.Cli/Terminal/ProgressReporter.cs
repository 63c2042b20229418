using System.Diagnostics;
using System.Globalization;
using AcShadow.Core.Batch;

namespace AcShadow.Cli.Terminal;

/// <summary>
/// Shows a batch's progress on stderr: on a terminal a bar redrawn in place (rate and ETA) at most ten
/// times a second; otherwise a plain line every few seconds, so logs stay readable; nothing when quiet.
/// Called from worker threads.
/// </summary>
public sealed class ProgressReporter
{
    private const int BarWidth = 28;
    private static readonly TimeSpan TerminalInterval = TimeSpan.FromMilliseconds(100);
    private static readonly TimeSpan PlainInterval = TimeSpan.FromSeconds(2);

    private readonly TextWriter _error;
    private readonly bool _terminal;
    private readonly bool _quiet;
    private readonly string _unit;
    private readonly string _label;
    private readonly Stopwatch _clock = Stopwatch.StartNew();
    private readonly Lock _lock = new();
    private readonly Func<int, TimeSpan?>? _remaining;
    private TimeSpan _lastShown = TimeSpan.Zero;
    private bool _drawn;

    /// <param name="label">The command's name, which starts each plain progress line ("batch: …", "chart: …").</param>
    /// <param name="remaining">The time left once so many are done (null: "not yet known"); by default, those left at the average rate so far.</param>
    public ProgressReporter(TextWriter error, bool isTerminal, bool quiet, string unit, string label, Func<int, TimeSpan?>? remaining = null)
    {
        _remaining = remaining;
        _label = label;
        _error = error;
        _terminal = isTerminal;
        _quiet = quiet;
        _unit = unit;
    }

    public void Report(BatchProgress progress)
    {
        if (_quiet || progress.Total == 0) return;
        lock (_lock)
        {
            var now = _clock.Elapsed;
            var last = progress.Done >= progress.Total;
            if (now - _lastShown < (_terminal ? TerminalInterval : PlainInterval) && !(last && _terminal && _drawn)) return;
            _lastShown = now;
            if (_terminal)
            {
                _error.Write("\r" + Bar(progress, now) + "\u001b[K");
                _drawn = true;
            }
            else if (!last)
            {
                _error.WriteLine($"{_label}: " + Counts(progress, now));
            }
        }
    }

    /// <summary>Ends the in-place bar with a newline so later output starts on its own line.</summary>
    public void Finish()
    {
        lock (_lock)
        {
            if (_drawn) _error.WriteLine();
            _drawn = false;
        }
    }

    private string Bar(BatchProgress p, TimeSpan elapsed)
    {
        var filled = (int)((long)BarWidth * p.Done / p.Total);
        return $"[{new string('#', filled)}{new string('.', BarWidth - filled)}] {Counts(p, elapsed)}";
    }

    private string Counts(BatchProgress p, TimeSpan elapsed)
    {
        var seconds = Math.Max(elapsed.TotalSeconds, 1e-3);
        var rate = p.Done / seconds;
        TimeSpan? eta = _remaining is null ? (rate > 0 ? TimeSpan.FromSeconds((p.Total - p.Done) / rate) : TimeSpan.Zero) : _remaining(p.Done);
        return string.Create(CultureInfo.InvariantCulture,
            $"{p.Done}/{p.Total} {_unit} ({100L * p.Done / p.Total}%), {rate:0.0}/s, ETA {(eta is { } e ? $"{(int)e.TotalMinutes}:{e.Seconds:00}" : "not yet known")}");
    }
}
