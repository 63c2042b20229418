using System.Numerics;
using AcShadow.Core.Dat.Objects;

namespace AcShadow.Forge.Spec;

/// <summary>A spec that passed <see cref="SpecValidator"/>: ids parsed, numbers float32 and finite.</summary>
public sealed record ValidSpec(
    int Iteration,
    IReadOnlyList<ForgeGfxObj> GfxObjs,
    IReadOnlyList<Setup> Setups,
    IReadOnlyList<LandBlockInfo> Landblocks)
{
    public IReadOnlyList<MotionTable> MotionTables { get; init; } = [];
    public IReadOnlyList<Animation> Animations { get; init; } = [];
}

/// <summary>
/// A GfxObj before its BSP is built. Polygon ids are the polygons' indices in the spec, so leaves,
/// physics polygons and drawing polygons all name the same polygon the same way.
/// </summary>
public sealed record ForgeGfxObj(uint Id, IReadOnlyList<Vector3> Vertices, IReadOnlyList<Polygon> Polygons, bool Physics, bool Drawing);
