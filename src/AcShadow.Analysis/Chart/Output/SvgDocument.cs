using System.Text;
using static AcShadow.Analysis.Chart.Output.ChartFormat;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// A hand-written SVG: elements appended in call order, coordinates with two decimals in the invariant
/// culture, text escaped. The same calls give the same bytes. It keeps the box everything drawn covers,
/// text measured by <see cref="TextMeasure"/>, and the canvas grows to hold it: nothing is drawn off-canvas
/// whatever a layout estimated. Every number must be finite (a caller's bug otherwise).
/// </summary>
internal sealed class SvgDocument
{
    private const double CanvasMargin = 12;
    private readonly StringBuilder _body = new();
    private readonly double _width;
    private readonly double _height;
    private double _right;
    private double _bottom;

    public SvgDocument(double width, double height)
    {
        _width = width;
        _height = height;
    }

    /// <summary>The right and bottom edges of everything drawn so far, text included.</summary>
    public (double Right, double Bottom) Extent => (_right, _bottom);

    /// <summary>Starts a group a viewer can hide as one (a layer): an id and a tooltip title. Close it with <see cref="EndGroup"/>.</summary>
    public void BeginGroup(string id, string title)
    {
        _body.Append($"<g id=\"{Escape(id)}\"><title>{Escape(title)}</title>\n");
    }

    public void EndGroup() => _body.Append("</g>\n");

    public void Rect(double x, double y, double w, double h, string fill, string? stroke = null, double strokeWidth = 1, string? title = null, double fillOpacity = 1, string? dash = null)
    {
        Cover(x + w + strokeWidth, y + h + strokeWidth);
        _body.Append($"<rect x=\"{N(x)}\" y=\"{N(y)}\" width=\"{N(w)}\" height=\"{N(h)}\" fill=\"{fill}\"");
        if (fill != "none" && fillOpacity < 1) _body.Append($" fill-opacity=\"{N(fillOpacity)}\"");
        if (dash is not null) _body.Append($" stroke-dasharray=\"{dash}\"");
        if (stroke is not null) _body.Append($" stroke=\"{stroke}\" stroke-width=\"{N(strokeWidth)}\"");
        Close("rect", title);
    }

    public void Line(double x1, double y1, double x2, double y2, string stroke, double width = 1, string? dash = null)
    {
        Cover(Math.Max(x1, x2) + width, Math.Max(y1, y2) + width);
        _body.Append($"<line x1=\"{N(x1)}\" y1=\"{N(y1)}\" x2=\"{N(x2)}\" y2=\"{N(y2)}\" stroke=\"{stroke}\" stroke-width=\"{N(width)}\"");
        if (dash is not null) _body.Append($" stroke-dasharray=\"{dash}\"");
        _body.Append("/>\n");
    }

    public void Circle(double cx, double cy, double r, string fill, string? stroke = null, double strokeWidth = 1, string? title = null, double fillOpacity = 1, string? dash = null)
    {
        Cover(cx + r + strokeWidth, cy + r + strokeWidth);
        _body.Append($"<circle cx=\"{N(cx)}\" cy=\"{N(cy)}\" r=\"{N(r)}\" fill=\"{fill}\"");
        if (fill != "none" && fillOpacity < 1) _body.Append($" fill-opacity=\"{N(fillOpacity)}\"");
        if (dash is not null) _body.Append($" stroke-dasharray=\"{dash}\"");
        if (stroke is not null) _body.Append($" stroke=\"{stroke}\" stroke-width=\"{N(strokeWidth)}\"");
        Close("circle", title);
    }

