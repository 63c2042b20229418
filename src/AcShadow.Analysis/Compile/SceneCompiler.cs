using AcShadow.Core.Export;
using System.Numerics;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Movement;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Core.Cells;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Json;
using AcShadow.Core.Scenes;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Scenes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Compile;

/// <summary>
/// Compiles a landblock: every distinct placed object gets the first model of <see cref="ModelLadder"/>
/// that qualifies (<see cref="SceneCompileOptions.Accepts"/>) on the chart's probes — grid, doorway lines
/// and stability probes for every mover radius — then the chosen model and retail are timed with the
/// chart's timer, and the whole scene is asked at every probe with every object as retail and as
/// compiled (<see cref="SceneTotals"/>). Objects one after another, so answers are the same on every
/// machine and timings do not disturb each other.
/// </summary>
internal static class SceneCompiler
{
    public static CompiledSceneReport Compile(LandblockScene scene, ChartSubjects subjects, SceneCompileOptions options, IQueryTimer timer, Action<int, int>? progress = null)
    {
        if (options.Problem() is { } problem) throw new ArgumentException(problem, nameof(options));
        var placed = PlacedObject.Of(scene);
        var distinct = placed.Select(p => (p.Object.Kind, p.Object.Id)).Distinct().ToArray();
        var total = distinct.Length + scene.Cells.Count;
        var compiled = new Dictionary<(SceneObjectKind, uint), ObjectCompilation>();
        foreach (var key in distinct)
        {
            compiled[key] = CompileOne(key.Kind, key.Id, subjects, options, timer);
            progress?.Invoke(compiled.Count, total);
        }
        var structures = new CellStructures(subjects.Dat);
        var cells = new List<CellCompilation>(scene.Cells.Count);
        foreach (var cell in scene.Cells)
        {
            cells.Add(CompileCell(cell, structures, options.Chart));
            progress?.Invoke(compiled.Count + cells.Count, total);
        }
        var totals = Totals(placed, compiled, cells, options, timer);
        return new CompiledSceneReport(options, scene, placed, compiled, cells, totals);
    }

    /// <summary>
    /// One indoor cell: its structure's PhysicsBSP in the cell's frame, kept as retail
    /// (<see cref="CellCompilation"/> says why), with the grid and stability probes the scene is checked at.
    /// </summary>
    public static CellCompilation CompileCell(EnvCell cell, CellStructures structures, ChartOptions chart)
    {
        var frame = new PartPose(cell.Position.Position, ClientFrameMatrix.PlacedRotation(cell.Position.Rotation), 1f);
        var (geometry, problem) = structures.For(cell.EnvironmentFileId, cell.CellStructure);
        if (geometry is null)
            return new CellCompilation(cell, null, null, frame, ProbeSpheres.Empty, Bounds.Empty, [new Diagnostic(ExportDiagnosticCodes.Unresolved, $"EnvCell {JsonIds.Format(cell.Id)}: {problem}")]);
        var physics = geometry.Physics with { GfxObjId = cell.Id };
        var diagnostics = physics.Diagnostics.Select(d => new Diagnostic(ExportDiagnosticCodes.BspGeometry, d)).ToList();
        if (!(float.IsFinite(cell.Position.Position.X) && float.IsFinite(cell.Position.Position.Y) && float.IsFinite(cell.Position.Position.Z)) || !float.IsFinite(cell.Position.Rotation.Length()) || cell.Position.Rotation.Length() < 1e-6f)
        {
            diagnostics.Add(new Diagnostic(ExportDiagnosticCodes.Unresolved, $"EnvCell {JsonIds.Format(cell.Id)}: its frame is not finite or has no rotation; nothing of it is asked"));
            return new CellCompilation(cell, physics, null, frame, ProbeSpheres.Empty, Bounds.Empty, diagnostics);
        }
        var bsp = CompiledBsp.Compile(physics);
        var bounds = bsp.Polygons.SelectMany(p => p.Vertices).Aggregate(Bounds.Empty, (b, v) => b.Include(v));
        Probe[] probes = bsp.Polygons.Length == 0 ? []
            : [.. ProbeGrid.Build(bounds, chart).Probes, .. StabilityProbes.Build(bsp, new PartPose(Vector3.Zero, Quaternion.Identity, 1f), chart)];
        return new CellCompilation(cell, physics, bsp, frame, new ProbeSpheres(probes), bounds, diagnostics);
    }

