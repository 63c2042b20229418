namespace AcShadow.Analysis.Chart.Movement;

/// <summary>Times a model's walks: runs them and gives nanoseconds per transition. Swappable so tests get fixed numbers.</summary>
internal interface ITransitionTimer
{
    /// <param name="model">The model's name.</param>
    /// <param name="run">Runs every walk once and returns how many transitions (frames) it ran.</param>
    double NsPerTransition(string model, Func<long> run);
}
