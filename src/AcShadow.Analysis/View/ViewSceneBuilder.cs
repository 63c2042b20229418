using System.Globalization;
using System.Numerics;
using AcShadow.Core.Batch;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Json;

namespace AcShadow.Analysis.View;

/// <summary>
/// Lays subjects out as a <see cref="ViewScene"/>: one group per model (in <see cref="ViewModels.Order"/>,
/// then any other), each holding every object that has shapes under that model, then one group per model and
/// kind of chart failure, with the failing probes as markers in the frame of each object they belong to.
/// A compiled scene is laid out by chosen model instead (<see cref="ForCompiledScene"/>).
/// </summary>
public static class ViewSceneBuilder
{
    /// <summary>Marker size: small against a 0.5 m probe, big enough to find in a 2 m doorway.</summary>
    public const float MarkerRadius = 0.04f;

    public static ViewScene ForSetup(ViewSubject subject, IReadOnlyList<ChartFailure> failures) =>
        Build(JsonIds.Format(subject.Id), $"{subject.Kind} {JsonIds.Format(subject.Id)}", Vector3.Zero,
            [new ViewPlacement(0, subject, Frame.Identity)], failures, single: true, []);

    /// <param name="worldOrigin">The landblock's corner in world coordinates; placements are relative to it.</param>
    public static ViewScene ForLandblock(uint landBlockInfoId, Vector3 worldOrigin, IReadOnlyList<ViewPlacement> placements,
        IReadOnlyList<ChartFailure> failures, IReadOnlyList<string> notes) =>
        Build(LandblockIds.Short(landBlockInfoId),
            string.Create(CultureInfo.InvariantCulture, $"Landblock {LandblockIds.Short(landBlockInfoId)}: {placements.Count} object(s), world origin ({worldOrigin.X}, {worldOrigin.Y})"),
            worldOrigin, placements, failures, single: false, notes);

    /// <summary>
    /// A compiled scene: one group per chosen model, in the ladder's order (so a viewer toggles "what was
    /// compiled to boxes"), each object in the one group of its model, then the indoor cells, then the chart's
    /// failures. Every model group is filled: here the groups split the objects instead of overlaying them.
    /// </summary>
    public static ViewScene ForCompiledScene(CompiledSceneDrawing scene, IReadOnlyList<ChartFailure> failures)
    {
        var landblock = LandblockIds.Short(scene.LandblockId);
        var groups = new List<ViewGroup>();
        var kinds = Compile.ModelLadder.Names.Append(ViewModels.Cells);
        foreach (var model in kinds)
        {
            var objects = scene.Objects.Concat(scene.Cells).Where(p => p.Model == model && p.Shapes.Count > 0)
                .Select(p => new ViewObject(p.Name, p.Frame, p.Shapes)).ToArray();
            if (objects.Length > 0)
                groups.Add(new ViewGroup(model, ViewModels.Description(model), ViewModels.Colour(model), objects) { Filled = true });
        }
        groups.AddRange(FailureGroups(scene.Objects.Select(p => (p.Id, p.Name, p.Frame)).ToArray(), failures));
        var drawn = scene.Objects.Count(p => p.Shapes.Count > 0);
        var notes = new List<string>
        {
            string.Create(CultureInfo.InvariantCulture,
                $"Each object as the model `acshadow scene` chose for it (mover radius {string.Join(", ", scene.MoverRadii.Select(r => r.ToString(CultureInfo.InvariantCulture)))} m, tolerance {scene.TolerancePercent} %); indoor cells as their retail polygons."),
        };
        if (drawn < scene.Objects.Count + scene.Undrawn)
            notes.Add($"{scene.Objects.Count + scene.Undrawn - drawn} placed object(s) have no shape to draw (no model, or a model with no shapes).");
        return new ViewScene(landblock + "-compiled",
            string.Create(CultureInfo.InvariantCulture,
                $"Landblock {landblock} compiled: {scene.Objects.Count + scene.Undrawn} object(s), {scene.Cells.Count} cell(s), world origin ({scene.WorldOrigin.X}, {scene.WorldOrigin.Y})"),
            scene.WorldOrigin, groups, notes);
    }

