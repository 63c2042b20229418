using System.Numerics;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Analysis.Fitting;

/// <summary>
/// A part's box: the smaller (by volume) of the box along the part's own axes and the box along the
/// principal axes of its physics vertices; on a tie the part's axes (a box GfxObj modelled along its own
/// axes has its corners at the very vertices, so its faces are the polygons' planes bit for bit). The box's
/// axes are a fit within the part's own space, not a frame the client moves points with, so they turn by the
/// plain unit-quaternion rotation.
/// </summary>
internal static class PartBoxFit
{
    public static OrientedBox? Of(IReadOnlyList<Vector3> vertices)
    {
        if (vertices.Count == 0) return null;
        var local = Along(Quaternion.Identity, vertices);
        var principal = Along(PrincipalAxes.Of(vertices), vertices);
        return principal.Volume < local.Volume * (1f - 1e-4f) ? principal : local;
    }

    /// <summary>The tightest box with the given axes: the extent of the vertices projected on each.</summary>
    public static OrientedBox Along(Quaternion axes, IReadOnlyList<Vector3> vertices)
    {
        var min = new Vector3(float.PositiveInfinity);
        var max = new Vector3(float.NegativeInfinity);
        foreach (var v in vertices)
        {
            var p = axes == Quaternion.Identity ? v : QuaternionRotation.RotateInverse(axes, v);
            min = Vector3.Min(min, p);
            max = Vector3.Max(max, p);
        }
        var mid = new Vector3((min.X + max.X) * 0.5f, (min.Y + max.Y) * 0.5f, (min.Z + max.Z) * 0.5f);
        var half = new Vector3((max.X - min.X) * 0.5f, (max.Y - min.Y) * 0.5f, (max.Z - min.Z) * 0.5f);
        var center = axes == Quaternion.Identity ? mid : QuaternionRotation.Rotate(axes, mid);
        return new OrientedBox(center, axes, half);
    }
}
