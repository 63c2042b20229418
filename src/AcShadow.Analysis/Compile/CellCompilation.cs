using AcShadow.Analysis.Chart;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Compile;

/// <summary>
/// One indoor cell of a compiled scene. A cell keeps its retail model, its cell structure's PhysicsBSP
/// asked as EnvCell::find_env_collisions asks it: a cell is a shell a mover stands inside, and every
/// cheaper model of the ladder is a closed solid (sphere, cylinder, box, convex hull) that would block
/// the room itself, so none can give retail's answer there and trying them would only spend time.
/// <see cref="Probes"/> (grid over the cell and stability probes on its polygons and splitting planes,
/// in the cell's frame) are where the whole scene is checked around it. <see cref="Physics"/> is null
/// when the cell structure could not be read (see the diagnostics).
/// </summary>
internal sealed record CellCompilation(
    EnvCell Cell,
    BspDump? Physics,
    CompiledBsp? Bsp,
    PartPose Frame,
    ProbeSpheres Probes,
    Bounds Bounds,
    IReadOnlyList<Diagnostic> Diagnostics)
{
    /// <summary>What a cell is modelled by: always its retail tree.</summary>
    public const string Model = "retail";
}
