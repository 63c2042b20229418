using AcShadow.Forging.Spec;

namespace AcShadow.Forge.Scale;

/// <summary>
/// The GfxObjs Setups are built from, besides the doors': a physics pool (statics' parts), a drawing-only
/// pool (creatures' and items' parts) and a bare pool no Setup uses (landblocks place some of it directly).
/// Each pool entry is used once in order first, then at random: every GfxObj of a pool is used and the
/// later draws share (a real dat reuses rocks, walls and limbs across many Setups).
/// </summary>
internal sealed class PartPools
{
    private readonly Random _random;
    private readonly List<PoolPart> _physics;
    private readonly List<PoolPart> _drawing;
    private int _physicsCursor;
    private int _drawingCursor;

    private PartPools(Random random, List<PoolPart> physics, List<PoolPart> drawing, List<uint> barePhysics)
    {
        _random = random;
        _physics = physics;
        _drawing = drawing;
        BareModels = barePhysics.Count > 0 ? barePhysics : physics.Select(p => p.Id).ToList();
    }

    /// <summary>What landblocks place as bare models: the bare pool's physics parts (the physics pool's if it has none).</summary>
    public IReadOnlyList<uint> BareModels { get; }

    /// <summary>Adds <paramref name="count"/> GfxObjs to <paramref name="gfxObjs"/>: 40 % physics, 10 % bare, the rest drawing-only.</summary>
    public static PartPools Generate(Random random, ScaleIds ids, int count, List<GfxObjSpec> gfxObjs)
    {
        var physicsCount = Math.Max(1, count * 40 / 100);
        var bareCount = Math.Max(2, count * 10 / 100);
        var drawingCount = count - physicsCount - bareCount;
        var physics = new List<PoolPart>(physicsCount);
        for (var i = 0; i < physicsCount; i++)
        {
            var id = ids.NewGfxObj();
            var (mesh, size) = PartShapes.Physics(random, PartShapes.PhysicsPolygonCount(random));
            gfxObjs.Add(mesh.ToSpec(id, true, random.Next(5) != 0));
            physics.Add(new(id, size));
        }
        var drawing = new List<PoolPart>(drawingCount);
        for (var i = 0; i < drawingCount; i++)
        {
            var id = ids.NewGfxObj();
            var (mesh, size) = PartShapes.Drawing(random);
            gfxObjs.Add(mesh.ToSpec(id, false, true));
            drawing.Add(new(id, size));
        }
        var barePhysics = new List<uint>();
        for (var i = 0; i < bareCount; i++)
        {
            var id = ids.NewGfxObj();
            if (i % 2 == 0)
            {
                gfxObjs.Add(PartShapes.Physics(random, PartShapes.PhysicsPolygonCount(random)).Mesh.ToSpec(id, true, true));
                barePhysics.Add(id);
            }
            else gfxObjs.Add(PartShapes.Drawing(random).Mesh.ToSpec(id, false, true));
        }
        return new PartPools(random, physics, drawing, barePhysics);
    }

    public PoolPart NextPhysics() => _physicsCursor < _physics.Count ? _physics[_physicsCursor++] : _physics[_random.Next(_physics.Count)];

    public PoolPart NextDrawing() => _drawingCursor < _drawing.Count ? _drawing[_drawingCursor++] : _drawing[_random.Next(_drawing.Count)];
}
