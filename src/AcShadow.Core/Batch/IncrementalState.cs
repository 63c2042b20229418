using AcShadow.Core.Export;
using AcShadow.Core.Formats;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Batch;

/// <summary>
/// What a batch leaves for the next `--incremental` run (the folder's incremental.json): the tool and
/// options it ran with (policy, scale, formats), and per exported Setup the fingerprint of its inputs, its parts, its diagnostic
/// count and its files' entries.
/// </summary>
public sealed record IncrementalState(string Tool, IReadOnlyList<IncrementalSetup> Setups)
{
    public const string Path = "incremental.json";
    public const string Format = "acshadow.incremental/1";

    /// <summary>
    /// The build of the code that makes the files (the Core assembly's module id changes with any change
    /// to it) and the options the files depend on: a different tool or option reuses nothing.
    /// </summary>
    public static string ToolKey(ShapeBuildOptions options, OutputFormats formats) =>
        $"{typeof(ExportEngine).Assembly.ManifestModule.ModuleVersionId:N}/{options.Policy.Name()}/{options.EntityScale.ToString("R", System.Globalization.CultureInfo.InvariantCulture)}/{formats.Name()}/{Poses.PoseNames.Name(options.Pose)}/{Poses.PoseNames.Name(options.DoorState)}/{options.MotionTable:X8}";

    /// <summary>
    /// Whether this state is <paramref name="previous"/> itself: the same tool, and every Setup's record the very
    /// record read from it (reused, not made again), no more, no fewer. Then its file holds the same bytes.
    /// </summary>
    public bool IsUnchangedFrom(IncrementalState previous)
    {
        if (Tool != previous.Tool || Setups.Count != previous.Setups.Count) return false;
        var records = previous.Setups.ToDictionary(s => s.Id);
        return Setups.All(s => records.TryGetValue(s.Id, out var record) && ReferenceEquals(s, record));
    }
}

/// <summary>One Setup's record in <see cref="IncrementalState"/>: every file written for it (its shadow file, its BSP dumps, in the chosen formats).</summary>
public sealed record IncrementalSetup(uint Id, string Fingerprint, IReadOnlyList<uint> Parts, int Diagnostics, IReadOnlyList<FileEntry> Files);
