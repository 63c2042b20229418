using System.Globalization;
using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Dat;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Json;

namespace AcShadow.Forging.Spec;

/// <summary>
/// Checks a <see cref="ForgeSpec"/> and converts it to dat objects. Stops at the first problem with a
/// <see cref="SpecException"/> whose one line names the item (e.g. "setups[2] (0x02000010)") and says
/// what to change: the forge exists to make exact test data, so anything ambiguous is refused.
/// </summary>
public static class SpecValidator
{
    /// <summary>How far a quaternion's length may stray from 1 (dat quaternions are unit).</summary>
    public const double UnitTolerance = 1e-3;

    /// <summary>Vertex ids are stored as int16, so a GfxObj holds at most this many vertices.</summary>
    public const int MaxVertices = short.MaxValue + 1;

    public static ValidSpec Validate(ForgeSpec spec)
    {
        if (spec.Iteration < 1) throw new SpecException($"iteration {spec.Iteration}: the dat iteration must be 1 or more");

        var gfxObjs = new List<ForgeGfxObj>();
        var gfxIds = new Dictionary<uint, int>();
        var gfxList = spec.GfxObjs ?? [];
        for (var i = 0; i < gfxList.Count; i++)
        {
            var g = gfxList[i] ?? throw new SpecException($"gfxObjs[{i}]: is null; expected an object with id, vertices, polygons");
            var id = ParseId(g.Id, $"gfxObjs[{i}]", DatObjectKind.GfxObj);
            var where = $"gfxObjs[{i}] (0x{id:X8})";
            if (gfxIds.TryGetValue(id, out var first)) throw new SpecException($"{where}: duplicate id, already declared by gfxObjs[{first}]; give each gfxObj its own id");
            gfxIds[id] = i;
            gfxObjs.Add(ValidateGfxObj(g, id, where));
        }

        var animations = new List<Animation>();
        var animationIds = new Dictionary<uint, int>();
        var animationList = spec.Animations ?? [];
        for (var i = 0; i < animationList.Count; i++)
        {
            var a = animationList[i] ?? throw new SpecException($"animations[{i}]: is null; expected an object with id, parts, frames");
            var id = ParseId(a.Id, $"animations[{i}]", DatObjectKind.Animation);
            var where = $"animations[{i}] (0x{id:X8})";
            if (animationIds.TryGetValue(id, out var first)) throw new SpecException($"{where}: duplicate id, already declared by animations[{first}]; give each animation its own id");
            animationIds[id] = i;
            animations.Add(ValidateAnimation(a, id, where));
        }

        var tables = new List<MotionTable>();
        var tableIds = new Dictionary<uint, int>();
        var tableList = spec.MotionTables ?? [];
        for (var i = 0; i < tableList.Count; i++)
        {
            var t = tableList[i] ?? throw new SpecException($"motionTables[{i}]: is null; expected an object with id, defaultStyle, styleDefaults, cycles");
            var id = ParseId(t.Id, $"motionTables[{i}]", DatObjectKind.MotionTable);
            var where = $"motionTables[{i}] (0x{id:X8})";
            if (tableIds.TryGetValue(id, out var first)) throw new SpecException($"{where}: duplicate id, already declared by motionTables[{first}]; give each motion table its own id");
            tableIds[id] = i;
            tables.Add(ValidateMotionTable(t, id, where, animationIds));
        }

        var setups = new List<Setup>();
        var setupIds = new Dictionary<uint, int>();
        var setupList = spec.Setups ?? [];
        for (var i = 0; i < setupList.Count; i++)
        {
            var s = setupList[i] ?? throw new SpecException($"setups[{i}]: is null; expected an object with id and parts");
            var id = ParseId(s.Id, $"setups[{i}]", DatObjectKind.Setup);
            var where = $"setups[{i}] (0x{id:X8})";
            if (setupIds.TryGetValue(id, out var first)) throw new SpecException($"{where}: duplicate id, already declared by setups[{first}]; give each setup its own id");
            setupIds[id] = i;
            setups.Add(ValidateSetup(s, id, where, gfxIds) with
            {
                DefaultAnimation = Declared(s.DefaultAnimation, $"{where} defaultAnimation", DatObjectKind.Animation, animationIds, "animations"),
                DefaultMotionTable = Declared(s.DefaultMotionTable, $"{where} defaultMotionTable", DatObjectKind.MotionTable, tableIds, "motionTables"),
            });
        }

        var environments = new List<ForgeEnvironment>();
        var environmentList = spec.Environments ?? [];
        for (var i = 0; i < environmentList.Count; i++)
        {
            var e = environmentList[i] ?? throw new SpecException($"environments[{i}]: is null; expected an object with id and cellStructs");
            var id = ParseId(e.Id, $"environments[{i}]", DatObjectKind.Environment);
            var where = $"environments[{i}] (0x{id:X8})";
            var first = environments.FindIndex(x => x.Id == id);
            if (first >= 0) throw new SpecException($"{where}: duplicate id, already declared by environments[{first}]; give each environment its own id");
            environments.Add(ValidateEnvironment(e, id, where));
        }

        var cells = new List<EnvCell>();
        var landblocks = new List<LandBlockInfo>();
        var landblockIds = new Dictionary<uint, int>();
        var landblockList = spec.Landblocks ?? [];
        for (var i = 0; i < landblockList.Count; i++)
        {
            var l = landblockList[i] ?? throw new SpecException($"landblocks[{i}]: is null; expected an object with id, objects, buildings");
            var id = ParseId(l.Id, $"landblocks[{i}]", DatObjectKind.LandBlockInfo);
            var where = $"landblocks[{i}] (0x{id:X8})";
            if (landblockIds.TryGetValue(id, out var first)) throw new SpecException($"{where}: duplicate id, already declared by landblocks[{first}]; give each landblock its own id");
            landblockIds[id] = i;
            var landblockCells = ValidateCells(l.Cells ?? [], id, where, environments, gfxIds, setupIds);
            if (landblockCells.Count > 0 && l.NumCells != 0 && l.NumCells != landblockCells.Count)
                throw new SpecException($"{where}: numCells {l.NumCells} but {landblockCells.Count} cell(s) are given; leave numCells out (it is the number of cells)");
            var info = ValidateLandblock(l, id, where, gfxIds, setupIds);
            landblocks.Add(landblockCells.Count > 0 ? info with { NumCells = (uint)landblockCells.Count } : info);
            cells.AddRange(landblockCells);
        }

        return new ValidSpec(spec.Iteration, gfxObjs, setups, landblocks) { MotionTables = tables, Animations = animations, Environments = environments, Cells = cells };
    }

