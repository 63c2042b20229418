using System.CommandLine;
using System.Globalization;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Cli.Infrastructure;

/// <summary>Options several commands share, spelled and described once.</summary>
public static class CommonOptions
{
    public static Option<string?> Dat() => new("--dat")
    {
        Description = "client_portal.dat, or the folder holding it (default: $ACSHADOW_DAT, else the built-in synthetic sample)",
        HelpName = "PATH",
    };

    public static Option<ShapePolicy?> Policy() =>
        ValueOptions.Single("--policy", "retail|union", "retail (default: the retail client's rules) or union (acdream's ShadowShapeBuilder design: every CylSphere, Sphere and BSP part)", ArgumentParsing.Policy);

    /// <summary>--scale; not given, the entity scale is 1.</summary>
    public static Option<float?> Scale() =>
        ArgumentParsing.Scale.Option("--scale", "S", "entity scale applied to positions and radii (default 1)");

    /// <summary>--setup for the commands that take several Setups, one id each time it is given.</summary>
    public static Option<uint[]> SetupIds(string description) =>
        ValueOptions.Repeated("--setup", "ID", description, text => ArgumentParsing.SetupId(text));

    /// <summary>A distance in metres (radius, spacing), refused unless positive.</summary>
    public static NumberRule<float> Metres(float example) =>
        new("a positive number of metres", $"use e.g. {example.ToString(CultureInfo.InvariantCulture)}") { Above = 0f };

    public static Option<string> Out(string defaultValue) => new("--out")
    {
        Description = "output folder",
        HelpName = "DIR",
        DefaultValueFactory = _ => defaultValue,
    };

    /// <summary>--out for the commands that write a folder of many files and have no default for it.</summary>
    public static Option<string> RequiredOut() => new("--out")
    {
        Description = "output folder",
        HelpName = "DIR",
        Required = true,
    };
}
