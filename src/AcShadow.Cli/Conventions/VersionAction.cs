using System.CommandLine.Invocation;
using System.CommandLine;
using System.Reflection;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures;

namespace AcShadow.Cli.Conventions;

/// <summary>
/// `acshadow --version`: the tool's version, the dat layer it was built with, and the formats it writes.
/// The dat layer is in-house (src/AcShadow.Core/Dat); Chorizite.DatReaderWriter was not available to the
/// build, and the output says so rather than naming a version that is not there.
/// </summary>
public sealed class VersionAction : SynchronousCommandLineAction
{
    public override bool ClearsParseErrors => true;

    public static string Text()
    {
        var assembly = typeof(VersionAction).Assembly;
        var informational = assembly.GetCustomAttribute<AssemblyInformationalVersionAttribute>()?.InformationalVersion ?? "unknown";
        var plus = informational.IndexOf('+');
        var version = plus < 0 ? informational : informational[..plus];
        var commit = plus < 0 ? null : informational[(plus + 1)..];
        var datLayer = typeof(AcShadow.Core.Dat.IDatSource).Assembly.GetName();
        return $"acshadow {version}{(commit is null ? "" : $" (commit {commit[..Math.Min(7, commit.Length)]})")}\n" +
               $"dat layer: in-house {datLayer.Name} {datLayer.Version} (Dat/, behind IDatSource); Chorizite.DatReaderWriter: not used, not available to this build\n" +
               $"formats: {string.Join(", ", FileFormats.All.Select(f => f.Format))}\n" +
               $"runtime: .NET {Environment.Version}{(System.Runtime.CompilerServices.RuntimeFeature.IsDynamicCodeSupported ? "" : " (Native AOT)")}\n";
    }

    public override int Invoke(ParseResult parseResult)
    {
        parseResult.InvocationConfiguration.Output.Write(Text());
        return 0;
    }

    public static void Install(RootCommand root)
    {
        foreach (var option in root.Options.OfType<VersionOption>()) option.Action = new VersionAction();
    }
}
