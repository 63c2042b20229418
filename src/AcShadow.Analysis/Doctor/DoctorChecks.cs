using System.Globalization;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;

namespace AcShadow.Analysis.Doctor;

/// <summary>Turns what the passes counted into the report's checks, in a fixed order, each with its verdict.</summary>
internal static class DoctorChecks
{
    public const string Reading = "reading", Retail = "retail", Tool = "tool";

    public static IReadOnlyList<DoctorCheck> From(DoctorTallies t, DatArchive portal, DatArchive? cell, ExportSelfCheck.Outcome? export, long? peakBytes) =>
    [
        Decode(t, cell is not null),
        BytesUsed(t),
        Hooks(t),
        Directory(portal, cell),
        Iteration(portal, cell),
        Header(portal, cell),
        Planes(t),
        BothChildren(t),
        SolidLeaves(t),
        LeafPolygons(t),
        Spheres(t),
        PhysicsBspFlag(t),
        Placements(t),
        DefaultScale(t),
        PartsPosed(t),
        MotionPose(t),
        Determinism(export, peakBytes),
    ];

    private static KeyValuePair<string, long> C(string name, long value) => new(name, value);

    private static string N(long n) => n.ToString(CultureInfo.InvariantCulture);

    private static DoctorCheck Decode(DoctorTallies t, bool hasCell)
    {
        var objects = t.GfxObjs.Value + t.Setups.Value + t.LandBlockInfos.Value;
        var failed = t.DecodeFailed.Objects;
        List<KeyValuePair<string, long>> counts =
        [
            C("gfxObjs", t.GfxObjs.Value), C("gfxObjsRead", t.GfxObjsDecoded.Value),
            C("setups", t.Setups.Value), C("setupsRead", t.SetupsDecoded.Value),
        ];
        if (hasCell) counts.AddRange([C("landBlockInfos", t.LandBlockInfos.Value), C("landBlockInfosRead", t.LandBlockInfosDecoded.Value)]);
        counts.Add(C("failed", failed));
        KeyValuePair<string, long>[] reasons;
        lock (t.FailureReasons) reasons = [.. t.FailureReasons.OrderBy(r => r.Key, StringComparer.Ordinal).Select(r => C(r.Key, r.Value.Value))];
        return new DoctorCheck("reading.decode", Reading,
            "every GfxObj and Setup (and, with a cell dat, every LandBlockInfo) decodes with acshadow's layouts",
            DoctorVerdicts.Of(objects, failed), $"{N(objects - failed)}/{N(objects)} objects read",
            counts, t.DecodeFailed.Examples, "object") { Histogram = reasons, HistogramName = "failuresByReason" };
    }

    private static DoctorCheck BytesUsed(DoctorTallies t) => new("reading.bytes-used", Reading,
        "decoding an object uses every one of its bytes (a misread field leaves bytes over); GfxObjs with a drawing part are not counted: their drawing part is not read",
        DoctorVerdicts.Of(t.BytesChecked.Value, t.BytesLeft.Objects),
        $"{N(t.BytesChecked.Value - t.BytesLeft.Objects)}/{N(t.BytesChecked.Value)} objects used exactly",
        [C("checked", t.BytesChecked.Value), C("bytesLeftOver", t.BytesLeft.Objects), C("notCheckable", t.BytesNotCheckable.Value)],
        t.BytesLeft.Examples, "object");

    private static DoctorCheck Hooks(DoctorTallies t)
    {
        var byType = new List<KeyValuePair<string, long>>();
        for (var i = 0; i < t.HookTypes.Length; i++)
            if (t.HookTypes[i].Value > 0) byType.Add(C(((AnimationHookType)i).ToString(), t.HookTypes[i].Value));
        var unknown = t.UnknownHookType.Objects;
        return new DoctorCheck("reading.hooks", Reading,
            "every animation hook type in the Setups' placement frames has a known layout (an unknown one loses the Setup); animations are not read",
            DoctorVerdicts.Of(t.SetupsChecked.Value + unknown, unknown),
            $"{N(t.PlacementHooks.Value)} hook(s) of {N(byType.Count)} type(s) read, {N(unknown)} setup(s) with an unknown type",
            [C("hooks", t.PlacementHooks.Value), C("types", byType.Count), C("setupsWithUnknownType", unknown)],
            t.UnknownHookType.Examples, "setup") { Histogram = byType, HistogramName = "hooksByType" };
    }

