using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Poses;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Movement;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Movement;

/// <summary>
/// The object a suite walks against, as acshadow exports it: the retail-policy shadow shapes in the chosen
/// door state (ShadowShapeBuilder, the pose retail puts it in), the compiled PhysicsBSPs its parts name
/// (BspExtractor → CompiledBsp, as the chart compiles them), standing at <see cref="Origin"/> with no
/// rotation. A door's open state is ethereal when its pose says so.
/// </summary>
public sealed class MovementSubject
{
    /// <summary>Where the object stands, landblock-local: the middle of a 192 m landblock, on the floor at z 0.</summary>
    public static readonly Vector3 Origin = new(96f, 96f, 0f);

    public const float FloorZ = 0f;

    private readonly Dictionary<uint, (BspDump Dump, CompiledBsp Compiled)> _bsps = [];

    public Setup Setup { get; }

    private MovementSubject(Setup setup) => Setup = setup;

    /// <summary>The Setup, or null when the dat has none with that id.</summary>
    public static MovementSubject? Read(IDatSource dat, uint setupId) =>
        dat.ReadSetup(setupId) is { } setup ? new MovementSubject(setup) : null;

    /// <summary>The BSP dumps of every part the built states use, by GfxObj id (what the suite's shapes reference).</summary>
    public IReadOnlyDictionary<uint, BspDump> Dumps => _bsps.OrderBy(b => b.Key).ToDictionary(b => b.Key, b => b.Value.Dump);

    public (MovementObject Object, ShadowShapeSet Set) Build(IDatSource dat, DoorState state)
    {
        var set = ShadowShapeBuilder.Build(Setup, dat.ReadGfxObj, new ShapeBuildOptions(ShapePolicy.Retail) { DoorState = state }, dat);
        var bsps = new Dictionary<uint, CompiledBsp>();
        foreach (var shape in set.Shapes)
        {
            if (shape.CollisionType != CollisionType.Bsp || shape.GfxObjId is not { } id || bsps.ContainsKey(id)) continue;
            if (!_bsps.TryGetValue(id, out var bsp))
            {
                if (dat.ReadGfxObj(id) is not { } gfx || BspExtractor.Extract(gfx) is not { } dump) continue;
                bsp = (dump, CompiledBsp.Compile(dump));
                _bsps[id] = bsp;
            }
            bsps[id] = bsp.Compiled;
        }
        return (new MovementObject(set.Shapes, bsps, Origin, Quaternion.Identity, 1f, set.Pose.Ethereal), set);
    }
}