    public static ObjectCompilation CompileOne(SceneObjectKind kind, uint id, ChartSubjects subjects, SceneCompileOptions options, IQueryTimer timer)
    {
        ChartSubject? subject;
        string? why;
        try
        {
            (subject, why) = kind switch
            {
                SceneObjectKind.Setup => (subjects.For(id, options.EntityScale), "not in the dat"),
                SceneObjectKind.GfxObj => (subjects.ForBareGfxObj(id, options.EntityScale), "not in the dat"),
                _ => (null, $"neither a Setup ({DatObjectKind.Setup.RangeText()}) nor a GfxObj ({DatObjectKind.GfxObj.RangeText()})"),
            };
        }
        catch (DatFormatException e)
        {
            (subject, why) = (null, $"unreadable: {e.Message}");
        }
        if (subject is null)
            return Unresolved(kind, id, null, [new Diagnostic(ExportDiagnosticCodes.Unresolved, $"{JsonIds.Format(id)}: {why}")]);
        return Compile(subject, kind, options, timer);
    }

    /// <summary>
    /// One object: every model of the ladder counted on the probes (<see cref="QueryCost"/>), then tried
    /// cheapest count first (ladder order among equal counts) until one qualifies (on the probes and, with
    /// movement asked, on the object's movement cases: no false pass); the chosen model and retail timed. Retail always qualifies, so a model that counts more than retail is never tried.
    /// </summary>
    public static ObjectCompilation Compile(ChartSubject subject, SceneObjectKind kind, SceneCompileOptions options, IQueryTimer timer)
    {
        var chart = options.Chart;
        var ladder = ModelLadder.Models;
        var prepared = ladder.Select(m => ChartRunner.Prepare(m, subject)).ToArray();
        var retailIndex = prepared.Length - 1;
        var retail = prepared[retailIndex];
        if (retail.Shapes.Count == 0)
            return Unresolved(kind, subject.Setup.Id, ObjectCompilation.Nothing, retail.Diagnostics) with { Retail = retail };
        var laid = ChartProbes.Lay(retail, prepared, chart);
        var probes = laid.Probes;
        var expected = ChartRunner.Answers(retail, probes);
        var costs = prepared.Select(m => QueryCost.PerQuery(m.Shapes, probes, chart.TimingProbes)).ToArray();
        var candidates = new List<CandidateOutcome>();
        var chosen = retailIndex;
        ObjectWalks? walks = null;
        foreach (var m in ModelLadder.ByCost(costs))
        {
            var answers = m == retailIndex ? expected : ChartRunner.Answers(prepared[m], probes);
            int falsePass = 0, falseBlock = 0;
            for (var i = 0; i < probes.Length; i++)
            {
                if (answers[i] == expected[i]) continue;
                if (expected[i]) falsePass++; else falseBlock++;
            }
            // A model with no shapes for an object that has some is no model of it.
            var accepted = prepared[m].Shapes.Count > 0 && options.Accepts(falsePass, falseBlock, probes.Length);
            // Only a model the probes accept is walked: a walk costs far more than a probe.
            MovementCounts? movement = null;
            if (accepted && options.Movement is { } moving)
            {
                walks ??= ObjectWalks.Lay(subject, moving, ladder[retailIndex]);
                movement = walks.Walk(ladder[m], null, -1, out _).Counts([.. walks.Cases.Select(c => c.Fragile)]);
                accepted = movement.FalsePasses == 0;
            }
            candidates.Add(new CandidateOutcome(ladder[m].Name, prepared[m].Shapes.Count, falsePass, falseBlock, accepted, costs[m]) { Movement = movement });
            if (!accepted) continue;
            chosen = m;
            break;
        }
        var retailTiming = timer.Measure(ModelLadder.Retail, retail, probes, chart);
        var chosenTiming = chosen == retailIndex ? retailTiming : timer.Measure(ladder[chosen].Name, prepared[chosen], probes, chart);
        // Kept compactly, not as laid: held until the scene is written, the laid probes were its largest part.
        return new ObjectCompilation(subject.Setup.Id, kind, ladder[chosen].Name, prepared[chosen], retail, new ProbeSpheres(probes),
            candidates, chosenTiming, retailTiming, laid.Bounds, [.. retail.Diagnostics, .. chosen == retailIndex ? [] : prepared[chosen].Diagnostics])
        {
            ChosenOps = costs[chosen],
            RetailOps = costs[retailIndex],
        };
    }

    private static ObjectCompilation Unresolved(SceneObjectKind kind, uint id, string? model, IReadOnlyList<Diagnostic> diagnostics) =>
        new(id, kind, model, null, null, ProbeSpheres.Empty, [], TimingStats.Of([]), TimingStats.Of([]), Bounds.Empty, diagnostics);