    private static DoctorCheck Directory(DatArchive portal, DatArchive? cell)
    {
        var archives = cell is null ? new[] { portal } : [portal, cell];
        var shapes = archives.Select(a => a.DirectoryShape).ToArray();
        var fill = shapes.Aggregate(BranchFill.None, (f, s) => f.Combine(s.Fill));
        var notRetail = shapes.Count(s => s.Fill is not (BranchFill.Zero or BranchFill.None));
        List<KeyValuePair<string, long>> counts = [C("nodes", shapes[0].Nodes), C("levels", shapes[0].Levels)];
        if (cell is not null) counts.AddRange([C("cellNodes", shapes[1].Nodes), C("cellLevels", shapes[1].Levels)]);
        counts.Add(C("filesNotRetailStyle", notRetail));
        return new DoctorCheck("reading.directory", Reading,
            "the directory B-tree is retail's style: unused branch slots hold 0 (DatReaderWriter writes 0xCDCDCDCD, which acshadow also reads)",
            DoctorVerdicts.Of(shapes.Sum(s => s.Nodes), notRetail), $"branch fill {fill.Describe()}, {N(shapes.Sum(s => s.Nodes))} node(s)",
            counts, [], "object") { Histogram = [.. Enum.GetValues<BranchFill>().Select(f => C(f.ToString(), shapes.Count(s => s.Fill == f)))], HistogramName = "filesByFill" };
    }

    private static DoctorCheck Iteration(DatArchive portal, DatArchive? cell)
    {
        var archives = cell is null ? new[] { portal } : [portal, cell];
        var found = archives.Select(DatIteration.Of).ToArray();
        var missing = found.Count(f => f.Source != DatIterationSource.Record);
        List<KeyValuePair<string, long>> counts = [C("iteration", found[0].Iteration), C("maxEntryIteration", portal.MaxIteration)];
        if (cell is not null) counts.AddRange([C("cellIteration", found[1].Iteration), C("cellMaxEntryIteration", cell.MaxIteration)]);
        counts.Add(C("filesWithoutReadableRecord", missing));
        return new DoctorCheck("reading.iteration", Reading,
            $"each dat carries a readable Iteration record (0x{IterationRecord.Id:X8}), as real dats do",
            DoctorVerdicts.Of(archives.Length, missing), $"iteration {N(found[0].Iteration)} from the {found[0].Source.Describe()}",
            counts, [], "object") { Histogram = [.. Enum.GetValues<DatIterationSource>().Select(f => C(f.Name(), found.Count(x => x.Source == f)))], HistogramName = "filesByIterationSource" };
    }

    private static DoctorCheck Header(DatArchive portal, DatArchive? cell)
    {
        var archives = cell is null ? new[] { portal } : [portal, cell];
        var wrong = archives.Count(a => a.Header.FileSize != a.Length);
        return new DoctorCheck("reading.header", Reading,
            "the header's file size is the file's length",
            DoctorVerdicts.Of(archives.Length, wrong),
            $"block size {N(portal.Header.BlockSize)}, {N(portal.Length)} bytes{(wrong > 0 ? ", header says otherwise" : "")}",
            [C("blockSize", portal.Header.BlockSize), C("fileLength", portal.Length), C("headerFileSize", portal.Header.FileSize), C("filesDiffering", wrong)],
            [], "object");
    }

    private static DoctorCheck Planes(DoctorTallies t)
    {
        var nodes = t.InternalNodes.Value;
        var missed = t.PlaneNotReproduced.Occurrences;
        List<KeyValuePair<string, long>> histogram = [.. t.PlaneUlps.Buckets(), C("negated", t.PlanesNegated.Value), C("noPolygonInPlane", t.PlanesWithoutPolygon.Value)];
        return new DoctorCheck("bsp.planes", Retail,
            "every internal PhysicsBSP node's plane is, bit for bit, CPolygon::make_plane of a polygon of its GfxObj lying in it",
            DoctorVerdicts.Of(nodes, missed), $"{N(nodes - missed)}/{N(nodes)} planes reproduced bit for bit",
            [C("internalNodes", nodes), C("reproduced", t.PlanesReproduced.Value), C("notReproduced", missed), C("gfxObjs", t.PlaneNotReproduced.Objects)],
            t.PlaneNotReproduced.Examples, "gfxobj") { Histogram = histogram, HistogramName = "ulpDistanceOfTheRest" };
    }

    private static DoctorCheck BothChildren(DoctorTallies t)
    {
        var nodes = t.InternalNodes.Value;
        var one = t.OneChildNode.Occurrences;
        return new DoctorCheck("bsp.both-children", Retail,
            "every internal PhysicsBSP node has both children (BSPNODE::sphere_intersects_solid follows both unchecked)",
            DoctorVerdicts.Of(nodes, one), $"{N(one)} one-child node(s) of {N(nodes)}",
            [C("internalNodes", nodes), C("oneChild", one), C("gfxObjs", t.OneChildNode.Objects)],
            t.OneChildNode.Examples, "gfxobj");
    }

