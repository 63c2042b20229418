namespace AcShadow.Analysis.Chart.Movement;

/// <summary>Wall-clock time of the one run that also gives the verdicts (the walks are run once, not again for timing).</summary>
internal sealed class StopwatchTransitionTimer : ITransitionTimer
{
    public double NsPerTransition(string model, Func<long> run)
    {
        var start = System.Diagnostics.Stopwatch.GetTimestamp();
        var transitions = run();
        var elapsed = System.Diagnostics.Stopwatch.GetElapsedTime(start);
        return transitions == 0 ? double.NaN : elapsed.TotalNanoseconds / transitions;
    }
}
