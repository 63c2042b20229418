using AcShadow.Analysis.Chart.Movement;

namespace AcShadow.Tests.Chart.Movement;

/// <summary>A transition timer that runs the walks and measures nothing: a fixed time per transition, so movement files are byte-comparable.</summary>
internal sealed class FixedTransitionTimer : ITransitionTimer
{
    public double NsPerTransition(string model, Func<long> run)
    {
        run();
        return model.Length * 1000;
    }
}
