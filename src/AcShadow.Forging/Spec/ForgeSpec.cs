using System.Text.Json;
using System.Text.Json.Serialization;
using AcShadow.Fixtures.Bsp;

namespace AcShadow.Forging.Spec;

/// <summary>
/// The forge's input: what to put in the dats, as JSON (see docs/forge-spec.md). These records mirror
/// the JSON one to one and hold it unchecked; <see cref="SpecValidator"/> turns them into dat objects.
/// Vectors are [x, y, z] arrays read as doubles so that out-of-range values reach the validator
/// (which names them) instead of failing inside the JSON reader. Properties are settable, not init-only:
/// source-generated JSON (the CLI is published ahead-of-time) sets every init-only property, absent ones to
/// default, which would erase the defaults written here (Iteration = 1).
/// </summary>
public sealed record ForgeSpec
{
    public int Iteration { get; set; } = 1;
    /// <summary>Where the ids and shapes come from; free text, not written to the dat.</summary>
    public string? Provenance { get; set; }
    public string? Comment { get; set; }
    public IReadOnlyList<GfxObjSpec> GfxObjs { get; set; } = [];
    public IReadOnlyList<SetupSpec> Setups { get; set; } = [];
    public IReadOnlyList<MotionTableSpec> MotionTables { get; set; } = [];
    public IReadOnlyList<AnimationSpec> Animations { get; set; } = [];
    public IReadOnlyList<LandblockSpec> Landblocks { get; set; } = [];
    /// <summary>Environments (portal dat, 0x0D…): the cell shapes a landblock's cells use.</summary>
    public IReadOnlyList<EnvironmentSpec> Environments { get; set; } = [];
}

public sealed record GfxObjSpec
{
    public string? Id { get; set; }
    public string? Comment { get; set; }
    /// <summary>[[x, y, z], ...]; a vertex's id is its index.</summary>
    public IReadOnlyList<double[]?> Vertices { get; set; } = [];
    public IReadOnlyList<PolygonSpec> Polygons { get; set; } = [];
    /// <summary>The polygons become PhysicsPolygons and get a PhysicsBSP.</summary>
    public bool Physics { get; set; }
    /// <summary>The polygons are also written as drawing polygons.</summary>
    public bool Drawing { get; set; }
}

public sealed record PolygonSpec
{
    public IReadOnlyList<int> Vertices { get; set; } = [];
    /// <summary>A <see cref="Core.Dat.Objects.SidesType"/> name; default "Landblock" (0, single-sided).</summary>
    public string? SidesType { get; set; }
    /// <summary>A <see cref="Core.Dat.Objects.Stippling"/> flag list like "NoPos, NoNeg"; default "None".</summary>
    public string? Stippling { get; set; }
}

public sealed record SetupSpec
{
    public string? Id { get; set; }
    public string? Comment { get; set; }
    public IReadOnlyList<string> Parts { get; set; } = [];
    /// <summary>Placement name ("Resting", "Default", "Other", "Placement0xNN") → one frame per part.</summary>
    public IReadOnlyDictionary<string, IReadOnlyList<FrameSpec>?> Placements { get; set; } = new Dictionary<string, IReadOnlyList<FrameSpec>?>();
    public IReadOnlyList<CylSphereSpec> CylSpheres { get; set; } = [];
    public IReadOnlyList<SphereSpec> Spheres { get; set; } = [];
    public double Radius { get; set; }
    public double Height { get; set; }
    public double StepUpHeight { get; set; }
    public double StepDownHeight { get; set; }
    public SphereSpec? SortingSphere { get; set; }
    public SphereSpec? SelectionSphere { get; set; }
    /// <summary>[[x, y, z], ...], one per part, or absent.</summary>
    public IReadOnlyList<double[]?>? DefaultScale { get; set; }
    /// <summary><see cref="Core.Dat.Objects.SetupFlags"/> names; HasDefaultScale and HasParent are derived.</summary>
    public IReadOnlyList<string> Flags { get; set; } = [];
    /// <summary>Part ids deliberately left out of the dat.</summary>
    public IReadOnlyList<string> MissingParts { get; set; } = [];
    /// <summary>An animation of this spec the object plays when no motion table state replaces it.</summary>
    public string? DefaultAnimation { get; set; }
    /// <summary>A motion table of this spec the object starts with.</summary>
    public string? DefaultMotionTable { get; set; }
    /// <summary>Placement name (one of <see cref="Placements"/>) → the animation hooks its frame carries.</summary>
    public IReadOnlyDictionary<string, IReadOnlyList<HookSpec>?> Hooks { get; set; } = new Dictionary<string, IReadOnlyList<HookSpec>?>();
}

/// <summary>A MotionTable: its default style, each style's default substate, and what each (style, motion) plays.</summary>
public sealed record MotionTableSpec
{
    public string? Id { get; set; }
    public string? Comment { get; set; }
    /// <summary>A style (stance) command, e.g. "0x8000003D" (NonCombat).</summary>
    public string? DefaultStyle { get; set; }
    public IReadOnlyList<StyleDefaultSpec> StyleDefaults { get; set; } = [];
    public IReadOnlyList<MotionSpec> Cycles { get; set; } = [];
    public IReadOnlyList<MotionSpec> Modifiers { get; set; } = [];
    public IReadOnlyList<LinkSpec> Links { get; set; } = [];
    /// <summary>Animation ids this table names that are deliberately left out of the dat.</summary>
    public IReadOnlyList<string> MissingAnimations { get; set; } = [];
}

public sealed record StyleDefaultSpec
{
    public string? Style { get; set; }
    public string? Substate { get; set; }
}