    /// <summary>A closed outline through the points; <paramref name="fillOpacity"/> below 1 lets what lies behind show.</summary>
    public void Polygon(IEnumerable<(double X, double Y)> points, string fill, double fillOpacity, string stroke, double strokeWidth = 1, string? dash = null, string? title = null)
    {
        var corners = points.ToArray();
        foreach (var (px, py) in corners) Cover(px + strokeWidth, py + strokeWidth);
        _body.Append("<polygon points=\"").AppendJoin(' ', corners.Select(p => N(p.X) + "," + N(p.Y))).Append($"\" fill=\"{fill}\"");
        if (fill != "none" && fillOpacity < 1) _body.Append($" fill-opacity=\"{N(fillOpacity)}\"");
        _body.Append($" stroke=\"{stroke}\" stroke-width=\"{N(strokeWidth)}\" stroke-linejoin=\"round\"");
        if (dash is not null) _body.Append($" stroke-dasharray=\"{dash}\"");
        Close("polygon", title);
    }

    /// <summary>A path (SVG path data built by the caller from <see cref="Number"/>s): many strokes in one element keeps big maps small.</summary>
    public void Path(string data, string fill, string? stroke = null, double strokeWidth = 1, double opacity = 1, string? dash = null)
    {
        if (data.Length == 0) return;
        _body.Append($"<path d=\"{data}\" fill=\"{fill}\"");
        if (stroke is not null) _body.Append($" stroke=\"{stroke}\" stroke-width=\"{N(strokeWidth)}\" stroke-linecap=\"round\" stroke-linejoin=\"round\"");
        if (opacity < 1) _body.Append($" opacity=\"{N(opacity)}\"");
        if (dash is not null) _body.Append($" stroke-dasharray=\"{dash}\"");
        _body.Append("/>\n");
    }

    /// <summary>A coordinate as every element writes it (two decimals, invariant culture).</summary>
    public static string Number(double v) => N(v);

    /// <summary>Text; anchor start | middle | end; rotate in degrees about the anchor point.</summary>
    public void Text(double x, double y, string text, double size = 12, string anchor = "start", string weight = "normal", string fill = "#222", double rotate = 0)
    {
        var width = TextMeasure.Width(text, size, weight == "bold");
        var (above, below) = TextMeasure.Extent(size);
        if (rotate == 0)
            Cover(anchor switch { "middle" => x + width / 2, "end" => x, _ => x + width }, y + below);
        else
            Cover(x + Math.Max(width, above), y + Math.Max(width, above));
        _body.Append($"<text x=\"{N(x)}\" y=\"{N(y)}\" font-size=\"{N(size)}\" text-anchor=\"{anchor}\" font-weight=\"{weight}\" fill=\"{fill}\"");
        if (rotate != 0) _body.Append($" transform=\"rotate({N(rotate)} {N(x)} {N(y)})\"");
        _body.Append('>').Append(Escape(text)).Append("</text>\n");
    }

    /// <summary>The document, its canvas the size asked for or larger, to hold everything drawn with a margin.</summary>
    public string Render()
    {
        var width = Math.Max(_width, Math.Ceiling(_right + CanvasMargin));
        var height = Math.Max(_height, Math.Ceiling(_bottom + CanvasMargin));
        return $"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{N(width)}\" height=\"{N(height)}\" viewBox=\"0 0 {N(width)} {N(height)}\" " +
            "font-family=\"DejaVu Sans, Arial, Helvetica, sans-serif\">\n" +
            $"<rect x=\"0\" y=\"0\" width=\"{N(width)}\" height=\"{N(height)}\" fill=\"#ffffff\"/>\n" +
            _body + "</svg>\n";
    }

    private void Cover(double right, double bottom)
    {
        if (!double.IsFinite(right) || !double.IsFinite(bottom))
            throw new ArgumentOutOfRangeException(nameof(right), "an SVG coordinate is not finite");
        _right = Math.Max(_right, right);
        _bottom = Math.Max(_bottom, bottom);
    }

    private void Close(string element, string? title)
    {
        if (title is null) { _body.Append("/>\n"); return; }
        _body.Append("><title>").Append(Escape(title)).Append("</title></").Append(element).Append(">\n");
    }

    private static string N(double v) => F(v, 2);

    private static string Escape(string s) => s.Replace("&", "&amp;").Replace("<", "&lt;").Replace(">", "&gt;").Replace("\"", "&quot;");
}