    /// <summary>0 when absent; else an id of the kind that this spec declares.</summary>
    private static uint Declared(string? text, string at, DatObjectKind kind, Dictionary<uint, int> declared, string list)
    {
        if (text is null) return 0;
        var id = ParseId(text, at, kind);
        if (!declared.ContainsKey(id)) throw new SpecException($"{at}: 0x{id:X8} is not one of this spec's {list}; declare it");
        return id;
    }

    private static Animation ValidateAnimation(AnimationSpec a, uint id, string where)
    {
        if (a.Parts < 0) throw new SpecException($"{where}: parts {a.Parts} is negative");
        var frames = (a.Frames ?? []).Select((f, i) =>
        {
            var at = $"{where} frames[{i}]";
            var parts = f ?? throw new SpecException($"{at}: is null; expected one frame per part");
            if (parts.Count != a.Parts)
                throw new SpecException($"{at}: has {parts.Count} part frame(s) but the animation has {a.Parts} part(s); the dat stores exactly one per part, so give {a.Parts}");
            return new AnimationFrame(parts.Select((p, j) => Frame(p, $"{at}[{j}]")).ToArray(), []);
        }).ToArray();
        Frame[]? pos = null;
        if (a.PosFrames is { } posSpecs)
        {
            if (posSpecs.Count != frames.Length)
                throw new SpecException($"{where}: posFrames has {posSpecs.Count} frame(s) for {frames.Length} animation frame(s); the dat stores one per frame");
            pos = posSpecs.Select((p, i) => Frame(p, $"{where} posFrames[{i}]")).ToArray();
        }
        return new Animation(id, pos is null ? 0 : Animation.HasPosFrames, a.Parts, pos, frames);
    }

