using System.Numerics;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Movement;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Movement;

/// <summary>
/// The object's top-down extent in its own frame: the axis-aligned box of every posed physics polygon
/// vertex (CylSpheres and Spheres by their radius), as the chart's doorway lines find a slab. A door's gate
/// is the slab's mid-plane across its thin axis; <see cref="AcrossIsY"/> says which axis that is.
/// </summary>
public sealed record MovementFootprint(Vector3 Min, Vector3 Max)
{
    public Vector3 Center => new((Min.X + Max.X) * 0.5f, (Min.Y + Max.Y) * 0.5f, 0f);

    public bool AcrossIsY => Max.Y - Min.Y <= Max.X - Min.X;

    /// <summary>Half the wide side (a door's half width).</summary>
    public float HalfWidth => (AcrossIsY ? Max.X - Min.X : Max.Y - Min.Y) * 0.5f;

    /// <summary>The thin side (a door's thickness).</summary>
    public float Thickness => AcrossIsY ? Max.Y - Min.Y : Max.X - Min.X;

    /// <summary>Half the box's diagonal: every point of the footprint is within this of its centre.</summary>
    public float Reach => MathF.Sqrt((Max.X - Min.X) * (Max.X - Min.X) + (Max.Y - Min.Y) * (Max.Y - Min.Y)) * 0.5f;

    public static MovementFootprint Of(MovementObject subject)
    {
        var min = new Vector3(float.PositiveInfinity);
        var max = new Vector3(float.NegativeInfinity);
        void Add(Vector3 p)
        {
            min = Vector3.Min(min, p);
            max = Vector3.Max(max, p);
        }
        foreach (var shape in subject.Shapes)
        {
            switch (shape.CollisionType)
            {
                case CollisionType.Bsp when shape.GfxObjId is { } id && subject.Bsps.TryGetValue(id, out var bsp):
                    foreach (var polygon in bsp.Polygons)
                        foreach (var v in polygon.Vertices)
                            // The extent the movement cases are laid out in, no client counterpart: the plain rotation.
                            Add(shape.LocalPosition + QuaternionRotation.Rotate(shape.LocalRotation, v * shape.Scale));
                    break;
                case CollisionType.Cylinder or CollisionType.Sphere:
                    var r = new Vector3(shape.Radius, shape.Radius, 0f);
                    Add(shape.LocalPosition - r);
                    Add(shape.LocalPosition + r);
                    break;
            }
        }
        return float.IsInfinity(min.X) ? new MovementFootprint(Vector3.Zero, Vector3.Zero) : new MovementFootprint(min, max);
    }
}
