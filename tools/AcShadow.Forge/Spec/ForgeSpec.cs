using System.Text.Json.Serialization;

namespace AcShadow.Forge.Spec;

/// <summary>
/// The forge's input: what to put in the dats, as JSON (see docs/forge-spec.md). These records mirror
/// the JSON one to one and hold it unchecked; <see cref="SpecValidator"/> turns them into dat objects.
/// Vectors are [x, y, z] arrays read as doubles so that out-of-range values reach the validator
/// (which names them) instead of failing inside the JSON reader.
/// </summary>
public sealed record ForgeSpec
{
    public int Iteration { get; init; } = 1;
    /// <summary>Where the ids and shapes come from; free text, not written to the dat.</summary>
    public string? Provenance { get; init; }
    public string? Comment { get; init; }
    public IReadOnlyList<GfxObjSpec> GfxObjs { get; init; } = [];
    public IReadOnlyList<SetupSpec> Setups { get; init; } = [];
    public IReadOnlyList<LandblockSpec> Landblocks { get; init; } = [];
}

public sealed record GfxObjSpec
{
    public string? Id { get; init; }
    public string? Comment { get; init; }
    /// <summary>[[x, y, z], ...]; a vertex's id is its index.</summary>
    public IReadOnlyList<double[]?> Vertices { get; init; } = [];
    public IReadOnlyList<PolygonSpec> Polygons { get; init; } = [];
    /// <summary>The polygons become PhysicsPolygons and get a PhysicsBSP.</summary>
    public bool Physics { get; init; }
    /// <summary>The polygons are also written as drawing polygons.</summary>
    public bool Drawing { get; init; }
}

public sealed record PolygonSpec
{
    public IReadOnlyList<int> Vertices { get; init; } = [];
    /// <summary>A <see cref="Core.Dat.Objects.SidesType"/> name; default "Landblock" (0, single-sided).</summary>
    public string? SidesType { get; init; }
    /// <summary>A <see cref="Core.Dat.Objects.Stippling"/> flag list like "NoPos, NoNeg"; default "None".</summary>
    public string? Stippling { get; init; }
}

public sealed record SetupSpec
{
    public string? Id { get; init; }
    public string? Comment { get; init; }
    public IReadOnlyList<string> Parts { get; init; } = [];
    /// <summary>Placement name ("Resting", "Default", "Other", "Placement0xNN") → one frame per part.</summary>
    public IReadOnlyDictionary<string, IReadOnlyList<FrameSpec>?> Placements { get; init; } = new Dictionary<string, IReadOnlyList<FrameSpec>?>();
    public IReadOnlyList<CylSphereSpec> CylSpheres { get; init; } = [];
    public IReadOnlyList<SphereSpec> Spheres { get; init; } = [];
    public double Radius { get; init; }
    public double Height { get; init; }
    public double StepUpHeight { get; init; }
    public double StepDownHeight { get; init; }
    public SphereSpec? SortingSphere { get; init; }
    public SphereSpec? SelectionSphere { get; init; }
    /// <summary>[[x, y, z], ...], one per part, or absent.</summary>
    public IReadOnlyList<double[]?>? DefaultScale { get; init; }
    /// <summary><see cref="Core.Dat.Objects.SetupFlags"/> names; HasDefaultScale and HasParent are derived.</summary>
    public IReadOnlyList<string> Flags { get; init; } = [];
    /// <summary>Part ids deliberately left out of the dat.</summary>
    public IReadOnlyList<string> MissingParts { get; init; } = [];
}

public sealed record FrameSpec
{
    public double[]? Origin { get; init; }
    public QuaternionSpec? Orientation { get; init; }
}

/// <summary>Stored W, X, Y, Z in the dat; written here by name so the order cannot be confused.</summary>
public sealed record QuaternionSpec(double W, double X, double Y, double Z);

public sealed record CylSphereSpec
{
    public double[]? Origin { get; init; }
    public double Radius { get; init; }
    public double Height { get; init; }
}

public sealed record SphereSpec
{
    public double[]? Center { get; init; }
    public double Radius { get; init; }
}

public sealed record LandblockSpec
{
    public string? Id { get; init; }
    public string? Comment { get; init; }
    public int NumCells { get; init; }
    public IReadOnlyList<StabSpec> Objects { get; init; } = [];
    public IReadOnlyList<BuildingSpec> Buildings { get; init; } = [];
}

public sealed record StabSpec
{
    public string? Id { get; init; }
    public double[]? Origin { get; init; }
    public QuaternionSpec? Orientation { get; init; }
}

public sealed record BuildingSpec
{
    public string? ModelId { get; init; }
    public double[]? Origin { get; init; }
    public QuaternionSpec? Orientation { get; init; }
    public int NumLeaves { get; init; }
}

/// <summary>One bad spec item: the message is a single line naming the item and the fix.</summary>
public sealed class SpecException(string message) : Exception(message);