    private static MotionTable ValidateMotionTable(MotionTableSpec t, uint id, string where, Dictionary<uint, int> animationIds)
    {
        var missing = new HashSet<uint>();
        foreach (var text in t.MissingAnimations ?? [])
        {
            var anim = ParseId(text, $"{where} missingAnimations", DatObjectKind.Animation);
            if (animationIds.ContainsKey(anim)) throw new SpecException($"{where}: missingAnimations lists 0x{anim:X8}, but animations declares it; remove it from one of them");
            missing.Add(anim);
        }
        var styles = new List<KeyValuePair<uint, uint>>();
        foreach (var (d, i) in (t.StyleDefaults ?? []).Select((d, i) => (d, i)))
        {
            var at = $"{where} styleDefaults[{i}]";
            if (d is null) throw new SpecException($"{at}: is null; expected {{style, substate}}");
            var style = ParseHex(d.Style, $"{at} style");
            if (styles.Any(p => p.Key == style)) throw new SpecException($"{at}: style 0x{style:X8} is given twice; keep one");
            styles.Add(new(style, ParseHex(d.Substate, $"{at} substate")));
        }
        KeyValuePair<uint, MotionData>[] Motions(IReadOnlyList<MotionSpec>? specs, string list)
        {
            var result = new List<KeyValuePair<uint, MotionData>>();
            foreach (var (m, i) in (specs ?? []).Select((m, i) => (m, i)))
            {
                var at = $"{where} {list}[{i}]";
                if (m is null) throw new SpecException($"{at}: is null; expected {{style, motion, anims}}");
                var key = MotionCommand.Key(ParseHex(m.Style, $"{at} style"), ParseHex(m.Motion, $"{at} motion"));
                if (result.Any(p => p.Key == key)) throw new SpecException($"{at}: key 0x{key:X8} is given twice in {list}; keep one");
                result.Add(new(key, Motion(m.Bitfield, m.Anims, m.Velocity, m.Omega, at)));
            }
            return [.. result];
        }
        MotionData Motion(int bitfield, IReadOnlyList<AnimDataSpec>? anims, double[]? velocity, double[]? omega, string at)
        {
            if (bitfield is < 0 or > byte.MaxValue) throw new SpecException($"{at}: bitfield {bitfield} is not a byte (0-255)");
            var list = anims ?? [];
            if (list.Count > byte.MaxValue) throw new SpecException($"{at}: {list.Count} anims; a motion holds at most 255");
            var data = list.Select((a, i) =>
            {
                var ad = $"{at} anims[{i}]";
                if (a is null) throw new SpecException($"{ad}: is null; expected {{anim, lowFrame, highFrame, framerate}}");
                var anim = ParseId(a.Anim, $"{ad} anim", DatObjectKind.Animation);
                if (!animationIds.ContainsKey(anim) && !missing.Contains(anim))
                    throw new SpecException($"{ad}: animation 0x{anim:X8} is not in this spec (declare it, or list it in missingAnimations)");
                return new AnimData(anim, a.LowFrame, a.HighFrame, Finite(a.Framerate, $"{ad} framerate"));
            }).ToArray();
            return new MotionData((byte)bitfield, data,
                velocity is null ? null : Vector(velocity, $"{at} velocity"), omega is null ? null : Vector(omega, $"{at} omega"));
        }
        var links = new List<KeyValuePair<uint, IReadOnlyList<KeyValuePair<uint, MotionData>>>>();
        foreach (var (l, i) in (t.Links ?? []).Select((l, i) => (l, i)))
        {
            var at = $"{where} links[{i}]";
            if (l is null) throw new SpecException($"{at}: is null; expected {{style, from, to, anims}}");
            var key = MotionCommand.Key(ParseHex(l.Style, $"{at} style"), ParseHex(l.From, $"{at} from"));
            var to = ParseHex(l.To, $"{at} to");
            var index = links.FindIndex(p => p.Key == key);
            var targets = index < 0 ? [] : links[index].Value.ToList();
            if (targets.Any(p => p.Key == to)) throw new SpecException($"{at}: the link from key 0x{key:X8} to 0x{to:X8} is given twice; keep one");
            targets.Add(new(to, Motion(l.Bitfield, l.Anims, null, null, at)));
            if (index < 0) links.Add(new(key, targets)); else links[index] = new(key, targets);
        }
        return new MotionTable(id, ParseHex(t.DefaultStyle, $"{where} defaultStyle"), styles, Motions(t.Cycles, "cycles"), Motions(t.Modifiers, "modifiers"), links);
    }