    private static DoctorCheck SolidLeaves(DoctorTallies t)
    {
        var bad = t.SolidLeafEmpty.Occurrences + t.SolidFlagOddValue.Occurrences;
        return new DoctorCheck("bsp.solid-leaves", Retail,
            "a solid PhysicsBSP leaf holds polygons (an empty side is a leaf with no polygons, not solid); the solid flag is 0 or 1",
            DoctorVerdicts.Of(t.Leaves.Value, bad), $"{N(bad)} odd leaf/leaves of {N(t.Leaves.Value)}",
            [
                C("leaves", t.Leaves.Value), C("solidWithPolygons", t.SolidWithPolygons.Value), C("solidEmpty", t.SolidEmpty.Value),
                C("openWithPolygons", t.OpenWithPolygons.Value), C("openEmpty", t.OpenEmpty.Value), C("solidFlagNeither0Nor1", t.SolidFlagOddValue.Occurrences),
            ],
            Merge(t.SolidLeafEmpty, t.SolidFlagOddValue), "gfxobj");
    }

    private static DoctorCheck LeafPolygons(DoctorTallies t)
    {
        var bad = t.LeafPolygonMissing.Occurrences + t.PolygonVertexMissing.Occurrences;
        return new DoctorCheck("bsp.leaf-polygons", Retail,
            "every polygon id a PhysicsBSP leaf holds is one of the GfxObj's physics polygons, and every physics polygon's vertices exist",
            DoctorVerdicts.Of(t.LeafPolygonRefs.Value, bad), $"{N(t.LeafPolygonMissing.Occurrences)} missing of {N(t.LeafPolygonRefs.Value)} leaf polygon id(s)",
            [C("leafPolygonIds", t.LeafPolygonRefs.Value), C("missingPolygons", t.LeafPolygonMissing.Occurrences), C("polygonsWithMissingVertices", t.PolygonVertexMissing.Occurrences)],
            Merge(t.LeafPolygonMissing, t.PolygonVertexMissing), "gfxobj");
    }

    private static DoctorCheck Spheres(DoctorTallies t)
    {
        var small = t.SphereTooSmall.Occurrences;
        return new DoctorCheck("bsp.bounding-spheres", Retail,
            $"every PhysicsBSP node's bounding sphere holds its subtree's polygons, to within {BspInspection.SphereSlackMetres.ToString(CultureInfo.InvariantCulture)} m (half of retail's EPSILON)",
            DoctorVerdicts.Of(t.SpheresChecked.Value, small),
            $"{N(t.SpheresChecked.Value - small)}/{N(t.SpheresChecked.Value)} spheres hold their polygons, worst excess {N(t.MaxExcessNanometres)} nm",
            [
                C("spheres", t.SpheresChecked.Value), C("containing", t.SpheresExactlyContaining.Value), C("withinSlack", t.SpheresWithinSlack.Value),
                C("tooSmall", small), C("maxExcessNanometres", t.MaxExcessNanometres),
            ],
            t.SphereTooSmall.Examples, "gfxobj");
    }

    private static DoctorCheck MotionPose(DoctorTallies t)
    {
        var fellBack = t.PoseFellBack.Objects;
        var differs = t.PoseDiffers.Objects;
        return new DoctorCheck("setup.motion-pose", Retail,
            "a Setup with a DefaultAnimation or a motion table is posed by the animation frame current right after creation (CPartArray::InitDefaults, CPhysicsObj::InitDefaults, CMotionTable::SetDefaultState); none falls back to its placement pose for a missing table, state, animation or frame",
            DoctorVerdicts.Of(t.WithMotion.Value, fellBack),
            $"{N(t.MotionPosed.Value)}/{N(t.WithMotion.Value)} setups take their motion pose, {N(differs)} of them move a part from the placement pose",
            [C("setupsWithMotion", t.WithMotion.Value), C("motionPosed", t.MotionPosed.Value), C("fellBackToPlacement", fellBack), C("poseDiffersFromPlacement", differs)],
            t.PoseFellBack.Examples, "setup");
    }

