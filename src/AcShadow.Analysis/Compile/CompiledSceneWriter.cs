using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Movement;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Core.Scenes;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Scenes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Compile;

/// <summary>
/// compiled-scene.json: per placed object its chosen model, the shapes that model tests (part-space
/// geometry with the part's pose, so a reader answers with the same floats) and the evidence. Every
/// field but <c>evidence.medianNsPerQuery</c> and <c>timing</c> is the same bytes on every run (the
/// counted costs, <c>opsPerQuery</c> and <c>…OpsPerPosition</c>, included).
/// </summary>
internal static class CompiledSceneWriter
{
    public static byte[] Write(CompiledSceneReport report)
    {
        var scene = report.Scene;
        var options = report.Options;
        var coordinates = scene.Coordinates;
        var objects = new JsonArr();
        var byModel = new SortedDictionary<string, int>(StringComparer.Ordinal);
        foreach (var placed in report.Placed)
        {
            var c = report.For(placed.Object);
            if (c?.Model is { } model) byModel[model] = byModel.GetValueOrDefault(model) + 1;
            objects.Add(ObjectJson(placed, scene, c));
        }
        var totals = report.Totals;
        var json = new JsonObj()
            .Add("format", FileFormats.CompiledScene.Format)
            .Add("landblockId", JsonIds.Format(scene.LandBlockInfoId))
            .Add("landblock", new JsonObj().Add("x", coordinates.X).Add("y", coordinates.Y))
            .Add("worldOrigin", new JsonArr().Add(JsonNum.Of(coordinates.WorldOriginX)).Add(JsonNum.Of(coordinates.WorldOriginY)).Add(JsonNum.Of(0)))
            .Add("entityScale", options.EntityScale)
            .Add("moverRadii", JsonArr.Of(options.Chart.Radii, r => JsonNum.Of(r)))
            .Add("tolerancePercent", JsonNum.Of(options.TolerancePercent))
            .Add("ladder", JsonArr.Of(ModelLadder.Names))
            .Add("mover", options.Movement is { } moving ? MoverJson(moving.Mover) : JsonNull.Value)
            .Add("probes", new JsonObj()
                .Add("gridSpacing", options.Chart.Spacing)
                .Add("probeRadius", options.Chart.ProbeRadius)
                .Add("stabilityOffset", options.Chart.StabilityOffset))
            .Add("summary", new JsonObj()
                .Add("objects", report.Placed.Count)
                .Add("cells", report.Cells.Count)
                .Add("models", Counts(byModel))
                .Add("bspGfxObjs", BspGfxObjs(report).Count)
                .Add("positions", totals.Positions)
                .Add("agree", totals.Agree)
                .Add("falsePass", totals.FalsePass)
                .Add("falseBlock", totals.FalseBlock)
                .Add("retailOpsPerPosition", Ops(totals.RetailOps))
                .Add("compiledOpsPerPosition", Ops(totals.CompiledOps))
                .Add("exhaustiveOpsPerPosition", Ops(totals.ExhaustiveOps))
                .Add("narrowFloorOpsPerPosition", Ops(totals.NarrowFloorOps)))
            .Add("timing", new JsonObj()
                .Add("retailMedianNsPerPosition", JsonNum.Of(totals.Retail.MedianNs))
                .Add("compiledMedianNsPerPosition", JsonNum.Of(totals.Compiled.MedianNs))
                .Add("exhaustiveMedianNsPerPosition", JsonNum.Of(totals.Exhaustive.MedianNs)))
            .Add("objects", objects)
            .Add("cells", JsonArr.Of(report.Cells, c => CellJson(c, scene)));
        return CanonicalJsonWriter.WriteUtf8(json);
    }

    /// <summary>The GfxObjs whose BSP dump a reader needs: the BSP parts of objects still modelled by retail.</summary>
    public static IReadOnlyList<uint> BspGfxObjs(CompiledSceneReport report) =>
        report.Placed.Select(p => report.For(p.Object)).OfType<ObjectCompilation>()
            .Where(c => c.Chosen is not null)
            .SelectMany(c => c.Chosen!.Shapes.Where(s => s.Bsp is not null).Select(s => s.Bsp!.GfxObjId))
            .Distinct().Order().ToArray();

    /// <summary>A counted cost, to 3 decimals: an average of integers, the same bytes on every run.</summary>
    private static JsonNode Ops(double ops) => JsonNum.Of(Math.Round(ops, 3));