    private static ForgeGfxObj ValidateGfxObj(GfxObjSpec g, uint id, string where)
    {
        var vertexSpecs = g.Vertices ?? [];
        if (vertexSpecs.Count > MaxVertices) throw new SpecException($"{where}: {vertexSpecs.Count} vertices; vertex ids are int16, so at most {MaxVertices}");
        var vertices = new Vector3[vertexSpecs.Count];
        for (var v = 0; v < vertices.Length; v++) vertices[v] = Vector(vertexSpecs[v], $"{where} vertices[{v}]");

        var polygonSpecs = g.Polygons ?? [];
        if (polygonSpecs.Count > ushort.MaxValue + 1) throw new SpecException($"{where}: {polygonSpecs.Count} polygons; polygon ids are uint16, so at most {ushort.MaxValue + 1}");
        if (!g.Physics && !g.Drawing && polygonSpecs.Count > 0)
            throw new SpecException($"{where}: has polygons but neither physics nor drawing is true; set one (physics: collision polygons + BSP, drawing: drawing polygons)");
        if (g.Physics && polygonSpecs.Count == 0)
            throw new SpecException($"{where}: physics is true but there are no polygons; a PhysicsBSP needs at least one polygon");

        var polygons = new Polygon[polygonSpecs.Count];
        for (var p = 0; p < polygons.Length; p++)
        {
            var ps = polygonSpecs[p] ?? throw new SpecException($"{where} polygons[{p}]: is null; expected {{\"vertices\": [0, 1, 2]}}");
            var ids = ps.Vertices ?? [];
            if (ids.Count < 3) throw new SpecException($"{where} polygons[{p}]: has {ids.Count} vertex id(s); a polygon needs at least 3");
            if (ids.Count > byte.MaxValue) throw new SpecException($"{where} polygons[{p}]: has {ids.Count} vertex ids; a polygon holds at most 255");
            foreach (var v in ids)
                if (v < 0 || v >= vertices.Length)
                    throw new SpecException(vertices.Length == 0
                        ? $"{where} polygons[{p}]: vertex id {v} is out of range; this gfxObj has no vertices"
                        : $"{where} polygons[{p}]: vertex id {v} is out of range; valid ids are 0-{vertices.Length - 1}");
            var sides = ParseEnum(ps.SidesType, SidesType.Landblock, $"{where} polygons[{p}] sidesType");
            var stippling = ParseEnum(ps.Stippling, Stippling.None, $"{where} polygons[{p}] stippling");
            polygons[p] = new Polygon(stippling, sides, 0, 0, ids.Select(v => (short)v).ToArray(), [], []);
        }
        return new ForgeGfxObj(id, vertices, polygons, g.Physics, g.Drawing);
    }

