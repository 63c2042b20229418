using System.Globalization;
using System.Numerics;
using AcShadow.Core.Batch;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.View;

/// <summary>
/// Lays subjects out as a <see cref="ViewScene"/>: one group per model (in <see cref="ViewModels.Order"/>,
/// then any other), each holding every object that has shapes under that model, the reference model first;
/// a landblock's indoor cells; then, per model, its chart failures (false passes, then false blocks) as
/// markers in the frame of each object they belong to. A shape another model shares with the reference is
/// not repeated: the layer's note says how many it shares. Nothing that cannot be drawn is drawn (a
/// non-finite number, a shape too far from the origin): it is left out with a warning.
/// A compiled scene is laid out by chosen model instead (<see cref="ForCompiledScene"/>).
/// </summary>
public static class ViewSceneBuilder
{
    /// <summary>Marker size, centre to corner: small against a 0.5 m probe, big enough to find in a 2 m doorway.</summary>
    public const float MarkerRadius = 0.04f;

    /// <summary>
    /// How far from the view's origin a drawn point may lie: past 100 km (a landblock is 192 m, the world
    /// about 50 km) float metres have lost their centimetres and a drawing at any readable scale would be
    /// larger than a screen, so such a shape is left out with a <see cref="ViewDiagnosticCodes.TooFarToDraw"/> warning.
    /// </summary>
    public const float MaxDistance = 100_000f;

    public static ViewScene ForSetup(ViewSubject subject, IReadOnlyList<ChartFailure> failures) =>
        Build(JsonIds.Format(subject.Id), $"{subject.Kind} {JsonIds.Format(subject.Id)}", Vector3.Zero,
            [new ViewPlacement(0, subject, Frame.Identity)], [], failures, single: true, []);

    /// <param name="worldOrigin">The landblock's corner in world coordinates; placements are relative to it.</param>
    /// <param name="placements">Every object the landblock places, outdoors and in its cells, numbered as the compiled scene numbers them.</param>
    public static ViewScene ForLandblock(uint landBlockInfoId, Vector3 worldOrigin, IReadOnlyList<ViewPlacement> placements, IReadOnlyList<ViewCell> cells,
        IReadOnlyList<ChartFailure> failures, IReadOnlyList<string> notes) =>
        Build(LandblockIds.Short(landBlockInfoId),
            string.Create(CultureInfo.InvariantCulture, $"Landblock {LandblockIds.Short(landBlockInfoId)}: {placements.Count} object(s), {cells.Count} cell(s), world origin ({worldOrigin.X}, {worldOrigin.Y})"),
            worldOrigin, placements, cells, failures, single: false, notes);

