using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// A box in a part's own space: its centre, its axes (a unit quaternion turning the box's x, y, z onto
/// them) and its half extents along them (zero for a flat box). The part's pose places it in the entity.
/// The box is acshadow's fitted model with no client counterpart, so its own axes turn by the plain unit-quaternion
/// rotation (<see cref="QuaternionRotation"/>); moving between the part's and the entity's frame is the part pose's
/// client arithmetic.
/// </summary>
internal readonly record struct OrientedBox(Vector3 Center, Quaternion Axes, Vector3 HalfExtents)
{
    /// <summary>Corner i: bit 0 picks +x, bit 1 +y, bit 2 +z.</summary>
    public Vector3 Corner(int i)
    {
        var local = new Vector3((i & 1) == 0 ? -HalfExtents.X : HalfExtents.X, (i & 2) == 0 ? -HalfExtents.Y : HalfExtents.Y, (i & 4) == 0 ? -HalfExtents.Z : HalfExtents.Z);
        var turned = QuaternionRotation.Rotate(Axes, local);
        return new Vector3(turned.X + Center.X, turned.Y + Center.Y, turned.Z + Center.Z);
    }

    public float Volume => 8f * HalfExtents.X * HalfExtents.Y * HalfExtents.Z;

    /// <summary>The box as a convex polytope (its six faces, outward wound; a flat box keeps its two big faces).</summary>
    public ConvexPolytope ToPolytope()
    {
        // Counter-clockwise seen from outside, so each face's plane (CPolygon::make_plane) points out.
        int[][] faces = [[0, 4, 6, 2], [1, 3, 7, 5], [0, 1, 5, 4], [2, 6, 7, 3], [0, 2, 3, 1], [4, 5, 7, 6]];
        var corners = Enumerable.Range(0, 8).Select(Corner).ToArray();
        var polygons = new List<CompiledPolygon>();
        foreach (var face in faces)
        {
            var vertices = face.Select(i => corners[i]).ToArray();
            if (PolygonPlane.Compute(vertices) is { } plane) polygons.Add(new CompiledPolygon(polygons.Count, plane, vertices));
        }
        return new ConvexPolytope(corners, polygons);
    }
}
