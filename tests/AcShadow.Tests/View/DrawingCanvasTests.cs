using System.Globalization;
using System.Text.RegularExpressions;
using AcShadow.Tests.Fixtures;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.View;

/// <summary>
/// Every drawing acshadow writes, rasterised by librsvg (rsvg-convert) as a reader's viewer would: the
/// committed ones under docs/view, and fresh ones of every sample Setup (with and without the chart's
/// failure markers), the sample landblock from the dat and from the fixtures, the compiled scene and its
/// scene-chart, and the chart's speed–accuracy plot and failure map. Two checks, each on real glyphs:
/// nothing is drawn outside the canvas (the drawing is rendered onto a larger transparent canvas and no
/// pixel past the declared one may have ink), and no two texts overlap (every text drawn alone at half
/// opacity: where two overlap, the ink is darker than any one text can make it); and no circle is drawn with
/// radius 0.
/// </summary>
[Trait("Speed", "Slow")]
public sealed partial class DrawingCanvasTests
{
    private const int Pad = 400;

    public static TheoryData<string> Kinds() => ["committed", "setups", "chart-markers", "landblock", "fixtures", "compiled-scene", "chart"];

    [Theory]
    [MemberData(nameof(Kinds))]
    public void Nothing_is_drawn_off_the_canvas_and_no_two_texts_overlap(string kind)
    {
        using var dir = new TempDir();
        var svgs = Drawings(kind, dir);
        Assert.NotEmpty(svgs);
        var problems = new List<string>();
        foreach (var svg in svgs)
        {
            var text = File.ReadAllText(svg);
            var name = Path.GetFileName(svg);
            var (width, height) = Canvas(text);
            if (text.Contains(" r=\"0.00\"", StringComparison.Ordinal)) problems.Add($"{name}: a circle of radius 0 (a sphere or cylinder drawn as a point)");
            var offCanvas = Ink(Padded(text, width, height), dir, 0, width, height);
            if (offCanvas is { } off) problems.Add($"{name}: {off.Count} px of ink outside the {width} x {height} canvas, within x {off.MinX}..{off.MaxX}, y {off.MinY}..{off.MaxY}");
            var overlap = Ink(Padded(TextsOnly(text), width, height), dir, 190, 0, 0);
            if (overlap is { } o) problems.Add($"{name}: texts overlap in {o.Count} px, within x {o.MinX}..{o.MaxX}, y {o.MinY}..{o.MaxY}");
        }
        Assert.True(problems.Count == 0, string.Join('\n', problems));
    }

    /// <summary>The drawings of one kind, written into <paramref name="dir"/> (or the committed ones).</summary>
    private static IReadOnlyList<string> Drawings(string kind, TempDir dir)
    {
        var fixtures = CommittedFixturesTests.RepositoryFixtures();
        var setups = Directory.GetFiles(Path.Combine(fixtures, "setups"), "*.shadow.json")
            .Select(f => Path.GetFileName(f)[..10]).Order(StringComparer.Ordinal).ToArray();
        var outDir = Path.Combine(dir.Path, "out");
        switch (kind)
        {
            case "committed":
                return Directory.GetFiles(Path.Combine(RepositoryRoot.Path, "docs", "view"), "*.svg").Order(StringComparer.Ordinal).ToArray();
            case "setups":
                Cli(["view", .. setups.SelectMany(id => new[] { "--setup", id }), "--out", outDir]);
                break;
            case "chart-markers":
                var chart = Path.Combine(dir.Path, "chart");
                Cli("chart", "--setup", "0x020019FF", "--setup", "0x02005000", "--out", chart, "--quiet");
                Cli("view", "--setup", "0x020019FF", "--setup", "0x02005000", "--chart", chart, "--out", outDir);
                break;
            case "landblock":
                Cli("view", "--landblock", "0xA9B4", "--out", outDir);
                break;
            case "fixtures":
                Cli("view", "--fixtures", fixtures, "--out", outDir);
                break;
            case "compiled-scene":
                var scene = Path.Combine(dir.Path, "scene");
                Cli("scene", "--landblock", "0xA9B4", "--out", scene, "--quiet");
                Cli("view", "--scene", scene, "--out", outDir);
                return [.. Directory.GetFiles(outDir, "*.svg"), Path.Combine(scene, "scene-chart.svg")];
            case "chart":
                Cli("chart", "--setup", "0x020019FF", "--out", outDir, "--quiet");
                return Directory.GetFiles(outDir, "*.svg", SearchOption.AllDirectories).Order(StringComparer.Ordinal).ToArray();
        }
        return Directory.GetFiles(outDir, "*.svg").Order(StringComparer.Ordinal).ToArray();
    }