    private static Setup ValidateSetup(SetupSpec s, uint id, string where, Dictionary<uint, int> gfxIds)
    {
        var missing = new HashSet<uint>();
        foreach (var text in s.MissingParts ?? [])
        {
            var part = ParseId(text, $"{where} missingParts", DatObjectKind.GfxObj);
            if (gfxIds.ContainsKey(part)) throw new SpecException($"{where}: missingParts lists 0x{part:X8}, but gfxObjs declares it; remove it from one of them");
            missing.Add(part);
        }

        var partSpecs = s.Parts ?? [];
        if (partSpecs.Count == 0) throw new SpecException($"{where}: has no parts; a Setup needs at least one part id");
        var parts = new uint[partSpecs.Count];
        for (var i = 0; i < parts.Length; i++)
        {
            parts[i] = ParseId(partSpecs[i], $"{where} parts[{i}]", DatObjectKind.GfxObj);
            if (!gfxIds.ContainsKey(parts[i]) && !missing.Contains(parts[i]))
                throw new SpecException($"{where}: part 0x{parts[i]:X8} is not a gfxObj in this spec (declare it, or list it in missingParts)");
        }
        foreach (var m in missing.Where(m => !parts.Contains(m)))
            throw new SpecException($"{where}: missingParts lists 0x{m:X8}, which is not one of its parts; remove it");

        var placements = new List<PlacementFrame>();
        foreach (var (name, frameSpecs) in s.Placements ?? new Dictionary<string, IReadOnlyList<FrameSpec>?>())
        {
            if (!Placement.TryParse(name, out var key))
                throw new SpecException($"{where}: unknown placement name \"{name}\" (use a retail name such as Resting, Default, Other, or Placement0xNN)");
            if (placements.Any(p => p.Placement == key))
                throw new SpecException($"{where}: placement \"{name}\" is given twice (as {Placement.Name(key)}); keep one");
            var frames = frameSpecs ?? [];
            if (frames.Count != parts.Length)
                throw new SpecException($"{where}: placement \"{name}\" has {frames.Count} frame(s) but the setup has {parts.Length} part(s); the dat stores exactly one frame per part, so give {parts.Length}");
            placements.Add(new PlacementFrame(key, frames.Select((f, i) => Frame(f, $"{where} placement \"{name}\" frame {i}")).ToArray()));
        }
        foreach (var (name, hookSpecs) in s.Hooks ?? new Dictionary<string, IReadOnlyList<HookSpec>?>())
        {
            var index = Placement.TryParse(name, out var key) ? placements.FindIndex(p => p.Placement == key) : -1;
            if (index < 0) throw new SpecException($"{where}: hooks names placement \"{name}\", which is not one of its placements; hooks belong to a placement's frame");
            placements[index] = placements[index] with
            {
                Hooks = (hookSpecs ?? []).Select((h, i) => HookValidator.Validate(h, $"{where} hooks \"{name}\"[{i}]")).ToArray(),
            };
        }

        var cyls = (s.CylSpheres ?? []).Select((c, i) =>
        {
            var at = $"{where} cylSpheres[{i}]";
            if (c is null) throw new SpecException($"{at}: is null; expected {{origin, radius, height}}");
            return new CylSphere(Vector(c.Origin ?? [0, 0, 0], $"{at} origin"), NonNegative(c.Radius, $"{at} radius"), NonNegative(c.Height, $"{at} height"));
        }).ToArray();
        var spheres = (s.Spheres ?? []).Select((c, i) => Sphere(c, $"{where} spheres[{i}]")).ToArray();

        Vector3[] scales = [];
        if (s.DefaultScale is { } scaleSpecs)
        {
            if (scaleSpecs.Count != parts.Length)
                throw new SpecException($"{where}: defaultScale has {scaleSpecs.Count} entries but the setup has {parts.Length} part(s); the dat stores exactly one scale per part");
            scales = scaleSpecs.Select((v, i) => Vector(v, $"{where} defaultScale[{i}]")).ToArray();
        }

        var flags = SetupFlags.None;
        foreach (var name in s.Flags ?? [])
        {
            if (string.IsNullOrEmpty(name) || char.IsDigit(name[0]) || name[0] == '-' || !Enum.TryParse<SetupFlags>(name, ignoreCase: true, out var flag) || !Enum.IsDefined(flag) || flag == SetupFlags.None)
                throw new SpecException($"{where}: unknown flag \"{name}\" (use {string.Join(", ", SettableFlags)})");
            if (flag is SetupFlags.HasDefaultScale or SetupFlags.HasParent)
                throw new SpecException($"{where}: flag {flag} is derived (from defaultScale / parent indices); remove it from flags");
            flags |= flag;
        }
        if (scales.Length > 0) flags |= SetupFlags.HasDefaultScale;

        return new Setup(
            id, flags, parts, [], scales, placements, cyls, spheres,
            Finite(s.Height, $"{where} height"), NonNegative(s.Radius, $"{where} radius"),
            Finite(s.StepUpHeight, $"{where} stepUpHeight"), Finite(s.StepDownHeight, $"{where} stepDownHeight"),
            s.SortingSphere is null ? default : Sphere(s.SortingSphere, $"{where} sortingSphere"),
            s.SelectionSphere is null ? default : Sphere(s.SelectionSphere, $"{where} selectionSphere"));
    }

