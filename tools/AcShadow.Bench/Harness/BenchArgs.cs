using System.Globalization;

namespace AcShadow.Bench.Harness;

/// <summary>The bench's "--name value" arguments: every subcommand reads them the same way and says what is missing.</summary>
public sealed class BenchArgs(IReadOnlyList<string> args, string usage)
{
    public bool Has(string flag) => args.Contains(flag);

    /// <summary>The value after <paramref name="name"/>, or null when it is not given.</summary>
    public string? Value(string name)
    {
        var i = args.ToList().IndexOf(name);
        if (i < 0) return null;
        return i + 1 < args.Count ? args[i + 1] : throw new ArgumentException($"{name} needs a value; {usage}");
    }

    public string Required(string name, string what) =>
        Value(name) ?? throw new ArgumentException($"{name} is required: {what}; {usage}");

    public int PositiveInt(string name, int fallback) => Value(name) is { } text
        ? int.TryParse(text, NumberStyles.Integer, CultureInfo.InvariantCulture, out var v) && v > 0 ? v : throw new ArgumentException($"{name} {text}: give a positive integer")
        : fallback;
}