    /// <summary>
    /// A compiled scene: one group per chosen model, in the ladder's order (so a viewer toggles "what was
    /// compiled to boxes"), each object in the one group of its model, then the indoor cells, then the chart's
    /// failures. Every model group is filled: here the groups split the objects instead of overlaying them.
    /// The cells are translucent, so what stands in them shows.
    /// </summary>
    public static ViewScene ForCompiledScene(CompiledSceneDrawing scene, IReadOnlyList<ChartFailure> failures)
    {
        var landblock = LandblockIds.Short(scene.LandblockId);
        var groups = new List<ViewGroup>();
        var warnings = new List<string>();
        foreach (var model in Compile.ModelLadder.Names)
        {
            var objects = scene.Objects.Where(p => p.Model == model && p.Shapes.Count > 0)
                .Select(p => Drawable(new ViewObject(p.Name, p.Frame, p.Shapes) { Key = I(p.Index) }, warnings)).OfType<ViewObject>().ToArray();
            if (objects.Length > 0)
                groups.Add(new ViewGroup(model, ViewModels.Description(model), ViewModels.Colour(model), objects) { Filled = true });
        }
        var cells = scene.Cells.Select((c, i) => Drawable(new ViewObject(c.Name, c.Frame, c.Shapes) { Key = CellKey(c.Id) }, warnings)).OfType<ViewObject>().ToArray();
        if (cells.Length > 0) groups.Add(new ViewGroup(ViewModels.Cells, ViewModels.Description(ViewModels.Cells), ViewModels.Colour(ViewModels.Cells), cells));
        groups.AddRange(FailureGroups(scene.Objects.Select(p => (p.Id, p.Name, p.Frame)).ToArray(), failures));
        var drawn = scene.Objects.Count(p => p.Shapes.Count > 0);
        var notes = new List<string>
        {
            string.Create(CultureInfo.InvariantCulture,
                $"Each object as the model `acshadow scene` chose for it (mover radius {string.Join(", ", scene.MoverRadii.Select(r => r.ToString(CultureInfo.InvariantCulture)))} m, tolerance {scene.TolerancePercent} %); indoor cells as their retail polygons."),
        };
        if (drawn < scene.Objects.Count + scene.Undrawn)
            notes.Add($"{scene.Objects.Count + scene.Undrawn - drawn} placed object(s) have no shape to draw (no model, or a model with no shapes).");
        warnings.AddRange(scene.Warnings);
        return new ViewScene(landblock + "-compiled",
            string.Create(CultureInfo.InvariantCulture,
                $"Landblock {landblock} compiled: {scene.Objects.Count + scene.Undrawn} object(s), {scene.Cells.Count} cell(s), world origin ({scene.WorldOrigin.X}, {scene.WorldOrigin.Y})"),
            scene.WorldOrigin, groups, notes) { Warnings = warnings };
    }

    /// <summary>A cell's label in every drawing of its landblock: "c" and its number in the landblock (0x…0100 is c0).</summary>
    public static string CellKey(uint cellId) => "c" + I((int)(cellId & 0xFFFF) - 0x0100);

