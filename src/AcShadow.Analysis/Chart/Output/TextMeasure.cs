namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// How wide a line of text is in the drawings' font (DejaVu Sans, the first the SVGs name): each printable
/// ASCII character's advance in thousandths of an em, taken from DejaVu Sans's hmtx table, regular and
/// bold; anything else (arrows, minus, µ, …) one em at most. The fonts a viewer falls back to (Arial,
/// Helvetica) are narrower, so a layout made from these widths holds in them too.
/// </summary>
public static class TextMeasure
{
    private static readonly short[] Regular =
    [
        318, 401, 460, 838, 636, 950, 780, 275, 390, 390, 500, 838, 318, 361, 318, 337, 636, 636, 636, 636, 636, 636, 636, 636,
        636, 636, 337, 337, 838, 838, 838, 531, 1000, 684, 686, 698, 770, 632, 575, 775, 752, 295, 295, 656, 557, 863, 748, 787,
        603, 787, 695, 635, 611, 732, 684, 989, 685, 611, 685, 390, 337, 390, 838, 500, 500, 613, 635, 550, 635, 615, 352, 635,
        634, 278, 278, 579, 278, 974, 634, 612, 635, 635, 411, 521, 392, 634, 592, 818, 592, 592, 525, 636, 337, 636, 838,
    ];

    private static readonly short[] Bold =
    [
        348, 456, 521, 838, 696, 1002, 872, 306, 457, 457, 523, 838, 380, 415, 380, 365, 696, 696, 696, 696, 696, 696, 696, 696,
        696, 696, 400, 400, 838, 838, 838, 580, 1000, 774, 762, 734, 830, 683, 683, 821, 837, 372, 372, 775, 637, 995, 837, 850,
        733, 850, 770, 720, 682, 812, 774, 1103, 771, 724, 725, 457, 365, 457, 838, 500, 500, 675, 716, 593, 716, 678, 435, 716,
        712, 343, 343, 665, 343, 1042, 712, 687, 716, 716, 493, 595, 478, 712, 652, 924, 645, 652, 582, 712, 365, 712, 838,
    ];

    /// <summary>The advance of <paramref name="text"/> at <paramref name="size"/> px, in px.</summary>
    public static double Width(string text, double size, bool bold = false)
    {
        var table = bold ? Bold : Regular;
        var thousandths = 0;
        foreach (var c in text) thousandths += c is >= ' ' and <= '~' ? table[c - ' '] : 1000;
        return thousandths / 1000.0 * size;
    }

    /// <summary>How far the tallest glyph rises above the baseline and the deepest falls below it, in px (DejaVu's ascent 0.93 em, descent 0.24 em).</summary>
    public static (double Above, double Below) Extent(double size) => (0.93 * size, 0.24 * size);
}