    private static DoctorCheck PhysicsBspFlag(DoctorTallies t)
    {
        var bad = t.FlagSetPartsNone.Objects + t.FlagClearPartsBsp.Objects;
        return new DoctorCheck("setup.physics-bsp-flag", Retail,
            "a Setup's HasPhysicsBSP flag (0x8) agrees with its parts (CPartArray::CacheHasPhysicsBSP: any part's GfxObj has a PhysicsBSP)",
            DoctorVerdicts.Of(t.SetupsChecked.Value, bad), $"{N(bad)} of {N(t.SetupsChecked.Value)} setups disagree",
            [
                C("setups", t.SetupsChecked.Value), C("flagWithoutBspParts", t.FlagSetPartsNone.Objects), C("bspPartsWithoutFlag", t.FlagClearPartsBsp.Objects),
                C("setupsWithMissingParts", t.PartMissing.Objects), C("missingParts", t.PartMissing.Occurrences),
            ],
            Merge(t.FlagSetPartsNone, t.FlagClearPartsBsp), "setup");
    }

    private static DoctorCheck Placements(DoctorTallies t)
    {
        var bad = t.NeitherRestingNorDefault.Objects;
        return new DoctorCheck("setup.placements", Retail,
            "a Setup with placement frames has Resting or Default (CPartArray::SetPlacementFrame takes no other; the union design would take the first)",
            DoctorVerdicts.Of(t.SetupsChecked.Value, bad),
            $"Resting {N(t.WithResting.Value)}, Default {N(t.WithDefault.Value)}, other {N(t.WithOther.Value)}, none {N(t.WithNoPlacement.Value)}",
            [
                C("setups", t.SetupsChecked.Value), C("withResting", t.WithResting.Value), C("withDefault", t.WithDefault.Value),
                C("withOther", t.WithOther.Value), C("withNone", t.WithNoPlacement.Value), C("onlyOther", bad),
            ],
            t.NeitherRestingNorDefault.Examples, "setup");
    }

    private static DoctorCheck DefaultScale(DoctorTallies t)
    {
        var bad = t.NonUniformBspScale.Objects;
        return new DoctorCheck("setup.default-scale", Retail,
            "where a Setup has DefaultScale, its BSP parts' scales are uniform (BSP collision uses only Z: CPhysicsPart::find_obj_collisions)",
            DoctorVerdicts.Of(t.WithDefaultScale.Value, bad), $"{N(t.WithDefaultScale.Value)} setup(s) with DefaultScale, {N(bad)} non-uniform on a BSP part",
            [C("setups", t.SetupsChecked.Value), C("withDefaultScale", t.WithDefaultScale.Value), C("nonUniformOnBspPart", bad), C("nonUniformBspParts", t.NonUniformBspScale.Occurrences)],
            t.NonUniformBspScale.Examples, "setup");
    }

    private static DoctorCheck PartsPosed(DoctorTallies t)
    {
        var bad = t.PartsWithoutPose.Occurrences;
        return new DoctorCheck("setup.parts-posed", Retail,
            "retail gives every part a pose (Resting or Default has a frame per part; a one-part object without one sits at the origin)",
            DoctorVerdicts.Of(t.PartsTotal.Value, bad), $"{N(bad)} of {N(t.PartsTotal.Value)} parts without a pose",
            [C("parts", t.PartsTotal.Value), C("partsWithoutPose", bad), C("setups", t.PartsWithoutPose.Objects)],
            t.PartsWithoutPose.Examples, "setup");
    }

    private static DoctorCheck Determinism(ExportSelfCheck.Outcome? export, long? peakBytes)
    {
        const string claim = "`batch --all` run twice on this machine gives the same bytes (index.json, which holds every file's SHA-256)";
        if (export is null)
            return new DoctorCheck("tool.determinism", Tool, claim, DoctorVerdict.NotChecked, "not run", [], [], "object");
        List<KeyValuePair<string, double>> measured = [new("firstRunSeconds", Round(export.FirstSeconds)), new("secondRunSeconds", Round(export.SecondSeconds))];
        if (peakBytes is { } peak) measured.Add(new("peakMemoryMiB", Round(peak / (1024.0 * 1024.0))));
        return new DoctorCheck("tool.determinism", Tool, claim,
            export.Identical ? DoctorVerdict.Holds : DoctorVerdict.Differs,
            string.Create(CultureInfo.InvariantCulture, $"{(export.Identical ? "same" : "different")} bytes twice, {export.Files} files, {export.FirstSeconds:0.00} s a run"),
            [C("setups", export.Setups), C("files", export.Files), C("skipped", export.Skipped)], [], "object")
        {
            Measured = measured,
            Digests = [new("firstRun", export.FirstDigest), new("secondRun", export.SecondDigest)],
        };
    }

    private static double Round(double x) => Math.Round(x, 3, MidpointRounding.AwayFromZero);

    private static IReadOnlyList<uint> Merge(params Finding[] findings) =>
        [.. findings.SelectMany(f => f.Examples).Distinct().Order().Take(Finding.MaxExamples)];
}