    private static ViewScene Build(string name, string title, Vector3 worldOrigin, IReadOnlyList<ViewPlacement> placements, IReadOnlyList<ViewCell> cells,
        IReadOnlyList<ChartFailure> failures, bool single, IReadOnlyList<string> notes)
    {
        var warnings = new List<string>();
        foreach (var subject in placements.Select(p => p.Subject).DistinctBy(s => (s.Id, s.Kind)))
            warnings.AddRange(subject.Diagnostics.Select(d => $"{JsonIds.Format(subject.Id)}: {d.Code}: {d.Message}"));

        // The reference is the first model a subject lists (retail, or a shadow file's own policy).
        var reference = placements.Select(p => p.Subject.Models.FirstOrDefault()?.Model).FirstOrDefault(m => m is not null);
        var models = placements.SelectMany(p => p.Subject.Models.Select(m => m.Model)).Distinct().ToArray();
        var ordered = ViewModels.Order.Where(models.Contains).Concat(models.Where(m => !ViewModels.Order.Contains(m)));
        // An object placed twice shares one shape list (and so one mesh in the glb).
        var tessellated = new Dictionary<(uint, string, string), (IReadOnlyList<ViewShape> Shapes, int Shared)>();
        var groups = new List<ViewGroup>();
        var referenceDrawn = false;
        foreach (var model in ordered)
        {
            var objects = new List<ViewObject>();
            var shared = 0;
            var cylinders = 0;
            foreach (var p in placements)
            {
                if (p.Subject.Models.FirstOrDefault(m => m.Model == model) is not { } shapes) continue;
                var key = (p.Subject.Id, p.Subject.Kind, model);
                if (!tessellated.TryGetValue(key, out var drawn))
                {
                    // A shape the reference has too is drawn once, in the reference's layer.
                    var own = model == reference ? shapes.Shapes
                        : shapes.Shapes.Where(s => !(p.Subject.Models.FirstOrDefault(m => m.Model == reference)?.Shapes.Contains(s) ?? false)).ToArray();
                    var made = new List<ViewShape>(shapes.Drawn ?? []);
                    foreach (var s in own)
                    {
                        if (!IsFinite(s))
                        {
                            warnings.Add($"{JsonIds.Format(p.Subject.Id)}: {DiagnosticCodes.NonFinite}: {model}: {ShapeTessellation.NameOf(s)} has a non-finite position, rotation, scale or radius: not drawn");
                            continue;
                        }
                        if (ShapeTessellation.Tessellate(s, p.Subject.Bsps) is { } shape) made.Add(shape);
                    }
                    tessellated[key] = drawn = (made, shapes.Shapes.Count - own.Count);
                    cylinders += own.Count(s => s.CollisionType == Fixtures.Shapes.CollisionType.Cylinder);
                }
                shared += drawn.Shared;
                if (drawn.Shapes.Count > 0 && Drawable(new ViewObject(ObjectName(p, single), p.Frame, drawn.Shapes) { Key = single ? null : I(p.Index) }, warnings) is { } o)
                    objects.Add(o);
            }
            var isReference = model == reference;
            var note = shared == 0 ? null
                : objects.Count == 0 ? $"the same as {reference}: its {I(shared)} shape(s) are drawn in the {reference} layer"
                : $"{I(shared)} shape(s) the same as {reference}'s are drawn in the {reference} layer only";
            if (model == ViewModels.Spheres && cylinders > 0) note = (note is null ? "" : note + "; ") + "the Setup's CylSpheres are its cylinders";
            if (objects.Count > 0 || note is not null)
                groups.Add(new ViewGroup(model, ViewModels.Description(model), ViewModels.Colour(model), objects) { Filled = isReference, Note = note });
            referenceDrawn |= isReference && objects.Count > 0;
        }
        var allNotes = notes.ToList();
        if (!referenceDrawn && reference is not null)
            allNotes.Insert(0, $"{reference} has no shape to draw: the object collides with nothing, so no layer is filled; the outlines are what the other models would register.");

        var cellObjects = cells.Select(c => Drawable(new ViewObject($"cell {JsonIds.Format(c.Id)}", c.Frame,
            [ShapeTessellation.Polygons("physics polygons", new Fixtures.Collision.PartPose(Vector3.Zero, Quaternion.Identity, 1f), c.Physics)]) { Key = CellKey(c.Id) }, warnings))
            .OfType<ViewObject>().ToArray();
        if (cellObjects.Length > 0)
            groups.Add(new ViewGroup(ViewModels.Cells, ViewModels.Description(ViewModels.Cells), ViewModels.Colour(ViewModels.Cells), cellObjects));
        groups.AddRange(FailureGroups(placements.Select(p => (p.Subject.Id, ObjectName(p, single), p.Frame)).ToArray(), failures));
        var drawnModels = groups.Select(g => g.Name).ToHashSet();
        foreach (var missing in failures.Select(f => f.Model).Distinct().Where(m => !drawnModels.Contains(m)).Order(StringComparer.Ordinal))
            allNotes.Add($"{missing}'s shapes are not drawn here (a view from fixtures has no dat to fit them from): its markers stand alone; `view` from the dat draws them.");
        return new ViewScene(name, title, worldOrigin, groups, allNotes) { Warnings = warnings };
    }

    /// <summary>
    /// Per model (in chart order), a layer of its false passes then one of its false blocks, in the model's
    /// colour: diamonds for false passes, squares for false blocks. Names and notes give the probe radius.
    /// </summary>
    private static IEnumerable<ViewGroup> FailureGroups(IReadOnlyList<(uint Id, string Name, Frame Frame)> placed, IReadOnlyList<ChartFailure> failures)
    {
        foreach (var (model, falsePass) in failures.Select(f => (f.Model, f.FalsePass)).Distinct()
                     .OrderBy(f => Rank(f.Model)).ThenBy(f => f.Model, StringComparer.Ordinal).ThenBy(f => !f.FalsePass))
        {
            var objects = new List<ViewObject>();
            var count = 0;
            var radii = new SortedSet<float>();
            foreach (var p in placed)
            {
                var mine = failures.Where(f => f.ObjectId == p.Id && f.Model == model && f.FalsePass == falsePass).ToArray();
                if (mine.Length == 0) continue;
                count += mine.Length;
                radii.UnionWith(mine.Select(f => f.Radius));
                var label = string.Create(CultureInfo.InvariantCulture,
                    $"{I(mine.Length)} {(falsePass ? "false pass" : "false block")}{(mine.Length == 1 ? "" : falsePass ? "es" : "s")} of {model} (probe r {Radii(mine.Select(f => f.Radius))} m)");
                objects.Add(new ViewObject(p.Name, p.Frame, [ShapeTessellation.Markers(label, mine.Select(f => f.Center).ToArray(), MarkerRadius, falsePass)]));
            }
            if (objects.Count > 0)
                yield return new ViewGroup(ViewModels.FailureGroup(falsePass, model),
                    falsePass ? $"probes the reference blocks and {model} lets through, marked at the probe sphere's centre" : $"probes {model} blocks and the reference lets through, marked at the probe sphere's centre",
                    ViewModels.Colour(model), objects)
                {
                    FalsePass = falsePass,
                    Note = string.Create(CultureInfo.InvariantCulture, $"{I(count)} probe(s) of radius {Radii(radii)} m, marked at their centres"),
                };
        }
    }