    private static readonly string[] SettableFlags = [nameof(SetupFlags.AllowFreeHeading), nameof(SetupFlags.HasPhysicsBsp)];

    private static LandBlockInfo ValidateLandblock(LandblockSpec l, uint id, string where, Dictionary<uint, int> gfxIds, Dictionary<uint, int> setupIds)
    {
        if (l.NumCells < 0) throw new SpecException($"{where}: numCells {l.NumCells} is negative");
        var objects = (l.Objects ?? []).Select((o, i) =>
        {
            var at = $"{where} objects[{i}]";
            if (o is null) throw new SpecException($"{at}: is null; expected {{id, origin, orientation}}");
            var model = ModelId(o.Id, at, gfxIds, setupIds);
            return new Stab(model, new Frame(Vector(o.Origin ?? [0, 0, 0], $"{at} origin"), Orientation(o.Orientation, $"{at} orientation")));
        }).ToArray();
        var buildings = (l.Buildings ?? []).Select((b, i) =>
        {
            var at = $"{where} buildings[{i}]";
            if (b is null) throw new SpecException($"{at}: is null; expected {{modelId, origin, orientation, numLeaves}}");
            var model = ModelId(b.ModelId, at, gfxIds, setupIds);
            if (b.NumLeaves < 0) throw new SpecException($"{at}: numLeaves {b.NumLeaves} is negative");
            return new BuildingInfo(model, new Frame(Vector(b.Origin ?? [0, 0, 0], $"{at} origin"), Orientation(b.Orientation, $"{at} orientation")), (uint)b.NumLeaves, []);
        }).ToArray();
        return new LandBlockInfo(id, (uint)l.NumCells, objects, buildings, []);
    }

    private static ForgeEnvironment ValidateEnvironment(EnvironmentSpec e, uint id, string where)
    {
        var structs = e.CellStructs ?? [];
        if (structs.Count == 0) throw new SpecException($"{where}: has no cellStructs; an environment needs at least one cell structure");
        return new ForgeEnvironment(id, structs.Select((c, i) =>
        {
            var at = $"{where} cellStructs[{i}]";
            if (c is null) throw new SpecException($"{at}: is null; expected {{vertices, polygons, portals}}");
            var vertexSpecs = c.Vertices ?? [];
            if (vertexSpecs.Count > MaxVertices) throw new SpecException($"{at}: {vertexSpecs.Count} vertices; vertex ids are int16, so at most {MaxVertices}");
            var vertices = vertexSpecs.Select((v, k) => Vector(v, $"{at} vertices[{k}]")).ToArray();
            var polygons = CellPolygons(c.Polygons ?? [], vertices.Length, $"{at} polygons");
            if (polygons.Length == 0) throw new SpecException($"{at}: has no polygons; a cell's PhysicsBSP needs at least one");
            var portals = CellPolygons(c.Portals ?? [], vertices.Length, $"{at} portals");
            if (polygons.Length + portals.Length > ushort.MaxValue + 1) throw new SpecException($"{at}: more than {ushort.MaxValue + 1} polygons and portals; polygon ids are uint16");
            return new ForgeCellStruct(vertices, polygons, portals);
        }).ToArray());
    }

    private static Polygon[] CellPolygons(IReadOnlyList<PolygonSpec> specs, int vertexCount, string where) => specs.Select((ps, p) =>
    {
        var at = $"{where}[{p}]";
        if (ps is null) throw new SpecException($"{at}: is null; expected {{\"vertices\": [0, 1, 2]}}");
        var ids = ps.Vertices ?? [];
        if (ids.Count < 3) throw new SpecException($"{at}: has {ids.Count} vertex id(s); a polygon needs at least 3");
        if (ids.Count > byte.MaxValue) throw new SpecException($"{at}: has {ids.Count} vertex ids; a polygon holds at most 255");
        foreach (var v in ids)
            if (v < 0 || v >= vertexCount)
                throw new SpecException($"{at}: vertex id {v} is out of range; valid ids are 0-{vertexCount - 1}");
        var sides = ParseEnum(ps.SidesType, SidesType.Landblock, $"{at} sidesType");
        var stippling = ParseEnum(ps.Stippling, Stippling.None, $"{at} stippling");
        return new Polygon(stippling, sides, 0, 0, ids.Select(v => (short)v).ToArray(), [], []);
    }).ToArray();