/// <summary>One motion: stored under the key (style &lt;&lt; 16) | (motion &amp; 0xFFFFFF).</summary>
public sealed record MotionSpec
{
    public string? Style { get; set; }
    public string? Motion { get; set; }
    public int Bitfield { get; set; }
    public IReadOnlyList<AnimDataSpec> Anims { get; set; } = [];
    public double[]? Velocity { get; set; }
    public double[]? Omega { get; set; }
}

/// <summary>A transition: from (style, substate) to a motion, stored under the key of (style, from) and the full to-motion.</summary>
public sealed record LinkSpec
{
    public string? Style { get; set; }
    public string? From { get; set; }
    public string? To { get; set; }
    public int Bitfield { get; set; }
    public IReadOnlyList<AnimDataSpec> Anims { get; set; } = [];
}

public sealed record AnimDataSpec
{
    public string? Anim { get; set; }
    public int LowFrame { get; set; }
    /// <summary>−1: to the last frame.</summary>
    public int HighFrame { get; set; } = -1;
    public double Framerate { get; set; } = 30;
}

/// <summary>An Animation: per frame, one frame per animated part (<see cref="Parts"/> of them).</summary>
public sealed record AnimationSpec
{
    public string? Id { get; set; }
    public string? Comment { get; set; }
    public int Parts { get; set; }
    public IReadOnlyList<IReadOnlyList<FrameSpec>?> Frames { get; set; } = [];
    /// <summary>Root motion, one frame per animation frame, or absent.</summary>
    public IReadOnlyList<FrameSpec>? PosFrames { get; set; }
}

/// <summary>One animation hook: its type, direction and payload fields by name (docs/formats.md lists each type's fields).</summary>
public sealed record HookSpec
{
    /// <summary>An <see cref="Core.Dat.Objects.AnimationHookType"/> name.</summary>
    public string? Type { get; set; }
    /// <summary>"Forward" (1, the default), "Backward" (-1) or "Both" (0).</summary>
    public string? Direction { get; set; }
    /// <summary>Field name → value: a number, true/false, a hex id string, [x, y, z], or a frame {origin, orientation}.</summary>
    public IReadOnlyDictionary<string, JsonElement> Fields { get; set; } = new Dictionary<string, JsonElement>();
}

public sealed record FrameSpec
{
    public double[]? Origin { get; set; }
    public QuaternionSpec? Orientation { get; set; }
}

/// <summary>Stored W, X, Y, Z in the dat; written here by name so the order cannot be confused.</summary>
public sealed record QuaternionSpec(double W, double X, double Y, double Z);

public sealed record CylSphereSpec
{
    public double[]? Origin { get; set; }
    public double Radius { get; set; }
    public double Height { get; set; }
}

public sealed record SphereSpec
{
    public double[]? Center { get; set; }
    public double Radius { get; set; }
}

public sealed record LandblockSpec
{
    public string? Id { get; set; }
    public string? Comment { get; set; }
    public int NumCells { get; set; }
    public IReadOnlyList<StabSpec> Objects { get; set; } = [];
    public IReadOnlyList<BuildingSpec> Buildings { get; set; } = [];
    /// <summary>Indoor cells (EnvCells), numbered 0xXXYY0100 upwards in this order.</summary>
    public IReadOnlyList<CellSpec> Cells { get; set; } = [];
}

/// <summary>An Environment: its cell structures, indexed from 0 in this order.</summary>
public sealed record EnvironmentSpec
{
    public string? Id { get; set; }
    public string? Comment { get; set; }
    public IReadOnlyList<CellStructSpec> CellStructs { get; set; } = [];
}

/// <summary>
/// One cell shape in cell-local metres: <see cref="Polygons"/> are its walls, floors and ceilings
/// (physics and drawing polygons, ids 0..n−1), <see cref="Portals"/> its openings (drawing polygons only,
/// ids n, n+1, …, and the portal list).
/// </summary>
public sealed record CellStructSpec
{
    public string? Comment { get; set; }
    public IReadOnlyList<double[]?> Vertices { get; set; } = [];
    public IReadOnlyList<PolygonSpec> Polygons { get; set; } = [];
    public IReadOnlyList<PolygonSpec> Portals { get; set; } = [];
}

/// <summary>An EnvCell: which shape, where (landblock-relative), its portals, the cells it sees and the objects inside it.</summary>
public sealed record CellSpec
{
    public string? Comment { get; set; }
    public string? Environment { get; set; }
    public int CellStruct { get; set; }
    public double[]? Origin { get; set; }
    public QuaternionSpec? Orientation { get; set; }
    public bool SeenOutside { get; set; }
    public IReadOnlyList<CellPortalSpec> Portals { get; set; } = [];
    /// <summary>Other cells of the landblock, as "0x0101".</summary>
    public IReadOnlyList<string> VisibleCells { get; set; } = [];
    public IReadOnlyList<StabSpec> Objects { get; set; } = [];
}

public sealed record CellPortalSpec
{
    /// <summary>Index into the cell structure's portals.</summary>
    public int Polygon { get; set; }
    /// <summary>"0x0101" (a cell of this landblock) or "outside".</summary>
    public string? OtherCell { get; set; }
    public int OtherPortal { get; set; }
    /// <summary><see cref="Core.Dat.Objects.PortalFlags"/> names, comma-separated; default "None".</summary>
    public string? Flags { get; set; }
}

public sealed record StabSpec
{
    public string? Id { get; set; }
    public double[]? Origin { get; set; }
    public QuaternionSpec? Orientation { get; set; }
}

public sealed record BuildingSpec
{
    public string? ModelId { get; set; }
    public double[]? Origin { get; set; }
    public QuaternionSpec? Orientation { get; set; }
    public int NumLeaves { get; set; }
}

/// <summary>One bad spec item: the message is a single line naming the item and the fix.</summary>
public sealed class SpecException(string message) : Exception(message);
