using System.Numerics;

namespace AcShadow.Analysis.View;

/// <summary>
/// Where the three views of a drawing sit and how a point in the view's frame (dat axes, metres) lands on
/// each, in SVG pixels. Third-angle arrangement, one scale for all three: the top view (from above: x to
/// the right, y up the page) over the front view (from −y, looking north: x right, z up), the side view
/// (from +x, looking west: y right, z up) to the front view's right, so x and z line up across views.
/// </summary>
public sealed record ThreeViewLayout(Vector3 Min, Vector3 Max, double Scale, double Width, double Height,
    (double X, double Y) TopCorner, (double X, double Y) FrontCorner, (double X, double Y) SideCorner)
{
    public double SpanX => (Max.X - Min.X) * Scale;
    public double SpanY => (Max.Y - Min.Y) * Scale;
    public double SpanZ => (Max.Z - Min.Z) * Scale;

    public (double X, double Y) Top(Vector3 p) => (TopCorner.X + (p.X - Min.X) * Scale, TopCorner.Y + (Max.Y - p.Y) * Scale);
    public (double X, double Y) Front(Vector3 p) => (FrontCorner.X + (p.X - Min.X) * Scale, FrontCorner.Y + (Max.Z - p.Z) * Scale);
    public (double X, double Y) Side(Vector3 p) => (SideCorner.X + (p.Y - Min.Y) * Scale, SideCorner.Y + (Max.Z - p.Z) * Scale);

    private const double Margin = 40, Header = 96, Gap = 64, MaxWidth = 980, MaxPlotHeight = 760, MaxScale = 400;

    /// <summary>A layout for geometry within [min, max], padded, at the largest scale (up to 400 px/m) that fits about 1000 × 900 px.</summary>
    public static ThreeViewLayout Fit(Vector3 min, Vector3 max, int footerLines)
    {
        var pad = Vector3.Max((max - min) * 0.06f, new Vector3(0.1f));
        min -= pad;
        max += pad;
        float ex = max.X - min.X, ey = max.Y - min.Y, ez = max.Z - min.Z;
        var scale = Math.Min(MaxScale, Math.Min((MaxWidth - 2 * Margin - Gap) / (ex + ey), (MaxPlotHeight - Gap) / (ey + ez)));
        var top = (Margin, Header);
        var front = (Margin, Header + ey * scale + Gap);
        var side = (Margin + ex * scale + Gap, front.Item2);
        // Room for the side view's title, however narrow the object.
        var width = Math.Max(side.Item1 + Math.Max(ey * scale, 250) + Margin, 720);
        var height = front.Item2 + ez * scale + 56 + footerLines * 16 + 20;
        return new ThreeViewLayout(min, max, scale, width, height, top, front, side);
    }
}
