using System.Numerics;

namespace AcShadow.Analysis.View;

/// <summary>
/// Where the three views of a drawing sit and how a point in the view's frame (dat axes, metres) lands on
/// each, in SVG pixels. Third-angle arrangement, one scale for all three: the top view (from above: x to
/// the right, y up the page) over the front view (from −y, looking north: x right, z up), the side view
/// (from +x, looking west: y right, z up) to the front view's right, so x and z line up across views.
/// Each panel is at least as wide as its title, and the side panel starts past the front panel's title, so
/// titles never overlap; everything starts <paramref name="Header"/> px down, below the title and legend.
/// </summary>
public sealed record ThreeViewLayout(Vector3 Min, Vector3 Max, double Scale, double Width, double Header,
    (double X, double Y) TopCorner, (double X, double Y) FrontCorner, (double X, double Y) SideCorner)
{
    public double SpanX => (Max.X - Min.X) * Scale;
    public double SpanY => (Max.Y - Min.Y) * Scale;
    public double SpanZ => (Max.Z - Min.Z) * Scale;

    /// <summary>The bottom edge of the front and side panels.</summary>
    public double Bottom => FrontCorner.Y + SpanZ;

    public (double X, double Y) Top(Vector3 p) => (TopCorner.X + (p.X - Min.X) * Scale, TopCorner.Y + (Max.Y - p.Y) * Scale);
    public (double X, double Y) Front(Vector3 p) => (FrontCorner.X + (p.X - Min.X) * Scale, FrontCorner.Y + (Max.Z - p.Z) * Scale);
    public (double X, double Y) Side(Vector3 p) => (SideCorner.X + (p.Y - Min.Y) * Scale, SideCorner.Y + (Max.Z - p.Z) * Scale);

    public const double Margin = 20, PanelTitle = 24;
    private const double Gap = 40, MaxWidth = 980, MaxPlotHeight = 760, MaxScale = 400, MinWidth = 720;

    /// <summary>
    /// A layout for geometry within [min, max], padded, at the largest scale (up to 400 px/m) that fits about
    /// 1000 × 900 px, each panel at least as wide as its title (<paramref name="titleWidths"/>: top, front, side).
    /// </summary>
    public static ThreeViewLayout Fit(Vector3 min, Vector3 max, double header, (double Top, double Front, double Side) titleWidths)
    {
        var pad = Vector3.Max((max - min) * 0.06f, new Vector3(0.1f));
        min -= pad;
        max += pad;
        double ex = max.X - min.X, ey = max.Y - min.Y, ez = max.Z - min.Z;
        var scale = Math.Min(MaxScale, Math.Min((MaxWidth - 2 * Margin - Gap) / (ex + ey), (MaxPlotHeight - 2 * Gap) / (ey + ez)));
        var top = (Margin, header + PanelTitle);
        var front = (Margin, top.Item2 + ey * scale + Gap + PanelTitle);
        var side = (Margin + Math.Max(ex * scale, titleWidths.Front) + Gap, front.Item2);
        var width = Math.Max(MinWidth, Math.Max(Margin + Math.Max(ex * scale, titleWidths.Top), side.Item1 + Math.Max(ey * scale, titleWidths.Side)) + Margin);
        return new ThreeViewLayout(min, max, scale, width, header, top, front, side);
    }
}
