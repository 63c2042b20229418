using System.CommandLine;
using System.Globalization;
using AcShadow.Core.Batch;
using AcShadow.Core.Catalog;
using AcShadow.Core.Dat;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// The selection options batch and audit share (--doors, --all, --setups, --landblock, --cell-dat) and
/// --jobs, spelled once, with their parsing into a <see cref="BatchSelection"/> and a plan.
/// </summary>
public sealed class SelectionOptions
{
    public Option<bool> Doors { get; } = new("--doors") { Description = "every Setup of the built-in door catalog (ACE world database door weenies)" };
    public Option<bool> All { get; } = new("--all") { Description = "every Setup in the dat" };
    public Option<string?> Setups { get; } = new("--setups") { Description = "a file of Setup ids, one a line, '#' comments", HelpName = "FILE" };
    public Option<uint?> Landblock { get; } = ValueOptions.Single("--landblock", "0xXXYY", "a landblock's scene (needs --cell-dat unless the sample is used)", ParseLandblock);
    public Option<string?> CellDat { get; } = new("--cell-dat") { Description = "client_cell_1.dat (or its folder) for --landblock", HelpName = "PATH" };

    /// <summary>--no-cells for the commands that read a landblock's indoor cells (chart, scene): objects only.</summary>
    public static Option<bool> NoCells() => new("--no-cells") { Description = "with --landblock: objects only, no indoor cells" };

    /// <summary>The selection without its landblock's cells when <paramref name="noCells"/>; refused without a landblock.</summary>
    public static BatchSelection WithoutCells(BatchSelection selection, bool noCells)
    {
        if (!noCells) return selection;
        if (selection.Landblock is null) throw new CliException(ExitCodes.Usage, "--no-cells applies to a landblock's scene: add --landblock 0xXXYY");
        return selection with { Cells = false };
    }

    /// <summary>--jobs; not given, the command's default (all cores for batch and audit).</summary>
    public static Option<int?> Jobs(string description = "parallel workers (default: all cores)") =>
        new NumberRule<int>("a worker count", "use a whole number from 1 to 1024") { From = 1, To = 1024, Styles = NumberStyles.None }
            .Option("--jobs", "N", description);

    /// <summary>The worker count --jobs gives, all cores when it is not given.</summary>
    public static int WorkersOrAllCores(ParseResult parse, Option<int?> jobs) => parse.GetValue(jobs) ?? Environment.ProcessorCount;

    private static uint ParseLandblock(string text) =>
        LandblockIds.TryParse(text, out var id) ? id
            : throw new CliException(ExitCodes.Usage, $"--landblock: '{text}' is not a landblock: write 0xXXYY, e.g. 0xA9B4");

    /// <summary>The selection; with nothing chosen, --all when <paramref name="defaultToAll"/>, else a usage error.</summary>
    public BatchSelection Parse(ParseResult parse, bool defaultToAll)
    {
        SetupList? list = null;
        if (parse.GetValue(Setups) is { } file) list = ReadSetupList(file);
        var selection = new BatchSelection(parse.GetValue(Doors), parse.GetValue(All), list, parse.GetValue(Landblock));
        if (!selection.IsEmpty) return selection;
        if (defaultToAll) return selection with { All = true };
        throw new CliException(ExitCodes.Usage, "choose what to export: --doors, --all, --setups FILE and/or --landblock 0xXXYY (they combine)");
    }

    /// <summary>Plans against the open dats; a landblock missing from the cell dat is "not in dat".</summary>
    public static BatchPlan Plan(BatchSelection selection, OpenedDat dat)
    {
        if (selection.Landblock is { } lb && dat.Cell is null)
            throw new CliException(ExitCodes.Usage, $"--landblock {LandblockIds.Short(lb)}: pass --cell-dat PATH (client_cell_1.dat) with --dat");
        try
        {
            return BatchPlanner.Plan(selection, dat.Portal, dat.Cell, DoorCatalog.SetupIds);
        }
        catch (SelectionException e)
        {
            if (e.Problem != SelectionProblem.NotInDat) throw new CliException(ExitCodes.Usage, e.Message);
            var known = dat.Cell!.ListIds(DatObjectKind.LandBlockInfo);
            throw new CliException(ExitCodes.NotInDat, known.Count is > 0 and <= 8
                ? $"{e.Message} (it has {string.Join(", ", known.Select(LandblockIds.Short))})"
                : e.Message);
        }
    }

    /// <summary>The most a --setups file may hold: 64 Ki ids of 11 bytes each and room for comments, far past any dat's Setups.</summary>
    public const int MaxSetupListBytes = 16 << 20;

    internal static SetupList ReadSetupList(string path)
    {
        if (!File.Exists(path))
            throw new CliException(ExitCodes.Usage, $"--setups: {path} does not exist: pass a text file with one Setup id a line");
        string text;
        try
        {
            // Bounded: /dev/zero or an endless pipe is refused at the limit instead of filling memory. A pipe
            // (a shell's <(...)) is read like a file.
            using var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.ReadWrite, 1 << 16);
            var bytes = new MemoryStream();
            var chunk = new byte[1 << 16];
            for (int read; (read = stream.Read(chunk)) > 0;)
            {
                bytes.Write(chunk, 0, read);
                if (bytes.Length > MaxSetupListBytes)
                    throw new CliException(ExitCodes.Usage, $"--setups: {path} holds more than {MaxSetupListBytes >> 20} MiB: a Setup list is one id a line (every Setup of a dat is well under 1 MiB); pass a text file");
            }
            text = System.Text.Encoding.UTF8.GetString(bytes.GetBuffer(), 0, (int)bytes.Length).TrimStart('\uFEFF');
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException(ExitCodes.Usage, $"--setups: cannot read {path}: {e.Message}");
        }
        try
        {
            return SetupList.Parse(Path.GetFileName(path), text);
        }
        catch (FormatException e)
        {
            throw new CliException(ExitCodes.Usage, $"--setups: {e.Message}");
        }
    }
}