    /// <summary>Cell i of a landblock is 0xXXYY0100 + i; portals and visible cells name cells of the same landblock.</summary>
    private static List<EnvCell> ValidateCells(IReadOnlyList<CellSpec> specs, uint landblockId, string where, List<ForgeEnvironment> environments,
        Dictionary<uint, int> gfxIds, Dictionary<uint, int> setupIds)
    {
        const int first = 0x0100;
        if (specs.Count > 0xFFFD - first + 1) throw new SpecException($"{where}: {specs.Count} cells; cell ids run from 0x0100 to 0xFFFD");
        var cells = new List<EnvCell>();
        for (var i = 0; i < specs.Count; i++)
        {
            var id = (landblockId & 0xFFFF0000u) | (uint)(first + i);
            var at = $"{where} cells[{i}] (0x{id:X8})";
            var c = specs[i] ?? throw new SpecException($"{at}: is null; expected {{environment, cellStruct, origin, portals}}");
            var envId = ParseId(c.Environment, $"{at} environment", DatObjectKind.Environment);
            var environment = environments.Find(e => e.Id == envId)
                ?? throw new SpecException($"{at}: environment 0x{envId:X8} is not in this spec's environments; declare it");
            if (c.CellStruct < 0 || c.CellStruct >= environment.CellStructs.Count)
                throw new SpecException($"{at}: cellStruct {c.CellStruct} is out of range; environment 0x{envId:X8} has {environment.CellStructs.Count} (0-{environment.CellStructs.Count - 1})");
            var shape = environment.CellStructs[c.CellStruct];
            ushort OtherCell(string? text, string what)
            {
                if (string.Equals(text, "outside", StringComparison.OrdinalIgnoreCase)) return CellPortal.Outside;
                var other = ParseHex(text, what);
                if (other < first || other >= first + specs.Count || other == first + i)
                    throw new SpecException($"{what}: 0x{other:X4} is not another cell of this landblock (0x{first:X4}-0x{first + specs.Count - 1:X4}, not itself){(what.EndsWith("otherCell", StringComparison.Ordinal) ? " or \"outside\"" : "")}");
                return (ushort)other;
            }
            var portals = (c.Portals ?? []).Select((p, k) =>
            {
                var pat = $"{at} portals[{k}]";
                if (p is null) throw new SpecException($"{pat}: is null; expected {{polygon, otherCell, otherPortal, flags}}");
                if (p.Polygon < 0 || p.Polygon >= shape.Portals.Count)
                    throw new SpecException($"{pat}: polygon {p.Polygon} is out of range; the cell structure has {shape.Portals.Count} portal polygon(s)");
                if (p.OtherPortal is < 0 or > ushort.MaxValue) throw new SpecException($"{pat}: otherPortal {p.OtherPortal} is not a uint16");
                var flags = ParseEnum(p.Flags, PortalFlags.None, $"{pat} flags");
                return new CellPortal(flags, (ushort)(shape.Polygons.Count + p.Polygon), OtherCell(p.OtherCell, $"{pat} otherCell"), (ushort)p.OtherPortal);
            }).ToArray();
            if (portals.Length > byte.MaxValue) throw new SpecException($"{at}: {portals.Length} portals; the dat stores at most 255");
            var visible = (c.VisibleCells ?? []).Select((v, k) => OtherCell(v, $"{at} visibleCells[{k}]")).ToArray();
            var objects = (c.Objects ?? []).Select((o, k) =>
            {
                var oat = $"{at} objects[{k}]";
                if (o is null) throw new SpecException($"{oat}: is null; expected {{id, origin, orientation}}");
                return new Stab(ModelId(o.Id, oat, gfxIds, setupIds), new Frame(Vector(o.Origin ?? [0, 0, 0], $"{oat} origin"), Orientation(o.Orientation, $"{oat} orientation")));
            }).ToArray();
            var flagsOf = (c.SeenOutside ? EnvCellFlags.SeenOutside : 0) | (objects.Length > 0 ? EnvCellFlags.HasStaticObjs : 0);
            cells.Add(new EnvCell(id, flagsOf, [], (ushort)(envId & 0xFFFF), (ushort)c.CellStruct,
                new Frame(Vector(c.Origin ?? [0, 0, 0], $"{at} origin"), Orientation(c.Orientation, $"{at} orientation")),
                portals, visible, objects, 0));
        }
        return cells;
    }

    private static uint ModelId(string? text, string at, Dictionary<uint, int> gfxIds, Dictionary<uint, int> setupIds)
    {
        var id = ParseHex(text, at);
        if (!gfxIds.ContainsKey(id) && !setupIds.ContainsKey(id))
            throw new SpecException($"{at}: 0x{id:X8} is neither a gfxObj nor a setup in this spec; declare it or place another id");
        return id;
    }

    private static uint ParseId(string? text, string at, DatObjectKind kind)
    {
        var id = ParseHex(text, at);
        if (!kind.Contains(id)) throw new SpecException($"{at}: id 0x{id:X8} is outside the {kind} range {kind.RangeText()}");
        return id;
    }

    private static uint ParseHex(string? text, string at)
    {
        if (text is null) throw new SpecException($"{at}: id is missing; write it as a hex string like \"0x010044B5\"");
        // The spec insists on the 0x prefix the output formats use; the digits parse as everywhere else.
        if (!text.StartsWith("0x", StringComparison.OrdinalIgnoreCase) || !JsonIds.TryParse(text, out var id))
            throw new SpecException($"{at}: id \"{text}\" is not a hex id like \"0x010044B5\"");
        return id;
    }

    private static T ParseEnum<T>(string? text, T fallback, string at) where T : struct, Enum
    {
        if (text is null) return fallback;
        // Names only: a number would bypass the meaning the name documents.
        if (text.Length == 0 || char.IsDigit(text[0]) || text[0] == '-' || !Enum.TryParse<T>(text, ignoreCase: true, out var value))
            throw new SpecException($"{at}: \"{text}\" is not one of {string.Join(", ", Enum.GetNames<T>())}");
        return value;
    }

    private static Sphere Sphere(SphereSpec? s, string at)
    {
        if (s is null) throw new SpecException($"{at}: is null; expected {{center, radius}}");
        return new Sphere(Vector(s.Center ?? [0, 0, 0], $"{at} center"), NonNegative(s.Radius, $"{at} radius"));
    }

    private static Frame Frame(FrameSpec? f, string at)
    {
        if (f is null) throw new SpecException($"{at}: is null; expected {{origin, orientation}}");
        return new Frame(Vector(f.Origin ?? [0, 0, 0], $"{at} origin"), Orientation(f.Orientation, $"{at} orientation"));
    }

    private static Quaternion Orientation(QuaternionSpec? q, string at)
    {
        if (q is null) return Quaternion.Identity;
        var result = new Quaternion(Finite(q.X, $"{at} x"), Finite(q.Y, $"{at} y"), Finite(q.Z, $"{at} z"), Finite(q.W, $"{at} w"));
        var length = Math.Sqrt(q.W * q.W + q.X * q.X + q.Y * q.Y + q.Z * q.Z);
        if (Math.Abs(length - 1) > UnitTolerance)
            throw new SpecException($"{at}: quaternion length is {length.ToString("0.######", CultureInfo.InvariantCulture)}, not 1; normalize it");
        return result;
    }

    private static Vector3 Vector(double[]? v, string at)
    {
        if (v is null || v.Length != 3) throw new SpecException($"{at}: expected [x, y, z], got {(v is null ? "null" : $"{v.Length} number(s)")}");
        return new Vector3(Finite(v[0], $"{at} x"), Finite(v[1], $"{at} y"), Finite(v[2], $"{at} z"));
    }

    private static float NonNegative(double value, string at)
    {
        var f = Finite(value, at);
        if (f < 0) throw new SpecException($"{at}: {f.ToString(CultureInfo.InvariantCulture)} is negative; it must be 0 or more");
        return f;
    }

    private static float Finite(double value, string at)
    {
        var f = (float)value;
        if (!float.IsFinite(f))
            throw new SpecException($"{at}: {value.ToString(CultureInfo.InvariantCulture)} is not a finite float32 number");
        return f;
    }
}