    private static string Radii(IEnumerable<float> radii) => string.Join(", ", radii.Distinct().Order().Select(r => r.ToString(CultureInfo.InvariantCulture)));

    /// <summary>The object, or null with a warning when its frame or a shape's point is not finite or lies past <see cref="MaxDistance"/>.</summary>
    private static ViewObject? Drawable(ViewObject o, List<string> warnings)
    {
        var f = o.Frame;
        if (!(float.IsFinite(f.Position.X) && float.IsFinite(f.Position.Y) && float.IsFinite(f.Position.Z)
              && float.IsFinite(f.Rotation.X) && float.IsFinite(f.Rotation.Y) && float.IsFinite(f.Rotation.Z) && float.IsFinite(f.Rotation.W)))
        {
            warnings.Add($"{o.Name}: {DiagnosticCodes.NonFinite}: its placement frame is not finite: not drawn");
            return null;
        }
        var kept = new List<ViewShape>();
        foreach (var shape in o.Shapes)
        {
            var points = shape.OneSided.Positions.Concat(shape.TwoSided.Positions).Select(f.Apply).ToArray();
            if (points.Any(p => !(float.IsFinite(p.X) && float.IsFinite(p.Y) && float.IsFinite(p.Z))))
                warnings.Add($"{o.Name}: {DiagnosticCodes.NonFinite}: {shape.Name} has a non-finite point: not drawn");
            else if (points.Any(p => MathF.Max(MathF.Abs(p.X), MathF.Max(MathF.Abs(p.Y), MathF.Abs(p.Z))) > MaxDistance))
                warnings.Add(string.Create(CultureInfo.InvariantCulture, $"{o.Name}: {ViewDiagnosticCodes.TooFarToDraw}: {shape.Name} reaches more than {MaxDistance} m from the view's origin: not drawn"));
            else kept.Add(shape);
        }
        return kept.Count == 0 ? null : kept.Count == o.Shapes.Count ? o : o with { Shapes = kept };
    }

    private static bool IsFinite(ShadowShape s) =>
        float.IsFinite(s.LocalPosition.X) && float.IsFinite(s.LocalPosition.Y) && float.IsFinite(s.LocalPosition.Z)
        && float.IsFinite(s.LocalRotation.X) && float.IsFinite(s.LocalRotation.Y) && float.IsFinite(s.LocalRotation.Z) && float.IsFinite(s.LocalRotation.W)
        && float.IsFinite(s.Scale) && float.IsFinite(s.Radius) && float.IsFinite(s.CylHeight);

    private static int Rank(string model) => Chart.Models.ShapeModels.All.Select(m => m.Name).ToList().IndexOf(model) is var i and >= 0 ? i : int.MaxValue;

    private static string I(int value) => value.ToString(CultureInfo.InvariantCulture);

    private static string ObjectName(ViewPlacement p, bool single) =>
        single ? $"{p.Subject.Kind} {JsonIds.Format(p.Subject.Id)}" : $"#{p.Index} {p.Subject.Kind} {JsonIds.Format(p.Subject.Id)}";
}
