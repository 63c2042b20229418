using System.CommandLine;
using AcShadow.Cli.Infrastructure;
using AcShadow.Core.Export;
using AcShadow.Core.Formats;

namespace AcShadow.Cli.Commands;

/// <summary>`--format canonical|acdream|both` on dump and batch.</summary>
public static class FormatOption
{
    public static Option<string?> Create()
    {
        var option = new Option<string?>("--format")
        {
            Description = "canonical (default: shadow files and BSP dumps), acdream (acdream's 0x%08X.gfxobj.json GfxObj fixtures), or both",
            HelpName = "canonical|acdream|both",
        };
        option.CompletionSources.Add("canonical", "acdream", "both");
        return option;
    }

    public static OutputFormats Parse(string? text)
    {
        if (text is null) return OutputFormats.Canonical;
        if (OutputFormatNames.TryParse(text, out var formats)) return formats;
        throw new CliException(ExitCodes.Usage, $"--format: '{text}' is not a format: use canonical (the default), acdream or both");
    }
}
