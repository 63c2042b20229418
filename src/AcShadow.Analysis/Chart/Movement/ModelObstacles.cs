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
/// the solid's planes, listed in the order of the part's physics polygons whose planes they lie in (the rest
/// after them, in the solid's order), since at a corner the first polygon the leaf lists that the sphere
/// touches decides the slide; cylinders and spheres go through the CCylSphere and CSphere branches. Tested in list
/// order with the first non-OK winning, a one-family model gives what one object of it gives, and the union
/// is run across families on purpose.
/// </summary>
internal static class ModelObstacles
{
    /// <param name="partBsps">The retail PhysicsBSPs by GfxObj id, whose polygon order a fitted solid's faces follow (null: the solid's own order).</param>
    public static IReadOnlyList<MovementObject> Of(PreparedModel model, bool ethereal, Func<uint, CompiledBsp?>? partBsps = null)
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
            var bsp = prepared.Bsp ?? (prepared.Polytope is { } solid ? SolidLeaf(solid, id, partBsps?.Invoke(id)) : null);
            if (bsp is null) continue;
            objects.Add(Place([shape with { GfxObjId = id }], new Dictionary<uint, CompiledBsp> { [id] = bsp }, ethereal));
        }
        return objects;
    }

    private static CompiledBsp SolidLeaf(ConvexPolytope solid, uint id, CompiledBsp? part)
    {
        if (part is null) return solid.ToSolidLeaf(id);
        int Rank(CompiledPolygon face)
        {
            for (var k = 0; k < part.Polygons.Length; k++)
                if (part.Polygons[k].Normal == face.Normal && part.Polygons[k].D == face.D) return k;
            return part.Polygons.Length;
        }
        // A stable sort: faces in no physics polygon's plane keep the solid's order, after the others.
        return solid.ToSolidLeaf(id, [.. solid.Faces.Select((f, i) => (f, i)).OrderBy(x => Rank(x.f)).ThenBy(x => x.i).Select(x => x.f)]);
    }

    private static MovementObject Place(IReadOnlyList<ShadowShape> shapes, IReadOnlyDictionary<uint, CompiledBsp> bsps, bool ethereal) =>
        new(shapes, bsps, MovementSubject.Origin, Quaternion.Identity, 1f, ethereal);
}
