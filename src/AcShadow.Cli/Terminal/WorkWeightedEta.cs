namespace AcShadow.Cli.Terminal;

/// <summary>
/// The time left in a run whose objects differ in size, learned as it goes: the time when the first n
/// objects are done is fitted as a·n + b·W(n), where W(n) is their summed size estimate (least squares over
/// every report, a and b kept non-negative), and what is left is a·(objects left) + b·(size left).
/// Counting objects alone misleads when big ones come first: on the scale dat, a third of the Setups by id
/// hold two thirds of the polygons, and the count-based ETA said 47 minutes for a run of 26.7.
/// Until sizes and counts can be told apart it assumes an object's fixed cost equals an average object's
/// size cost. Thread-safe.
/// </summary>
public sealed class WorkWeightedEta
{
    private readonly double[] _before;
    private readonly Lock _lock = new();
    // Running sums for the two-parameter fit of elapsed seconds t on (n, w).
    private double _nn, _nw, _ww, _tn, _tw;
    private int _samples;
    private (int Done, double Seconds)? _origin;

    /// <param name="work">Each object's size estimate, in the order objects are reported done.</param>
    public WorkWeightedEta(IReadOnlyList<double> work)
    {
        _before = new double[work.Count + 1];
        for (var i = 0; i < work.Count; i++) _before[i + 1] = _before[i] + Math.Max(0, work[i]);
    }

    /// <summary>Notes that <paramref name="done"/> objects were done after <paramref name="elapsed"/>.</summary>
    public void Record(int done, TimeSpan elapsed)
    {
        if (done <= 0 || done >= _before.Length) return;
        lock (_lock)
        {
            // Counted from the first report, so start-up and the first object's one-off warm-up (JIT, the
            // timer's first long warm-up) are not taken for a cost every object pays.
            if (_origin is not { } origin)
            {
                _origin = (done, elapsed.TotalSeconds);
                return;
            }
            double n = done - origin.Done, w = _before[done] - _before[origin.Done], t = elapsed.TotalSeconds - origin.Seconds;
            if (n <= 0) return;
            _nn += n * n; _nw += n * w; _ww += w * w; _tn += t * n; _tw += t * w;
            _samples++;
        }
    }

    /// <summary>The time left once <paramref name="done"/> objects are done; null until two reports have come.</summary>
    public TimeSpan? Remaining(int done)
    {
        done = Math.Clamp(done, 0, _before.Length - 1);
        double objectsLeft = _before.Length - 1 - done, workLeft = _before[^1] - _before[done];
        double perObject, perWork;
        lock (_lock)
        {
            if (_samples == 0) return null;
            (perObject, perWork) = Fit();
        }
        var seconds = perObject * objectsLeft + perWork * workLeft;
        return double.IsFinite(seconds) && seconds >= 0 ? TimeSpan.FromSeconds(Math.Min(seconds, TimeSpan.MaxValue.TotalSeconds / 2)) : null;
    }

    private (double PerObject, double PerWork) Fit()
    {
        var det = _nn * _ww - _nw * _nw;
        if (_ww > 0 && det > 1e-9 * _nn * _ww)
        {
            var a = (_tn * _ww - _tw * _nw) / det;
            var b = (_tw * _nn - _tn * _nw) / det;
            if (a >= 0 && b >= 0) return (a, b);
            if (a < 0) return (0, _tw / _ww);
            return (_tn / _nn, 0);
        }
        // Sizes and counts have grown together so far (or there are no sizes): one rate over a combined
        // measure in which an object's fixed part weighs what an average object's size does.
        var objects = _before.Length - 1;
        var fixedPart = objects > 0 && _before[^1] > 0 ? _before[^1] / objects : 1;
        double cc = _nn * fixedPart * fixedPart + 2 * _nw * fixedPart + _ww, tc = _tn * fixedPart + _tw;
        var rate = cc > 0 ? tc / cc : 0;
        return (rate * fixedPart, rate);
    }
}
