namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// Puts point labels where they overlap neither each other nor the points: tries right, left, above and
/// below at growing distances and takes the first free spot inside the plot (else the last tried).
/// Deterministic: the same points in the same order get the same places.
/// </summary>
internal sealed class LabelPlacer(double left, double top, double right, double bottom)
{
    private readonly List<(double X0, double Y0, double X1, double Y1)> _taken = [];

    public void Avoid(double x, double y, double radius) => _taken.Add((x - radius, y - radius, x + radius, y + radius));

    /// <summary>Baseline position and text-anchor for a label of the given size near (x, y).</summary>
    public (double X, double Y, string Anchor) Place(double x, double y, double width, double height)
    {
        (double X, double Y, string Anchor) last = (x + 10, y - 8, "start");
        for (var ring = 0; ring < 8; ring++)
        {
            var step = ring * (height + 2);
            foreach (var (dx, dy, anchor) in new (double, double, string)[]
                     {
                         (10, -8 - step, "start"), (10, 18 + step, "start"), (-10, -8 - step, "end"), (-10, 18 + step, "end"),
                     })
            {
                var bx0 = anchor == "start" ? x + dx : x + dx - width;
                var by0 = y + dy - height + 3;
                var box = (bx0, by0, bx0 + width, by0 + height);
                last = (x + dx, y + dy, anchor);
                if (box.Item1 < left || box.Item3 > right || box.Item2 < top || box.Item4 > bottom) continue;
                if (_taken.Any(t => t.X0 < box.Item3 && box.Item1 < t.X1 && t.Y0 < box.Item4 && box.Item2 < t.Y1)) continue;
                _taken.Add(box);
                return last;
            }
        }
        return last;
    }
}
