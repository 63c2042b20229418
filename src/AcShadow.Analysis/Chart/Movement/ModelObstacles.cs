using System.Numerics;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Core.Movement;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Movement;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart.Movement;

/// <summary>
/// A prepared chart model as the client's primitives (movement.md §4.1), ready for the movement reference:
/// each shape one object in the cell's shadow list, in builder order, standing where the movement cases put
/// the object. BSP parts keep their tree; a fitted part (box or hull) becomes a one-leaf BSP whose faces carry
/// the solid's planes; cylinders and spheres go through the CCylSphere and CSphere branches. Tested in list
/// order with the first non-OK winning, a one-family model gives what one object of it gives, and the union
/// is run across families on purpose.
/// </summary>
internal static class ModelObstacles
{
    public static IReadOnlyList<MovementObject> Of(PreparedModel model, bool ethereal)
    {
        var objects = new List<MovementObject>(model.Shapes.Count);
        foreach (var prepared in model.Shapes)
        {
            var shape = prepared.Shape;
            if (shape.CollisionType != CollisionType.Bsp)
            {
                objects.Add(Place([shape], new Dictionary<uint, CompiledBsp>(), ethereal));
                continue;
            }
            var id = shape.GfxObjId ?? 0u;
            var bsp = prepared.Bsp ?? prepared.Polytope?.ToSolidLeaf(id);
            if (bsp is null) continue;
            objects.Add(Place([shape with { GfxObjId = id }], new Dictionary<uint, CompiledBsp> { [id] = bsp }, ethereal));
        }
        return objects;
    }

    private static MovementObject Place(IReadOnlyList<ShadowShape> shapes, IReadOnlyDictionary<uint, CompiledBsp> bsps, bool ethereal) =>
        new(shapes, bsps, MovementSubject.Origin, Quaternion.Identity, 1f, ethereal);
}
