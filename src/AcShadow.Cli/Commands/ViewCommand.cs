using System.CommandLine;
using System.Globalization;
using System.Numerics;
using System.Text.Json;
using AcShadow.Analysis.Compile;
using AcShadow.Core.Cells;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Cells;
using AcShadow.Analysis.View;
using AcShadow.Cli.Infrastructure;
using AcShadow.Cli.Output;
using AcShadow.Core.Batch;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Core.Scenes;
using AcShadow.Core.Shapes;
using AcShadow.Files;
using AcShadow.Fixtures;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Scenes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Cli.Commands;

/// <summary>
/// `acshadow view [--setup ID ...] [--landblock 0xXXYY] [--fixtures DIR | --scene DIR] [--chart DIR] --out DIR`:
/// each Setup (or the landblock) as a binary glTF model with one layer per shape model, and a three-view SVG
/// drawing; with <c>--scene</c>, a compiled landblock with one layer per chosen model.
/// </summary>
public static partial class ViewCommand
{
    public const string DefaultOut = "acshadow-view";

    public static Command Create(CliConsole console)
    {
        var setup = CommonOptions.SetupIds("a Setup to view, e.g. 0x020019FF (repeat for more)");
        var selection = new SelectionOptions();
        var fixtures = new Option<string?>("--fixtures") { Description = "read a folder `dump` or `batch` wrote (shadow files, BSP dumps, scene.json) instead of a dat; with no --setup or --landblock, everything in it", HelpName = "DIR" };
        var compiled = new Option<string?>("--scene") { Description = "read a folder `scene` wrote (compiled-scene.json and its BSP dumps) instead of a dat: the landblock with each object as its chosen model", HelpName = "DIR" };
        var chart = new Option<string?>("--chart") { Description = "a folder `chart` wrote: its false passes and false blocks (failures.csv) become markers", HelpName = "DIR" };
        var dat = CommonOptions.Dat();
        var outDir = CommonOptions.Out(DefaultOut);
        var scale = CommonOptions.Scale();
        var pose = new PoseOptions();
        var command = new Command("view", "Write each Setup (or a landblock) as a glTF model (.glb, one layer per shape model) and a three-view drawing (.svg)")
        {
            setup, selection.Landblock, selection.CellDat, fixtures, compiled, chart, dat, outDir, scale,
        };
        foreach (var option in pose.All) command.Options.Add(option);
        command.SetAction(parse =>
        {
            var ids = (parse.GetValue(setup) ?? []).Distinct().ToArray();
            var landblock = parse.GetValue(selection.Landblock);
            var folder = parse.GetValue(fixtures);
            var sceneFolder = parse.GetValue(compiled);
            if (folder is null && sceneFolder is null && ids.Length == 0 && landblock is null)
                throw new CliException(ExitCodes.Usage, "choose what to view: --setup ID (repeatable), --landblock 0xXXYY, --fixtures DIR or --scene DIR");
            if (sceneFolder is not null)
            {
                if (ids.Length > 0 || folder is not null)
                    throw new CliException(ExitCodes.Usage, "--scene draws one compiled landblock: drop --setup and --fixtures (view them in a run of their own)");
                if (parse.GetValue(dat) is not null || parse.GetValue(selection.CellDat) is not null)
                    throw new CliException(ExitCodes.Usage, "--scene reads only the folder `acshadow scene` wrote: drop --dat and --cell-dat");
                if (parse.GetValue(scale) is not null || pose.All.Any(o => parse.GetResult(o) is not null))
                    throw new CliException(ExitCodes.Usage, "--scene views the objects at the scale and in the pose they were compiled with: drop --scale, --pose, --state and --motion-table");
                OutputFolder.Check(parse.GetValue(outDir)!);
                var markers = parse.GetValue(chart) is { } dir ? ReadFailures(dir) : [];
                return Write(console, parse.GetValue(outDir)!, [FromCompiledScene(sceneFolder, landblock, markers)]);
            }
            if (folder is not null && (parse.GetValue(dat) is not null || parse.GetValue(selection.CellDat) is not null))
                throw new CliException(ExitCodes.Usage, "--fixtures reads only the folder's JSON: drop --dat and --cell-dat");
            if (folder is not null && parse.GetValue(scale) is not null)
                throw new CliException(ExitCodes.Usage, "--fixtures views the files at the scale they were written with: drop --scale");
            OutputFolder.Check(parse.GetValue(outDir)!);
            if (folder is not null && pose.All.Any(o => parse.GetResult(o) is not null))
                throw new CliException(ExitCodes.Usage, "--fixtures views the files in the pose they were written with: drop --pose, --state and --motion-table");
            var failures = parse.GetValue(chart) is { } chartDir ? ReadFailures(chartDir) : [];
            var scenes = folder is not null
                ? FromFixtures(console, folder, ids, landblock, failures)
                : FromDat(console, parse.GetValue(dat), parse.GetValue(selection.CellDat), ids, landblock,
                    pose.Apply(parse, new ShapeBuildOptions(ShapePolicy.Retail, parse.GetValue(scale) ?? 1f)), failures);
            return Write(console, parse.GetValue(outDir)!, scenes);
        });
        return command;
    }

