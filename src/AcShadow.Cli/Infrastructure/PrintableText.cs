using System.Globalization;
using System.Text;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// Text from the disk (file names, index paths, JSON values) as it may reach a terminal: control characters
/// written as escapes (<c>\n</c>, <c>\x1B</c>), so a file name cannot recolour, move or clear the terminal,
/// or split one report line into two that look like acshadow's own.
/// </summary>
public static class PrintableText
{
    public static string Escape(string text)
    {
        if (!text.Any(IsControl)) return text;
        var escaped = new StringBuilder(text.Length + 8);
        foreach (var c in text)
        {
            if (!IsControl(c)) escaped.Append(c);
            else escaped.Append(c switch
            {
                '\n' => "\\n",
                '\r' => "\\r",
                '\t' => "\\t",
                _ => "\\x" + ((int)c).ToString(c > 0xFF ? "X4" : "X2", CultureInfo.InvariantCulture),
            });
        }
        return escaped.ToString();
    }

    // C0, DEL and C1 (0x9B is a one-byte CSI on some terminals).
    private static bool IsControl(char c) => c < 0x20 || c is >= '\u007F' and <= '\u009F';
}
