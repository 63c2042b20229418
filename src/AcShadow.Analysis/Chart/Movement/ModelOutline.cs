using System.Numerics;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart.Movement;

/// <summary>
/// A model's shapes seen from above, landblock-local, for the movement failure map: each polygon of its BSP
/// parts or fitted solids projected onto the floor, and each cylinder or sphere as a circle.
/// </summary>
public sealed record ModelOutline(IReadOnlyList<IReadOnlyList<Vector2>> Polygons, IReadOnlyList<(Vector2 Center, float Radius)> Circles)
{
    internal static ModelOutline Of(PreparedModel model, Vector3 origin)
    {
        var polygons = new List<IReadOnlyList<Vector2>>();
        var circles = new List<(Vector2, float)>();
        foreach (var shape in model.Shapes)
        {
            IEnumerable<IReadOnlyList<Vector3>>? faces = shape.Bsp is { } bsp ? bsp.Polygons.Select(p => (IReadOnlyList<Vector3>)p.Vertices)
                : shape.Polytope is { } solid ? solid.Faces.Select(p => (IReadOnlyList<Vector3>)p.Vertices) : null;
            if (faces is null)
            {
                var c = origin + shape.Shape.LocalPosition;
                circles.Add((new Vector2(c.X, c.Y), shape.Shape.Radius));
                continue;
            }
            foreach (var face in faces)
                polygons.Add([.. face.Select(v =>
                {
                    var p = origin + shape.Pose.ToEntity(v);
                    return new Vector2(p.X, p.Y);
                })]);
        }
        return new ModelOutline(polygons, circles);
    }
}