    private static IReadOnlyList<ViewScene> FromDat(CliConsole console, string? datPath, string? cellPath, uint[] ids, uint? landblock, ShapeBuildOptions pose, IReadOnlyList<ChartFailure> failures)
    {
        using var dat = DatLocator.Open(datPath, cellPath, console);
        PoseOptions.RequireUsable(pose, dat.Portal, ids);
        var scenes = new List<ViewScene>();
        // The fitted models the chart's markers name are drawn too, so each marker stands with its model's shapes.
        var fitted = failures.Select(f => f.Model).ToHashSet(StringComparer.Ordinal);
        foreach (var id in ids)
        {
            var setup = dat.Portal.ReadSetup(id)
                ?? throw new CliException(ExitCodes.NotInDat, $"Setup {JsonIds.Format(id)} is not in {dat.Description}: check the id (`acshadow audit --all` lists every Setup the dat has)");
            var subject = ViewSubjects.FromDat(setup, dat.Portal.ReadGfxObj, pose, dat.Portal, fitted);
            scenes.Add(ViewSceneBuilder.ForSetup(subject, failures));
        }
        if (landblock is { } lb)
        {
            if (dat.Cell is null)
                throw new CliException(ExitCodes.Usage, $"--landblock {LandblockIds.Short(lb)}: pass --cell-dat PATH (client_cell_1.dat) with --dat");
            var info = dat.Cell.ReadLandBlockInfo(lb)
                ?? throw new CliException(ExitCodes.NotInDat, $"landblock {LandblockIds.Short(lb)} has no LandBlockInfo (0x{lb:X8}) in {dat.Cell.Info.FileName}");
            var scene = LandblockScene.From(info);
            var subjects = new Dictionary<uint, ViewSubject?>();
            ViewSubject? Subject(SceneObject o)
            {
                if (subjects.TryGetValue(o.Id, out var known)) return known;
                ViewSubject? made = null;
                try
                {
                    made = o.Kind switch
                    {
                        SceneObjectKind.Setup => dat.Portal.ReadSetup(o.Id) is { } s ? ViewSubjects.FromDat(s, dat.Portal.ReadGfxObj, pose, dat.Portal, fitted) : null,
                        SceneObjectKind.GfxObj => dat.Portal.ReadGfxObj(o.Id) is { } g ? ViewSubjects.FromBareGfxObj(g, dat.Portal.ReadGfxObj, pose.EntityScale) : null,
                        _ => null,
                    };
                    if (made is null) console.Error.WriteLine($"warning: {JsonIds.Format(o.Id)}: placed by landblock {LandblockIds.Short(lb)} but not a Setup or GfxObj of {dat.Description}; not drawn");
                }
                catch (DatFormatException e)
                {
                    console.Error.WriteLine($"warning: {JsonIds.Format(o.Id)}: unreadable, not drawn: {e.Message}");
                }
                return subjects[o.Id] = made;
            }
            // The indoor cells and what they place, numbered on from the outdoor objects as `scene` numbers them.
            var envCells = new List<EnvCell>();
            var cells = new List<ViewCell>();
            var structures = new CellStructures(dat.Portal);
            foreach (var cellId in LandblockScene.CellIds(info))
            {
                EnvCell? envCell;
                try
                {
                    envCell = dat.Cell.ReadEnvCell(cellId);
                }
                catch (DatFormatException e)
                {
                    console.Error.WriteLine($"warning: {JsonIds.Format(cellId)}: unreadable, not drawn: {e.Message}");
                    continue;
                }
                if (envCell is null)
                {
                    console.Error.WriteLine($"warning: {JsonIds.Format(cellId)}: counted by landblock {LandblockIds.Short(lb)} but not in {dat.Cell.Info.FileName}; not drawn");
                    continue;
                }
                envCells.Add(envCell);
                var (geometry, problem) = structures.For(envCell.EnvironmentFileId, envCell.CellStructure);
                if (geometry is null) console.Error.WriteLine($"warning: {JsonIds.Format(cellId)}: {problem}; its walls are not drawn");
                else cells.Add(new ViewCell(cellId, new Frame(envCell.Position.Position, envCell.Position.Rotation), geometry.Physics));
            }
            var placements = AcShadow.Analysis.Compile.PlacedObject.Of(scene with { Cells = envCells })
                .Select(p => (o: p.Object, s: Subject(p.Object)))
                .Where(p => p.s is not null)
                .Select(p => new ViewPlacement(p.o.Index, p.s!, new Frame(p.o.Frame.Position, p.o.Frame.Rotation)))
                .ToArray();
            var c = scene.Coordinates;
            scenes.Add(ViewSceneBuilder.ForLandblock(lb, new Vector3((float)c.WorldOriginX, (float)c.WorldOriginY, 0), placements, cells, failures, [CompiledSceneNote]));
        }
        return scenes;
    }