    private static void Cli(params string[] args)
    {
        var run = CliRun.Of(args);
        Assert.True(run.ExitCode == 0, $"{string.Join(' ', args)}: exit {run.ExitCode}: {run.Error}");
    }

    private static (int Width, int Height) Canvas(string svg)
    {
        var m = Root().Match(svg);
        Assert.True(m.Success, "no <svg width height viewBox> root");
        return ((int)Math.Ceiling(double.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture)),
            (int)Math.Ceiling(double.Parse(m.Groups[2].Value, CultureInfo.InvariantCulture)));
    }

    /// <summary>The same drawing on a canvas <see cref="Pad"/> px larger on every side, its own canvas where it was.</summary>
    private static string Padded(string svg, int width, int height) => Root().Replace(svg, string.Create(CultureInfo.InvariantCulture,
        $"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width + 2 * Pad}\" height=\"{height + 2 * Pad}\" viewBox=\"{-Pad} {-Pad} {width + 2 * Pad} {height + 2 * Pad}\""), 1);

    /// <summary>The root and only its texts, each black at half opacity.</summary>
    private static string TextsOnly(string svg)
    {
        var head = svg[..(svg.IndexOf('>') + 1)];
        var texts = TextElement().Matches(svg).Select(m => Fill().Replace(m.Value, "fill=\"#000000\" fill-opacity=\"0.5\"", 1));
        return head + "\n" + string.Join("\n", texts) + "\n</svg>\n";
    }

    /// <summary>
    /// Rasterises <paramref name="svg"/> (padded) and finds the pixels with alpha above <paramref name="alpha"/>
    /// outside the canvas [0, width) × [0, height) in the drawing's own coordinates; null when there are none.
    /// </summary>
    private static (int Count, int MinX, int MaxX, int MinY, int MaxY)? Ink(string svg, TempDir dir, byte alpha, int width, int height)
    {
        var svgPath = Path.Combine(dir.Path, "check.svg");
        var pngPath = Path.Combine(dir.Path, "check.png");
        File.WriteAllText(svgPath, svg);
        ViewCommandTests.Rasterise(svgPath, pngPath);
        var png = PngImage.Read(File.ReadAllBytes(pngPath));
        int count = 0, minX = int.MaxValue, maxX = int.MinValue, minY = int.MaxValue, maxY = int.MinValue;
        for (var y = 0; y < png.Height; y++)
            for (var x = 0; x < png.Width; x++)
            {
                int dx = x - Pad, dy = y - Pad;
                if (dx >= 0 && dx < width && dy >= 0 && dy < height) continue;
                if (png.At(x, y).A <= alpha) continue;
                count++;
                minX = Math.Min(minX, dx); maxX = Math.Max(maxX, dx); minY = Math.Min(minY, dy); maxY = Math.Max(maxY, dy);
            }
        return count == 0 ? null : (count, minX, maxX, minY, maxY);
    }

    [GeneratedRegex("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"([0-9.]+)\" height=\"([0-9.]+)\" viewBox=\"[^\"]*\"")]
    private static partial Regex Root();

    [GeneratedRegex("<text [^>]*>.*?</text>")]
    private static partial Regex TextElement();

    [GeneratedRegex("fill=\"[^\"]*\"")]
    private static partial Regex Fill();
}
