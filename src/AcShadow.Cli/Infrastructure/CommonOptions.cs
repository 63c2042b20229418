using System.CommandLine;

namespace AcShadow.Cli.Infrastructure;

/// <summary>Options several commands share, spelled and described once.</summary>
public static class CommonOptions
{
    public static Option<string?> Dat() => new("--dat")
    {
        Description = "client_portal.dat, or the folder holding it (default: $ACSHADOW_DAT, else the built-in synthetic sample)",
        HelpName = "PATH",
    };

    public static Option<string?> Policy() => new("--policy")
    {
        Description = "retail (default: the retail client's rules) or union (the seed design's builder)",
        HelpName = "retail|union",
    };

    public static Option<string?> Scale() => new("--scale")
    {
        Description = "entity scale applied to positions and radii (default 1)",
        HelpName = "S",
    };

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