    /// <summary>A landblock from a dat or fixtures shows every model of every object; a compiled scene shows each object's chosen one.</summary>
    private const string CompiledSceneNote = "Every object is shown under every model; `acshadow view --scene DIR` draws each object as the model `acshadow scene` chose for it.";

    private static IReadOnlyList<ViewScene> FromFixtures(CliConsole console, string folder, uint[] ids, uint? landblock, IReadOnlyList<ChartFailure> failures)
    {
        if (!Directory.Exists(folder))
            throw new CliException(ExitCodes.Usage, $"--fixtures: {folder} is not a folder: pass the folder `acshadow dump` or `batch` wrote");
        var dumps = new Dictionary<uint, BspDump?>();
        BspDump? Dump(uint id)
        {
            if (!dumps.TryGetValue(id, out var dump))
            {
                var path = Path.Combine(folder, FileFormats.Bsp.PathFor(id));
                dumps[id] = dump = File.Exists(path) ? ReadFixture(path, BspFileReader.Read) : null;
                if (dump is null) console.Error.WriteLine($"warning: {JsonIds.Format(id)}: {path} is missing; its shapes are not drawn");
            }
            return dump;
        }
        var subjects = new Dictionary<uint, ViewSubject>();
        ViewSubject Setup(uint id)
        {
            if (subjects.TryGetValue(id, out var known)) return known;
            var path = Path.Combine(folder, FileFormats.Shadow.PathFor(id));
            if (!File.Exists(path))
                throw new CliException(ExitCodes.NotInDat, $"--fixtures: no shadow file for Setup {JsonIds.Format(id)} ({path}): write it with `acshadow dump --setup {JsonIds.Format(id)} --out {folder}`");
            var subject = ReadFixture(path, json => ViewSubjects.FromShadowFile(json, Dump));
            // Drawn files are named for the Setup inside: a file named for another would be drawn (and written) twice.
            if (subject.Id != id)
                throw new CliException(ExitCodes.Usage, $"--fixtures: {path} holds Setup {JsonIds.Format(subject.Id)}, not the {JsonIds.Format(id)} its name says: a shadow file is named for its setupId; write it again with `acshadow dump --setup {JsonIds.Format(id)}`");
            return subjects[id] = subject;
        }

        var scenePath = Path.Combine(folder, FileFormats.Scene.Path);
        // Nothing chosen: everything the folder holds, every Setup and the scene when there is one.
        var everything = ids.Length == 0 && landblock is null;
        if (everything)
        {
            var setups = Path.Combine(folder, "setups");
            ids = Directory.Exists(setups)
                ? Directory.GetFiles(setups, "*" + ShadowSuffix).Select(f => Path.GetFileName(f)[..^ShadowSuffix.Length])
                    .Select(n => JsonIds.TryParse(n, out var id) ? id : (uint?)null).OfType<uint>().Order().ToArray()
                : [];
            if (ids.Length == 0 && !File.Exists(scenePath))
                throw new CliException(ExitCodes.Usage, $"--fixtures: {folder} holds no setups/*{ShadowSuffix} and no {FileFormats.Scene.Path}: pass the folder `acshadow dump` or `batch` wrote");
        }
        var scenes = ids.Select(id => ViewSceneBuilder.ForSetup(Setup(id), failures)).ToList();
        if (landblock is not null || (everything && File.Exists(scenePath)))
        {
            if (!File.Exists(scenePath))
                throw new CliException(ExitCodes.NotInDat, $"--fixtures: {folder} has no {FileFormats.Scene.Path}: write it with `acshadow batch --landblock 0xXXYY --out {folder}`");
            // One read of the file: the package's reader, and each object's landblock-relative frame.
            var (scene, frames) = ReadFixture(scenePath, json => (FixtureScene.Read(json), SceneFileFrames.Read(json)));
            if (landblock is { } lb && lb != scene.LandblockId)
                throw new CliException(ExitCodes.NotInDat, $"--fixtures: {scenePath} describes landblock {LandblockIds.Short(scene.LandblockId)}, not {LandblockIds.Short(lb)}");
            var placements = new List<ViewPlacement>();
            foreach (var o in scene.Objects.Where(o => o.File is not null))
            {
                var subject = o.Kind == SceneObjectKind.Setup ? Setup(o.Id) : ViewSubjects.FromSceneGfxObj(o.Id, scene.Policy.Name(), o.Shapes, Dump);
                placements.Add(new ViewPlacement(o.Index, subject, frames[o.Index]));
            }
            // The cell files beside it: each cell's walls, and what it places numbered on from the outdoor objects.
            var cells = new List<ViewCell>();
            var index = scene.Objects.Count;
            foreach (var cell in CellFiles(folder, scene.LandblockId).Select(id => ReadCell(folder, id)))
            {
                cells.Add(new ViewCell(cell.CellId, cell.LandblockFrame, cell.Physics));
                foreach (var o in cell.Objects)
                {
                    var at = index++;
                    if (o.File is null) continue;
                    var subject = o.Kind == SceneObjectKind.Setup ? Setup(o.Id) : ViewSubjects.FromSceneGfxObj(o.Id, scene.Policy.Name(), o.Shapes, Dump);
                    placements.Add(new ViewPlacement(at, subject, o.LandblockFrame));
                }
            }
            scenes.Add(ViewSceneBuilder.ForLandblock(scene.LandblockId, scene.WorldOrigin, placements, cells, failures,
                ["Read from the fixtures' scene.json and cell files; " + CompiledSceneNote[0..1].ToLowerInvariant() + CompiledSceneNote[1..]]));
        }
        return scenes;
    }

