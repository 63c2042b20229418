using System.Text;
using static AcShadow.Analysis.Chart.Output.ChartFormat;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// A hand-written SVG: elements appended in call order, coordinates with two decimals in the invariant
/// culture, text escaped. The same calls give the same bytes.
/// </summary>
internal sealed class SvgDocument
{
    private readonly StringBuilder _body = new();
    private readonly double _width;
    private readonly double _height;

    public SvgDocument(double width, double height)
    {
        _width = width;
        _height = height;
    }

    public void Rect(double x, double y, double w, double h, string fill, string? stroke = null, double strokeWidth = 1, string? title = null, double fillOpacity = 1, string? dash = null)
    {
        _body.Append($"<rect x=\"{N(x)}\" y=\"{N(y)}\" width=\"{N(w)}\" height=\"{N(h)}\" fill=\"{fill}\"");
        if (fill != "none" && fillOpacity < 1) _body.Append($" fill-opacity=\"{N(fillOpacity)}\"");
        if (dash is not null) _body.Append($" stroke-dasharray=\"{dash}\"");
        if (stroke is not null) _body.Append($" stroke=\"{stroke}\" stroke-width=\"{N(strokeWidth)}\"");
        Close("rect", title);
    }

    public void Line(double x1, double y1, double x2, double y2, string stroke, double width = 1, string? dash = null)
    {
        _body.Append($"<line x1=\"{N(x1)}\" y1=\"{N(y1)}\" x2=\"{N(x2)}\" y2=\"{N(y2)}\" stroke=\"{stroke}\" stroke-width=\"{N(width)}\"");
        if (dash is not null) _body.Append($" stroke-dasharray=\"{dash}\"");
        _body.Append("/>\n");
    }

    public void Circle(double cx, double cy, double r, string fill, string? stroke = null, double strokeWidth = 1, string? title = null, double fillOpacity = 1, string? dash = null)
    {
        _body.Append($"<circle cx=\"{N(cx)}\" cy=\"{N(cy)}\" r=\"{N(r)}\" fill=\"{fill}\"");
        if (fill != "none" && fillOpacity < 1) _body.Append($" fill-opacity=\"{N(fillOpacity)}\"");
        if (dash is not null) _body.Append($" stroke-dasharray=\"{dash}\"");
        if (stroke is not null) _body.Append($" stroke=\"{stroke}\" stroke-width=\"{N(strokeWidth)}\"");
        Close("circle", title);
    }

    /// <summary>A closed outline through the points; <paramref name="fillOpacity"/> below 1 lets what lies behind show.</summary>
    public void Polygon(IEnumerable<(double X, double Y)> points, string fill, double fillOpacity, string stroke, double strokeWidth = 1, string? dash = null)
    {
        _body.Append("<polygon points=\"").AppendJoin(' ', points.Select(p => N(p.X) + "," + N(p.Y))).Append($"\" fill=\"{fill}\"");
        if (fill != "none" && fillOpacity < 1) _body.Append($" fill-opacity=\"{N(fillOpacity)}\"");
        _body.Append($" stroke=\"{stroke}\" stroke-width=\"{N(strokeWidth)}\" stroke-linejoin=\"round\"");
        if (dash is not null) _body.Append($" stroke-dasharray=\"{dash}\"");
        _body.Append("/>\n");
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
        _body.Append($"<text x=\"{N(x)}\" y=\"{N(y)}\" font-size=\"{N(size)}\" text-anchor=\"{anchor}\" font-weight=\"{weight}\" fill=\"{fill}\"");
        if (rotate != 0) _body.Append($" transform=\"rotate({N(rotate)} {N(x)} {N(y)})\"");
        _body.Append('>').Append(Escape(text)).Append("</text>\n");
    }

    public string Render() =>
        $"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{N(_width)}\" height=\"{N(_height)}\" viewBox=\"0 0 {N(_width)} {N(_height)}\" " +
        "font-family=\"DejaVu Sans, Arial, Helvetica, sans-serif\">\n" +
        $"<rect x=\"0\" y=\"0\" width=\"{N(_width)}\" height=\"{N(_height)}\" fill=\"#ffffff\"/>\n" +
        _body + "</svg>\n";

    private void Close(string element, string? title)
    {
        if (title is null) { _body.Append("/>\n"); return; }
        _body.Append("><title>").Append(Escape(title)).Append("</title></").Append(element).Append(">\n");
    }

    private static string N(double v) => F(v, 2);

    private static string Escape(string s) => s.Replace("&", "&amp;").Replace("<", "&lt;").Replace(">", "&gt;").Replace("\"", "&quot;");
}