    private static JsonObj Counts(SortedDictionary<string, int> counts)
    {
        var o = new JsonObj();
        foreach (var (model, n) in counts) o.Add(model, n);
        return o;
    }

    /// <summary>The dump of a cell's PhysicsBSP beside compiled-scene.json (its id is the cell's).</summary>
    public static string CellBspPath(uint cellId) => $"cells/0x{cellId:X8}.bsp.json";

    private static JsonObj CellJson(CellCompilation c, LandblockScene scene)
    {
        var frame = c.Cell.Position;
        var (wx, wy, wz) = WorldFrame.Origin(scene.Coordinates, frame);
        var probes = new JsonObj();
        foreach (var kind in new[] { ProbeKind.Grid }.Concat(ProbeKinds.Stability))
            probes.Add(kind == ProbeKind.SplittingPlane ? "splittingPlane" : ProbeKinds.Name(kind), ChartProbes.Count(c.Probes, kind));
        probes.Add("total", c.Probes.Count);
        return new JsonObj()
            .Add("cellId", JsonIds.Format(c.Cell.Id))
            .Add("environmentId", JsonIds.Format(c.Cell.EnvironmentFileId))
            .Add("cellStructure", c.Cell.CellStructure)
            .Add("landblockFrame", new JsonObj().Add("origin", frame.Position).Add("orientation", JsonShapes.Quaternion(frame.Rotation)))
            .Add("worldFrame", new JsonObj().Add("origin", new JsonArr().Add(JsonNum.Of(wx)).Add(JsonNum.Of(wy)).Add(JsonNum.Of(wz)))
                .Add("orientation", JsonShapes.Quaternion(frame.Rotation)))
            .Add("model", c.Bsp is null ? null : CellCompilation.Model)
            .Add("file", c.Bsp is null ? null : CellBspPath(c.Cell.Id))
            .Add("polygons", c.Bsp?.Polygons.Length ?? 0)
            .Add("probes", probes)
            .Add("diagnostics", JsonArr.Of(c.Diagnostics, d => new JsonObj().Add("code", d.Code).Add("message", d.Message)));
    }

    private static JsonObj ObjectJson(PlacedObject p, LandblockScene scene, ObjectCompilation? c)
    {
        var placed = p.Object;
        var (wx, wy, wz) = WorldFrame.Origin(scene.Coordinates, placed.Frame);
        var json = new JsonObj()
            .Add("index", placed.Index)
            .Add("placedBy", placed.PlacedBy.Name())
            .Add("placedIndex", placed.PlacedIndex)
            .Add("cellId", p.CellId is { } cell ? JsonIds.Format(cell) : null)
            .Add("id", JsonIds.Format(placed.Id))
            .Add("kind", placed.Kind.Name())
            .Add("landblockFrame", new JsonObj().Add("origin", placed.Frame.Position).Add("orientation", JsonShapes.Quaternion(placed.Frame.Rotation)))
            .Add("worldFrame", new JsonObj().Add("origin", new JsonArr().Add(JsonNum.Of(wx)).Add(JsonNum.Of(wy)).Add(JsonNum.Of(wz)))
                .Add("orientation", JsonShapes.Quaternion(placed.Frame.Rotation)))
            .Add("model", c?.Model);
        var shapes = new JsonArr();
        if (c?.Chosen is { } chosen)
            foreach (var s in chosen.Shapes) shapes.Add(ShapeJson(s));
        json.Add("shapes", shapes);
        if (c?.Chosen is { } model && ShapeBounds.Of(model.Shapes) is { IsEmpty: false } bounds)
        {
            var (center, radius) = SceneCompiler.Bound(bounds);
            json.Add("bound", new JsonObj().Add("center", center).Add("radius", radius));
        }
        else json.Add("bound", JsonNull.Value);
        json.Add("evidence", c is null || c.Probes.Count == 0 ? JsonNull.Value : Evidence(c));
        json.Add("diagnostics", JsonArr.Of(c?.Diagnostics ?? [], d => new JsonObj().Add("code", d.Code).Add("message", d.Message)));
        return json;
    }