    private const string ShadowSuffix = ".shadow.json";

    /// <summary>The ids of the cell files a fixtures folder holds for a landblock, in id order.</summary>
    private static IReadOnlyList<uint> CellFiles(string folder, uint landBlockInfoId)
    {
        var dir = Path.Combine(folder, "cells");
        if (!Directory.Exists(dir)) return [];
        const string Suffix = ".cell.json";
        return Directory.GetFiles(dir, "*" + Suffix).Select(f => Path.GetFileName(f)[..^Suffix.Length])
            .Select(n => JsonIds.TryParse(n, out var id) ? id : (uint?)null).OfType<uint>()
            .Where(id => (id & 0xFFFF0000u) == (landBlockInfoId & 0xFFFF0000u)).Order().ToArray();
    }

    /// <summary>
    /// A folder `acshadow scene` wrote, read once: refused unless the consumer library loads it (<see cref="CompiledSceneDrawing.Read"/>)
    /// and every BSP dump it names is the one its id names; no dat is read.
    /// </summary>
    private static ViewScene FromCompiledScene(string folder, uint? landblock, IReadOnlyList<ChartFailure> failures)
    {
        const string Fix = "pass the folder `acshadow scene --out` wrote";
        if (!Directory.Exists(folder))
            throw new CliException(ExitCodes.Usage, $"--scene: {folder} is not a folder: {Fix}");
        var path = Path.Combine(folder, FileFormats.CompiledScene.Path);
        if (!File.Exists(path))
            throw new CliException(ExitCodes.Usage, $"--scene: {folder} has no {FileFormats.CompiledScene.Path}: {Fix} (acshadow scene --landblock 0xXXYY --out {folder})");
        var dumps = new Dictionary<string, BspDump>(StringComparer.Ordinal);
        BspDump Dump(string file)
        {
            if (dumps.TryGetValue(file, out var known)) return known;
            // Only the dumps `scene` writes, so a file naming "../x" reads nothing outside the folder.
            if (!DumpPath().IsMatch(file))
                throw new FormatException($"\"{file}\" is not a BSP dump `acshadow scene` writes (gfxobjs/0x%08X.bsp.json or cells/0x%08X.bsp.json)");
            var dumpPath = Path.Combine(folder, file);
            if (!File.Exists(dumpPath)) throw new FormatException($"it names {file}, which is missing");
            InputFile.RequireRegular(dumpPath, ExitCodes.Usage, "--scene", Fix);
            InputFile.RequireAtMost(dumpPath, InputFile.MaxFixtureBytes, ExitCodes.Usage, "--scene");
            return dumps[file] = BspFileReader.Read(File.ReadAllText(dumpPath));
        }
        InputFile.RequireRegular(path, ExitCodes.Usage, "--scene", Fix);
        InputFile.RequireAtMost(path, InputFile.MaxSceneBytes, ExitCodes.Usage, "--scene");
        CompiledSceneDrawing drawing;
        try
        {
            var json = File.ReadAllText(path);
            drawing = CompiledSceneDrawing.Read(json, Dump);
        }
        catch (Exception e) when (e is FormatException or JsonException or InvalidOperationException or KeyNotFoundException or IndexOutOfRangeException or ArgumentException)
        {
            throw new CliException(ExitCodes.Usage, $"--scene: {path} is not a compiled scene this version reads: {e.Message}");
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException(ExitCodes.Usage, $"--scene: cannot read a file of {folder}: {e.Message}");
        }
        if (landblock is { } lb && lb != drawing.LandblockId)
            throw new CliException(ExitCodes.NotInDat, $"--scene: {path} compiles landblock {LandblockIds.Short(drawing.LandblockId)}, not {LandblockIds.Short(lb)}");
        return ViewSceneBuilder.ForCompiledScene(drawing, failures);
    }

