namespace AcShadow.Fixtures.Movement;

/// <summary>
/// What one transition did beyond its result: the responses it ran (step up, step down, slide, edge slide,
/// landing), in order with repeats folded, and the smallest margin of the threshold decisions it took (the
/// step count against a whole number of radii, the slide's |o|² and |d|² against ε, a touched polygon's
/// |dist| against r − ε). A margin under the perturbation a case is rerun with makes the case fragile.
/// </summary>
internal sealed class MovementTrace
{
    private readonly List<string> _events = [];

    public IReadOnlyList<string> Events => _events;

    public float MinMargin { get; private set; } = float.PositiveInfinity;

    public void Event(string name)
    {
        if (_events.Count == 0 || _events[^1] != name) _events.Add(name);
    }

    public void Margin(float margin)
    {
        margin = MathF.Abs(margin);
        if (margin < MinMargin) MinMargin = margin;
    }
}
