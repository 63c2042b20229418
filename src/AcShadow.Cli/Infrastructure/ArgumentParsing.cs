using System.Globalization;
using AcShadow.Core.Catalog;
using AcShadow.Core.Dat;
using AcShadow.Core.Json;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Cli.Infrastructure;

/// <summary>Turns option text into domain values, or a one-line usage error naming the option and the fix.</summary>
public static class ArgumentParsing
{
    public static uint SetupId(string text, string option = "--setup")
    {
        if (!JsonIds.TryParse(text, out var id))
            throw new CliException(ExitCodes.Usage, $"{option}: '{text}' is not a Setup id: write it in hex, e.g. 0x020019FF or 020019FF");
        if (!DatObjectKind.Setup.Contains(id))
            throw new CliException(ExitCodes.Usage, DatIdRanges.Describe(id) is { } what
                ? $"{option}: 0x{id:X8} is {what}, not a Setup id: pass an id in the Setup range {DatObjectKind.Setup.RangeText()}"
                : $"{option}: 0x{id:X8} is outside the Setup range {DatObjectKind.Setup.RangeText()}");
        return id;
    }

    public static ShapePolicy Policy(string? text)
    {
        if (text is null) return ShapePolicy.Retail;
        if (ShapePolicies.TryParse(text, out var policy)) return policy;
        throw new CliException(ExitCodes.Usage, $"--policy: '{text}' is not a policy: use retail (the default) or union");
    }

    public static float Scale(string? text)
    {
        if (text is null) return 1f;
        if (float.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out var s) && float.IsFinite(s) && s > 0f) return s;
        throw new CliException(ExitCodes.Usage, $"--scale: '{text}' is not a positive number: use e.g. 1 or 1.5");
    }
}