    [System.Text.RegularExpressions.GeneratedRegex(@"^(gfxobjs|cells)/0x[0-9A-F]{8}\.bsp\.json$")]
    private static partial System.Text.RegularExpressions.Regex DumpPath();

    private static CellFile ReadCell(string folder, uint cellId)
    {
        InputFile.RequireRegular(Path.Combine(folder, FileFormats.Cell.PathFor(cellId)), ExitCodes.Usage, "--fixtures", "pass the folder acshadow wrote");
        try
        {
            return CellFixture.Load(folder, cellId).File;
        }
        catch (Exception e) when (e is FormatException or JsonException or InvalidOperationException or KeyNotFoundException)
        {
            throw new CliException(ExitCodes.Usage, $"--fixtures: {e.Message}");
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException(ExitCodes.Usage, $"--fixtures: cannot read the cell file of {JsonIds.Format(cellId)}: {e.Message}");
        }
    }

    private static T ReadFixture<T>(string path, Func<string, T> read)
    {
        InputFile.RequireRegular(path, ExitCodes.Usage, "--fixtures", "pass the folder acshadow wrote");
        InputFile.RequireAtMost(path, InputFile.MaxFixtureBytes, ExitCodes.Usage, "--fixtures");
        try
        {
            return read(File.ReadAllText(path));
        }
        catch (Exception e) when (e is FormatException or JsonException or InvalidOperationException or KeyNotFoundException)
        {
            throw new CliException(ExitCodes.Usage, $"--fixtures: {path} is not an acshadow file this version reads: {e.Message}");
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException(ExitCodes.Usage, $"--fixtures: cannot read {path}: {e.Message}");
        }
    }

    private static IReadOnlyList<ChartFailure> ReadFailures(string folder)
    {
        var path = Path.Combine(folder, "failures.csv");
        if (!File.Exists(path))
            throw new CliException(ExitCodes.Usage, $"--chart: {path} does not exist: pass the folder `acshadow chart --out` wrote");
        InputFile.RequireRegular(path, ExitCodes.Usage, "--chart", "pass the folder acshadow wrote");
        try
        {
            return ChartFailure.ParseCsv(File.ReadAllText(path));
        }
        catch (FormatException e)
        {
            throw new CliException(ExitCodes.Usage, $"--chart: {path}: {e.Message}");
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException(ExitCodes.Usage, $"--chart: cannot read {path}: {e.Message}");
        }
    }

    private static int Write(CliConsole console, string outDir, IReadOnlyList<ViewScene> scenes)
    {
        var files = scenes.SelectMany(s => new[]
        {
            new OutputFile(s.Name + ".glb", GlbWriter.Write(s)),
            OutputFile.Text(s.Name + ".svg", ThreeViewSvg.Write(s)),
        }).ToArray();
        var printed = new HashSet<string>(StringComparer.Ordinal);
        foreach (var warning in scenes.SelectMany(s => s.Warnings).Where(printed.Add))
            console.Error.WriteLine("warning: " + warning);
        using (var folder = OutputFolder.Open(outDir))
        {
            folder.RefuseForeign(files);
            folder.WriteEach(files, console.Out, console.Interrupted);
            folder.RequireStillInPlace();
        }
        foreach (var s in scenes)
            console.Out.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"view {s.Name}: {string.Join(", ", s.Groups.Select(g => $"{g.Name} {g.ShapeCount}"))} shape(s), {s.Groups.Sum(g => g.Objects.Sum(o => o.Shapes.Sum(x => x.TriangleCount)))} triangles"));
        return ExitCodes.Ok;
    }
}