    /// <summary>
    /// The scene asked as a whole at every placed object's and every cell's probes, all-retail against
    /// compiled: agreement, counted operations per position (<see cref="SceneCost"/>), and time per
    /// position, the three timed in the order retail, compiled, exhaustive, exhaustive, compiled, retail with
    /// their batches pooled, so a machine that speeds up or slows down during the measurement weighs on all
    /// alike. Retail and compiled ask through the land-cell partition (<see cref="SceneQuery"/>); the
    /// exhaustive walk (every object retail, every object and cell asked) is the baseline the partition is
    /// measured against.
    /// </summary>
    private static SceneTotals Totals(IReadOnlyList<PlacedObject> placed, IReadOnlyDictionary<(SceneObjectKind, uint), ObjectCompilation> compiled,
        IReadOnlyList<CellCompilation> cells, SceneCompileOptions options, IQueryTimer timer)
    {
        var retail = Query(placed, compiled, cells, c => c.Retail);
        // The compiled scene registers each posed part on its own (PlacedParts) and asks every tree through its
        // per-radius grids (BspReachGrid): retail's answers, fewer steps.
        var grids = new BspReachGrids(options.Chart.Radii);
        // And decides the whole scene ahead of time for each mover radius over landblock voxels (SceneReachGrid).
        var chosen = Query(placed, compiled, cells, c => c.Chosen, partsApart: true, grids: grids, gridRadii: options.Chart.Radii);
        var segments = new List<(IReadOnlyList<Probe>, PartPose)>();
        foreach (var p in placed)
        {
            if (compiled.GetValueOrDefault((p.Object.Kind, p.Object.Id)) is not { } c) continue;
            segments.Add((c.Probes, new PartPose(p.Object.Frame.Position, ClientFrameMatrix.PlacedRotation(p.Object.Frame.Rotation), 1f)));
        }
        foreach (var cell in cells) segments.Add((cell.Probes, cell.Frame));
        // Moved into the landblock as they are read: held, they were most of the compile's peak memory.
        var positions = new ScenePositions(segments);
        int agree = 0, falsePass = 0, falseBlock = 0;
        foreach (var p in positions)
        {
            var expected = retail.Overlaps(p.Center, p.Radius);
            var answer = chosen.Overlaps(p.Center, p.Radius);
            if (expected == answer) agree++;
            else if (expected) falsePass++;
            else falseBlock++;
        }
        var retailOps = SceneCost.PerPosition(placed, compiled, cells, c => c.Retail, positions, options.Chart.TimingProbes, built: retail);
        var compiledOps = SceneCost.PerPosition(placed, compiled, cells, c => c.Chosen, positions, options.Chart.TimingProbes, partsApart: true, grids: grids, built: chosen);
        var exhaustiveOps = SceneCost.PerPosition(placed, compiled, cells, c => c.Retail, positions, options.Chart.TimingProbes, SceneWalk.Exhaustive, built: retail);
        var floorOps = SceneCost.PerPosition(placed, compiled, cells, c => c.Retail, positions, options.Chart.TimingProbes, SceneWalk.NarrowFloor, built: retail);
        var retailModel = new PreparedModel(retail, [], []);
        var compiledModel = new PreparedModel(chosen, [], []);
        var exhaustiveModel = new PreparedModel(retail.Exhaustive, [], []);
        const string RetailName = "scene: every object retail", CompiledName = "scene: compiled", ExhaustiveName = "scene: every object retail, every object and cell asked";
        var r1 = timer.Measure(RetailName, retailModel, positions, options.Chart);
        var c1 = timer.Measure(CompiledName, compiledModel, positions, options.Chart);
        var e1 = timer.Measure(ExhaustiveName, exhaustiveModel, positions, options.Chart);
        var e2 = timer.Measure(ExhaustiveName, exhaustiveModel, positions, options.Chart);
        var c2 = timer.Measure(CompiledName, compiledModel, positions, options.Chart);
        var r2 = timer.Measure(RetailName, retailModel, positions, options.Chart);
        var retailTiming = TimingStats.Of([.. r1.BatchNs, .. r2.BatchNs]);
        var compiledTiming = TimingStats.Of([.. c1.BatchNs, .. c2.BatchNs]);
        var exhaustiveTiming = TimingStats.Of([.. e1.BatchNs, .. e2.BatchNs]);
        var cellShapes = cells.Count(c => c.Bsp is not null);
        int Shapes(Func<ObjectCompilation, PreparedModel?> pick) => cellShapes +
            placed.Sum(p => compiled.GetValueOrDefault((p.Object.Kind, p.Object.Id)) is { } c && pick(c) is { } m ? m.Shapes.Count : 0);
        return new SceneTotals(positions.Count, agree, falsePass, falseBlock, retailTiming, compiledTiming, Shapes(c => c.Retail), Shapes(c => c.Chosen))
        {
            RetailOps = retailOps,
            CompiledOps = compiledOps,
            Exhaustive = exhaustiveTiming,
            ExhaustiveOps = exhaustiveOps,
            NarrowFloorOps = floorOps,
        };
    }

