using System.Text.Json;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Json;
using AcShadow.Core.Poses;
using AcShadow.Core.Scenes;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.View;

/// <summary>
/// Where a view's subjects come from. From a dat: every model with geometry of its own — retail and union
/// through the shape builder, the fallback cylinder and the Setup's spheres from its primitives. From a
/// shadow file (no dat): the file's own policy, and the two primitive models from the Setup facts the file
/// records; union needs which parts have a PhysicsBSP under union's placement rule, which a retail file
/// does not say, so it is left out rather than guessed.
/// </summary>
public static class ViewSubjects
{
    /// <param name="pose">The pose, door state and motion table the parts take, and the entity scale (its policy is ignored: both are drawn).</param>
    /// <param name="motions">Where motion tables and animations come from (the dat), for the retail pose.</param>
    /// <param name="fitted">Fitted models to draw as well (part-spheres, part-boxes, part-hulls: those a chart's markers name), fitted as the chart fits them.</param>
    public static ViewSubject FromDat(Setup setup, Func<uint, GfxObj?> gfxObjs, ShapeBuildOptions pose, IMotionSource? motions, IReadOnlyCollection<string>? fitted = null)
    {
        var entityScale = pose.EntityScale;
        var retail = ShadowShapeBuilder.Build(setup, gfxObjs, pose with { Policy = ShapePolicy.Retail }, motions);
        var union = ShadowShapeBuilder.Build(setup, gfxObjs, pose with { Policy = ShapePolicy.Union }, motions);
        var primitives = SetupPrimitives.Of(setup);
        return new ViewSubject(setup.Id, "Setup",
            [
                new ModelShapes(ViewModels.Retail, retail.Shapes),
                new ModelShapes(ViewModels.Union, union.Shapes),
                new ModelShapes(ViewModels.FallbackCylinder, [primitives.FallbackCylinder(entityScale)]),
                new ModelShapes(ViewModels.Spheres, primitives.AllPrimitives(entityScale)),
                .. Fitted(setup, gfxObjs, pose, motions, fitted ?? []),
            ], Dumps(gfxObjs))
        {
            Diagnostics = retail.Diagnostics,
        };
    }

    /// <summary>
    /// The fitted models a chart compares, prepared exactly as the chart prepares them (<see cref="ShapeModels"/>),
    /// so a model's failure markers stand with that model's shapes: a part's sphere, box or hull in its part's pose.
    /// </summary>
    private static IEnumerable<ModelShapes> Fitted(Setup setup, Func<uint, GfxObj?> gfxObjs, ShapeBuildOptions pose, IMotionSource? motions, IReadOnlyCollection<string> models)
    {
        var wanted = new[] { ViewModels.PartSpheres, ViewModels.PartBoxes, ViewModels.PartHulls }.Where(models.Contains).ToArray();
        if (wanted.Length == 0) yield break;
        var bsps = new CompiledBspCache(id => gfxObjs(id) is { } g ? BspExtractor.Extract(g) : null);
        var chart = new ChartSubject(setup, gfxObjs, bsps.Get, pose.EntityScale) { Pose = pose, Motions = motions };
        foreach (var name in wanted)
        {
            var prepared = ShapeModels.Find(name)!.Prepare(chart);
            var kind = name switch { ViewModels.PartBoxes => "box", ViewModels.PartHulls => "hull", _ => "sphere" };
            var drawn = prepared.Shapes.Select(s => s.Polytope is { } solid
                    ? ShapeTessellation.Solid($"{s.Name} as {kind}", s.Pose, solid)
                    : s.Shape.CollisionType == CollisionType.Sphere && float.IsFinite(s.Shape.Radius) && s.Shape.Radius > 0f
                        ? ShapeTessellation.Sphere($"{s.Name} as {kind}", s.Shape.LocalPosition, s.Shape.Radius) : null)
                .OfType<ViewShape>().ToArray();
            yield return new ModelShapes(name, []) { Drawn = drawn };
        }
    }

    /// <summary>A bare GfxObj a landblock places: the one-part object a scene export describes (<see cref="BareGfxObjShape"/>).</summary>
    public static ViewSubject FromBareGfxObj(GfxObj gfx, Func<uint, GfxObj?> gfxObjs, float entityScale)
    {
        var retail = BareGfxObjShape.Build(gfx, gfxObjs, new ShapeBuildOptions(ShapePolicy.Retail, entityScale));
        var union = BareGfxObjShape.Build(gfx, gfxObjs, new ShapeBuildOptions(ShapePolicy.Union, entityScale));
        return new ViewSubject(gfx.Id, "GfxObj",
            [new ModelShapes(ViewModels.Retail, retail.Shapes), new ModelShapes(ViewModels.Union, union.Shapes)], Dumps(gfxObjs))
        {
            Diagnostics = retail.Diagnostics,
        };
    }

    /// <summary>An acshadow.shadow/1 file's text and a way to find the BSP dumps it names.</summary>
    public static ViewSubject FromShadowFile(string json, Func<uint, BspDump?> bsps)
    {
        var set = ShadowFileReader.Read(json);
        using var doc = JsonDocument.Parse(json);
        var primitives = SetupPrimitives.FromShadowFile(doc.RootElement);
        return new ViewSubject(set.SetupId, "Setup",
            [
                new ModelShapes(set.Policy.Name(), set.Shapes),
                new ModelShapes(ViewModels.FallbackCylinder, [primitives.FallbackCylinder(set.EntityScale)]),
                new ModelShapes(ViewModels.Spheres, primitives.AllPrimitives(set.EntityScale)),
            ], bsps)
        {
            Diagnostics = set.Diagnostics,
        };
    }

    /// <summary>A bare GfxObj of a scene file: its one shape (already in the file) and its dump.</summary>
    public static ViewSubject FromSceneGfxObj(uint gfxObjId, string policy, IReadOnlyList<ShadowShape> shapes, Func<uint, BspDump?> bsps) =>
        new(gfxObjId, "GfxObj", [new ModelShapes(policy, shapes)], bsps);

    private static Func<uint, BspDump?> Dumps(Func<uint, GfxObj?> gfxObjs)
    {
        var cache = new Dictionary<uint, BspDump?>();
        return id =>
        {
            if (!cache.TryGetValue(id, out var dump)) cache[id] = dump = gfxObjs(id) is { } gfx ? BspExtractor.Extract(gfx) : null;
            return dump;
        };
    }
}
