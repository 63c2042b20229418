using System.CommandLine;
using AcShadow.Cli.Infrastructure;
using AcShadow.Core.Export;
using AcShadow.Core.Formats;

namespace AcShadow.Cli.Commands;

/// <summary>`--format canonical|acdream|both` on dump and batch.</summary>
public static class FormatOption
{
    /// <summary>--format; not given, canonical.</summary>
    public static Option<OutputFormats?> Create()
    {
        var option = ValueOptions.Single("--format", "canonical|acdream|both",
            "canonical (default: shadow files and BSP dumps), acdream (acdream's 0x%08X.gfxobj.json GfxObj fixtures), or both", Parse);
        option.CompletionSources.Add("canonical", "acdream", "both");
        return option;
    }

    private static OutputFormats Parse(string text) =>
        OutputFormatNames.TryParse(text, out var formats) ? formats
            : throw new CliException(ExitCodes.Usage, $"--format: '{text}' is not a format: use canonical (the default), acdream or both");
}
