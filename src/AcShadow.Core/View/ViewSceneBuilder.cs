using System.Globalization;
using System.Numerics;
using AcShadow.Core.Batch;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Json;

namespace AcShadow.Core.View;

/// <summary>
/// Lays subjects out as a <see cref="ViewScene"/>: one group per model (in <see cref="ViewModels.Order"/>,
/// then any other), each holding every object that has shapes under that model, then one group per model and
/// kind of chart failure, with the failing probes as markers in the frame of each object they belong to.
/// </summary>
public static class ViewSceneBuilder
{
    /// <summary>Marker size: small against a 0.5 m probe, big enough to find in a 2 m doorway.</summary>
    public const float MarkerRadius = 0.04f;

    public static ViewScene ForSetup(ViewSubject subject, IReadOnlyList<ChartFailure> failures) =>
        Build(JsonIds.Format(subject.Id), $"{subject.Kind} {JsonIds.Format(subject.Id)}", Vector3.Zero,
            [new ViewPlacement(0, subject, ViewFrame.Identity)], failures, single: true, []);

    /// <param name="worldOrigin">The landblock's corner in world coordinates; placements are relative to it.</param>
    public static ViewScene ForLandblock(uint landBlockInfoId, Vector3 worldOrigin, IReadOnlyList<ViewPlacement> placements,
        IReadOnlyList<ChartFailure> failures, IReadOnlyList<string> notes) =>
        Build(LandblockIds.Short(landBlockInfoId),
            string.Create(CultureInfo.InvariantCulture, $"Landblock {LandblockIds.Short(landBlockInfoId)}: {placements.Count} object(s), world origin ({worldOrigin.X}, {worldOrigin.Y})"),
            worldOrigin, placements, failures, single: false, notes);

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
            if (objects.Count > 0) groups.Add(new ViewGroup(model, ViewModels.Description(model), ViewModels.Colour(model), objects));
        }
        foreach (var (model, falsePass) in failures.Select(f => (f.Model, f.FalsePass)).Distinct()
                     .OrderBy(f => Rank(f.Model)).ThenBy(f => f.Model, StringComparer.Ordinal).ThenBy(f => !f.FalsePass))
        {
            var objects = new List<ViewObject>();
            foreach (var p in placements)
            {
                var points = failures.Where(f => f.ObjectId == p.Subject.Id && f.Model == model && f.FalsePass == falsePass).Select(f => f.Center).ToArray();
                if (points.Length == 0) continue;
                var label = falsePass ? $"{points.Length} false pass{(points.Length == 1 ? "" : "es")}" : $"{points.Length} false block{(points.Length == 1 ? "" : "s")}";
                objects.Add(new ViewObject(ObjectName(p, single), p.Frame, [ShapeTessellation.Markers(label, points, MarkerRadius)]));
            }
            if (objects.Count > 0)
                groups.Add(new ViewGroup(ViewModels.FailureGroup(falsePass, model),
                    falsePass ? $"probes the reference blocks and {model} lets through" : $"probes {model} blocks and the reference lets through",
                    falsePass ? ViewModels.FalsePassColour : ViewModels.FalseBlockColour, objects));
        }
        return new ViewScene(name, title, worldOrigin, groups, notes);
    }

    private static int Rank(string model) => Chart.Models.ShapeModels.All.Select(m => m.Name).ToList().IndexOf(model) is var i and >= 0 ? i : int.MaxValue;

    private static string ObjectName(ViewPlacement p, bool single) =>
        single ? $"{p.Subject.Kind} {JsonIds.Format(p.Subject.Id)}" : $"#{p.Index} {p.Subject.Kind} {JsonIds.Format(p.Subject.Id)}";
}
