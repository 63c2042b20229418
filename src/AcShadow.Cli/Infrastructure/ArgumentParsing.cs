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

    public static ShapePolicy Policy(string text) =>
        ShapePolicies.TryParse(text, out var policy) ? policy
            : throw new CliException(ExitCodes.Usage, $"--policy: '{text}' is not a policy: use retail (the default) or union");

    /// <summary>
    /// Entity scales acshadow accepts: far beyond any object's in the game either way, and far inside what
    /// float geometry holds (1e-45 makes every coordinate denormal or zero; 1e30 makes a door kilometres of
    /// probes).
    /// </summary>
    public static readonly NumberRule<float> Scale = new("a positive number", "use e.g. 1 or 1.5")
    {
        Above = 0f,
        Limits = (1e-3f, 1e3f, "no object is scaled that far, and geometry that small or large loses its precision"),
    };
}