    /// <summary>
    /// Every placed object with a model, in landblock space, answered by the model <paramref name="pick"/>
    /// gives behind a bounding sphere around that model's own shapes (the mover's radius stretched for a cylinder's
    /// box profile, <see cref="BoundStretch"/>) — or, <paramref name="partsApart"/> (the
    /// compiled scene), each posed part behind its own (<see cref="PlacedParts"/>) — and every cell by its retail
    /// tree (<see cref="CellOverlapQuery"/>, as the fixtures library asks a cell); with <paramref name="grids"/>, every
    /// tree asked through its <see cref="BspReachGrid"/>s, and with <paramref name="gridRadii"/> the whole scene decided
    /// ahead for those radii (<see cref="SceneReachGrid"/>), as the fixtures library's compiled scene asks it.
    /// </summary>
    internal static SceneQuery Query(IReadOnlyList<PlacedObject> placed, IReadOnlyDictionary<(SceneObjectKind, uint), ObjectCompilation> compiled,
        IReadOnlyList<CellCompilation> cells, Func<ObjectCompilation, PreparedModel?> pick, bool partsApart = false, BspReachGrids? grids = null,
        IReadOnlyList<float>? gridRadii = null) =>
        new([.. Entries(placed, compiled, pick, partsApart, grids).Select(e => e.Entry)], CellQueries(cells, grids), gridRadii);

    /// <summary>The scene's object entries in order, each with the model it asks (one per object, or per part <paramref name="partsApart"/>).</summary>
    internal static IEnumerable<(PlacedQuery Entry, PreparedModel Model)> Entries(IReadOnlyList<PlacedObject> placed,
        IReadOnlyDictionary<(SceneObjectKind, uint), ObjectCompilation> compiled, Func<ObjectCompilation, PreparedModel?> pick, bool partsApart, BspReachGrids? grids = null)
    {
        var indexed = new Dictionary<ISphereOverlap, ISphereOverlap>(ReferenceEqualityComparer.Instance);
        foreach (var (p, model, center, radius) in Placements(placed, compiled, pick))
        {
            var o = p.Object;
            var query = model.Query;
            if (grids is not null && query is ObjectOverlapQuery parts && !indexed.TryGetValue(parts, out query))
                indexed[parts] = query = parts.Indexed(grids);
            if (!partsApart)
                yield return (new PlacedQuery(o.Index, o.Id, o.Frame.Position, o.Frame.Rotation, query, center, radius, BoundStretch.Of(query)), model);
            else
                foreach (var part in PlacedParts.Of(o.Index, o.Id, o.Frame.Position, o.Frame.Rotation, query, center, radius))
                    yield return (part, model);
        }
    }

    /// <summary>Every cell with a tree, as the scene asks it.</summary>
    internal static SceneCell[] CellQueries(IReadOnlyList<CellCompilation> cells, BspReachGrids? grids = null) =>
        [.. cells.Where(c => c.Bsp is not null).Select(c =>
        {
            var query = new CellOverlapQuery(c.Bsp!, c.Cell.Position.Position, c.Cell.Position.Rotation);
            return new SceneCell(c.Cell.Id, grids is null ? query : query.Indexed(grids));
        })];

    /// <summary>The placed objects a scene asks, in order, each with the picked model and the entity-space sphere around its shapes.</summary>
    internal static IEnumerable<(PlacedObject Placed, PreparedModel Model, Vector3 Center, float Radius)> Placements(IReadOnlyList<PlacedObject> placed,
        IReadOnlyDictionary<(SceneObjectKind, uint), ObjectCompilation> compiled, Func<ObjectCompilation, PreparedModel?> pick)
    {
        foreach (var p in placed)
        {
            var o = p.Object;
            if (compiled.GetValueOrDefault((o.Kind, o.Id)) is not { } c || pick(c) is not { } model || ShapeBounds.Of(model.Shapes) is var bounds && bounds.IsEmpty) continue;
            var (center, radius) = Bound(bounds);
            yield return (p, model, center, radius);
        }
    }

    /// <summary>The whole compiled scene (or all-retail) of a report.</summary>
    internal static SceneQuery Query(CompiledSceneReport report, Func<ObjectCompilation, PreparedModel?> pick, bool partsApart = false) =>
        Query(report.Placed, report.Compiled, report.Cells, pick, partsApart);

    /// <summary>The sphere around an entity-space box, padded so rounding never lets it reject a touching sphere.</summary>
    public static (Vector3 Center, float Radius) Bound(Bounds b)
    {
        var half = b.Size * 0.5f;
        return (b.Center, MathF.Sqrt(half.X * half.X + half.Y * half.Y + half.Z * half.Z) * 1.0001f + 1e-3f);
    }
}