    private static JsonObj Evidence(ObjectCompilation c)
    {
        var probes = new JsonObj();
        foreach (var kind in new[] { ProbeKind.Grid, ProbeKind.Doorway }.Concat(ProbeKinds.Stability))
            probes.Add(kind == ProbeKind.SplittingPlane ? "splittingPlane" : ProbeKinds.Name(kind), ChartProbes.Count(c.Probes, kind));
        probes.Add("total", c.Probes.Count);
        return new JsonObj()
            .Add("probes", probes)
            .Add("candidates", JsonArr.Of(c.Candidates, k => new JsonObj()
                .Add("model", k.Model).Add("shapes", k.Shapes).Add("opsPerQuery", Ops(k.OpsPerQuery))
                .Add("falsePass", k.FalsePass).Add("falseBlock", k.FalseBlock).Add("accepted", k.Accepted)
                .Add("movement", k.Movement is { } walked ? MovementJson(walked) : JsonNull.Value)))
            .Add("falsePass", c.FalsePass)
            .Add("falseBlock", c.FalseBlock)
            .Add("movement", c.Candidates.Count > 0 && c.Candidates[^1].Movement is { } chosen ? MovementJson(chosen) : JsonNull.Value)
            .Add("opsPerQuery", new JsonObj().Add("chosen", Ops(c.ChosenOps)).Add("retail", Ops(c.RetailOps)))
            .Add("medianNsPerQuery", new JsonObj().Add("chosen", JsonNum.Of(c.ChosenTiming.MedianNs)).Add("retail", JsonNum.Of(c.RetailTiming.MedianNs)));
    }

    /// <summary>A model's verdicts on the object's movement cases (movement.md §4.2): counts over non-fragile cases, fragile ones apart.</summary>
    private static JsonObj MovementJson(MovementCounts m) => new JsonObj()
        .Add("cases", m.Cases)
        .Add("fragile", m.Fragile)
        .Add("agree", m[MovementVerdict.Agree])
        .Add("falsePass", m[MovementVerdict.FalsePass])
        .Add("falseBlock", m[MovementVerdict.FalseBlock])
        .Add("deflection", m[MovementVerdict.Deflection])
        .Add("stepMismatch", m[MovementVerdict.StepMismatch])
        .Add("standoffDrift", m[MovementVerdict.StandOffDrift])
        .Add("fragileFalsePass", m.FragileFalsePass);

    /// <summary>The mover the movement cases walk: the spheres a transition uses and its step heights.</summary>
    private static JsonObj MoverJson(Fixtures.Movement.Mover mover) => new JsonObj()
        .Add("spheres", JsonArr.Of(mover.Spheres.Take(2), s => new JsonObj().Add("center", s.Center).Add("radius", s.Radius)))
        .Add("stepUpHeight", mover.StepUpHeight)
        .Add("stepDownHeight", mover.StepDownHeight);

    private static JsonObj ShapeJson(PreparedShape s)
    {
        var shape = s.Shape;
        if (s.Box is { } box)
            return Part("box", s).Add("center", box.Center).Add("axes", JsonShapes.Quaternion(box.Axes)).Add("halfExtents", box.HalfExtents);
        if (s.Polytope is { } hull)
        {
            var index = new Dictionary<System.Numerics.Vector3, int>();
            for (var i = 0; i < hull.Vertices.Count; i++) index.TryAdd(hull.Vertices[i], i);
            return Part("hull", s)
                .Add("vertices", JsonArr.Of(hull.Vertices, v => JsonArr.Of(v)))
                .Add("faces", JsonArr.Of(hull.Faces, f => new JsonObj()
                    .Add("vertices", JsonArr.Of(f.Vertices.Select(v => index[v])))
                    .Add("normal", f.Normal).Add("d", f.D)));
        }
        return shape.CollisionType switch
        {
            CollisionType.Bsp when s.Bsp is { } bsp => Part("bsp", s).Add("file", FileFormats.Bsp.PathFor(bsp.GfxObjId)),
            CollisionType.Cylinder => new JsonObj().Add("type", "cylinder").Add("source", s.Name).Add("base", shape.LocalPosition).Add("radius", shape.Radius).Add("height", shape.CylHeight),
            _ => new JsonObj().Add("type", "sphere").Add("source", s.Name).Add("center", shape.LocalPosition).Add("radius", shape.Radius),
        };
    }

    private static JsonObj Part(string type, PreparedShape s) => new JsonObj()
        .Add("type", type)
        .Add("source", s.Name)
        .Add("part", s.Shape.SourceIndex)
        .Add("gfxObjId", s.Shape.GfxObjId is { } id ? JsonIds.Format(id) : null)
        .Add("pose", new JsonObj().Add("position", s.Pose.Position).Add("orientation", JsonShapes.Quaternion(s.Pose.Rotation)).Add("scale", s.Pose.Scale));
}
