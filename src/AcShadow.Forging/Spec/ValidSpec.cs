using System.Numerics;
using AcShadow.Core.Dat.Objects;

namespace AcShadow.Forging.Spec;

/// <summary>A spec that passed <see cref="SpecValidator"/>: ids parsed, numbers float32 and finite.</summary>
public sealed record ValidSpec(
    int Iteration,
    IReadOnlyList<ForgeGfxObj> GfxObjs,
    IReadOnlyList<Setup> Setups,
    IReadOnlyList<LandBlockInfo> Landblocks)
{
    public IReadOnlyList<MotionTable> MotionTables { get; init; } = [];
    public IReadOnlyList<Animation> Animations { get; init; } = [];

    /// <summary>Environments before their BSPs are built.</summary>
    public IReadOnlyList<ForgeEnvironment> Environments { get; init; } = [];

    /// <summary>Every landblock's EnvCells, in id order.</summary>
    public IReadOnlyList<EnvCell> Cells { get; init; } = [];
}

/// <summary>An Environment before its cell structures' BSPs are built.</summary>
public sealed record ForgeEnvironment(uint Id, IReadOnlyList<ForgeCellStruct> CellStructs);

/// <summary>A cell shape: polygons 0..n−1 (physics and drawing) and portal polygons n.. (drawing only).</summary>
public sealed record ForgeCellStruct(IReadOnlyList<Vector3> Vertices, IReadOnlyList<Polygon> Polygons, IReadOnlyList<Polygon> Portals);

/// <summary>
/// A GfxObj before its BSP is built. Polygon ids are the polygons' indices in the spec, so leaves,
/// physics polygons and drawing polygons all name the same polygon the same way.
/// </summary>
public sealed record ForgeGfxObj(uint Id, IReadOnlyList<Vector3> Vertices, IReadOnlyList<Polygon> Polygons, bool Physics, bool Drawing);