    private static ViewScene Build(string name, string title, Vector3 worldOrigin, IReadOnlyList<ViewPlacement> placements,
        IReadOnlyList<ChartFailure> failures, bool single, IReadOnlyList<string> notes)
    {
        var models = placements.SelectMany(p => p.Subject.Models.Select(m => m.Model)).Distinct().ToArray();
        var ordered = ViewModels.Order.Where(models.Contains).Concat(models.Where(m => !ViewModels.Order.Contains(m)));
        // An object placed twice shares one shape list (and so one mesh in the glb).
        var tessellated = new Dictionary<(uint, string, string), IReadOnlyList<ViewShape>>();
        var groups = new List<ViewGroup>();
        foreach (var model in ordered)
        {
            var objects = new List<ViewObject>();
            foreach (var p in placements)
            {
                if (p.Subject.Models.FirstOrDefault(m => m.Model == model) is not { } shapes) continue;
                var key = (p.Subject.Id, p.Subject.Kind, model);
                if (!tessellated.TryGetValue(key, out var drawn))
                    tessellated[key] = drawn = shapes.Shapes.Select(s => ShapeTessellation.Tessellate(s, p.Subject.Bsps)).OfType<ViewShape>().ToArray();
                if (drawn.Count > 0) objects.Add(new ViewObject(ObjectName(p, single), p.Frame, drawn));
            }
            // The first model is the reference, drawn filled; the others are outlines over it.
            if (objects.Count > 0) groups.Add(new ViewGroup(model, ViewModels.Description(model), ViewModels.Colour(model), objects) { Filled = groups.Count == 0 });
        }
        groups.AddRange(FailureGroups(placements.Select(p => (p.Subject.Id, ObjectName(p, single), p.Frame)).ToArray(), failures));
        return new ViewScene(name, title, worldOrigin, groups, notes);
    }

    /// <summary>One group per model and kind of failure, with each object's failing probes as markers in its frame.</summary>
    private static IEnumerable<ViewGroup> FailureGroups(IReadOnlyList<(uint Id, string Name, Frame Frame)> placed, IReadOnlyList<ChartFailure> failures)
    {
        foreach (var (model, falsePass) in failures.Select(f => (f.Model, f.FalsePass)).Distinct()
                     .OrderBy(f => Rank(f.Model)).ThenBy(f => f.Model, StringComparer.Ordinal).ThenBy(f => !f.FalsePass))
        {
            var objects = new List<ViewObject>();
            foreach (var p in placed)
            {
                var points = failures.Where(f => f.ObjectId == p.Id && f.Model == model && f.FalsePass == falsePass).Select(f => f.Center).ToArray();
                if (points.Length == 0) continue;
                var label = falsePass ? $"{points.Length} false pass{(points.Length == 1 ? "" : "es")}" : $"{points.Length} false block{(points.Length == 1 ? "" : "s")}";
                objects.Add(new ViewObject(p.Name, p.Frame, [ShapeTessellation.Markers(label, points, MarkerRadius)]));
            }
            if (objects.Count > 0)
                yield return new ViewGroup(ViewModels.FailureGroup(falsePass, model),
                    falsePass ? $"probes the reference blocks and {model} lets through" : $"probes {model} blocks and the reference lets through",
                    falsePass ? ViewModels.FalsePassColour : ViewModels.FalseBlockColour, objects);
        }
    }

    private static int Rank(string model) => Chart.Models.ShapeModels.All.Select(m => m.Name).ToList().IndexOf(model) is var i and >= 0 ? i : int.MaxValue;

    private static string ObjectName(ViewPlacement p, bool single) =>
        single ? $"{p.Subject.Kind} {JsonIds.Format(p.Subject.Id)}" : $"#{p.Index} {p.Subject.Kind} {JsonIds.Format(p.Subject.Id)}";
}
