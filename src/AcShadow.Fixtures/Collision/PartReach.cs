using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// A posed part's reach in the entity frame: a sphere (centre, radius) and a factor on the query radius such that
/// a query sphere (c, r) with |c − Center| &gt; Radius + r·Stretch cannot be blocked by the part, whatever rounding
/// the turn into the part's frame (<see cref="PartPose.ToLocal(Vector3, float)"/>) and the part's own test make. A part is asked
/// behind it before the sphere is turned (CPartArray asks every part, each turning the sphere first), so a far
/// part costs one distance instead of a turn; the exact part-local test still decides, so answers are unchanged.
/// </summary>
/// <remarks>
/// Built from a part-local sphere (C, ρ) that the part's test keeps to: it passes only when
/// |local − C| ≤ (1 + τ)(ρ + r_local) + τ|C|, τ = 1e-5 (<see cref="LocalBound"/>). With M the pose's stored matrix
/// (a quaternion of squared length n gives n·R + (1 − n)·I, not a rotation), the entity centre E solves
/// Mᵀ(E − origin) = s·C exactly (in double), and |Mᵀv| ≥ σ|v| with σ² ≥ 1 − ‖I − MᵀM‖_F, so a passing sphere
/// has |c − E| ≤ (s·ρ + r)/σ plus rounding: float stores of the offset, the turn and the 1/s multiply, each a
/// few 2⁻²⁴ of s(|C| + ρ) + r. The margin a = 1e-4 covers them and the float test here ten times over.
/// A pose whose matrix is far from a rotation (σ under 0.5), or anything not finite, reaches everywhere.
/// </remarks>
internal readonly record struct PartReach(Vector3 Center, float Radius, float Stretch)
{
    private const double Margin = 1e-4;

    /// <summary>Reaches every sphere: no test is made.</summary>
    public static readonly PartReach Everywhere = new(Vector3.Zero, float.PositiveInfinity, 1f);

    public bool IsBounded => float.IsFinite(Radius);

    /// <summary>Can a sphere at this entity-space centre be blocked by the part? (NaN: no, as every part query answers.)</summary>
    public bool Reaches(Vector3 center, float radius)
    {
        float dx = center.X - Center.X, dy = center.Y - Center.Y, dz = center.Z - Center.Z;
        var sum = Radius + radius * Stretch;
        return dx * dx + dy * dy + dz * dz <= sum * sum;
    }

    /// <summary>The reach of a part posed by <paramref name="pose"/> whose test keeps to the part-local sphere <paramref name="local"/>.</summary>
    public static PartReach Of(PartPose pose, (Vector3 Center, float Radius)? local)
    {
        if (local is not { } bound || !Vec.IsFinite(bound.Center) || !float.IsFinite(bound.Radius) || !(pose.Scale > 0f) || !float.IsFinite(pose.Scale))
            return Everywhere;
        var m = pose.Matrix;
        double m0 = m.M0, m1 = m.M1, m2 = m.M2, m3 = m.M3, m4 = m.M4, m5 = m.M5, m6 = m.M6, m7 = m.M7, m8 = m.M8;
        // The turn into the part (ClientFrameMatrix.GlobalToLocal) is A with rows (m0 m1 m2), (m3 m4 m5), (m6 m7 m8);
        // AᵀA from its columns (products of floats are exact in double), whose eigenvalues are A's σ².
        double g00 = m0 * m0 + m3 * m3 + m6 * m6, g11 = m1 * m1 + m4 * m4 + m7 * m7, g22 = m2 * m2 + m5 * m5 + m8 * m8;
        double g01 = m0 * m1 + m3 * m4 + m6 * m7, g02 = m0 * m2 + m3 * m5 + m6 * m8, g12 = m1 * m2 + m4 * m5 + m7 * m8;
        var eta = Math.Sqrt((g00 - 1) * (g00 - 1) + (g11 - 1) * (g11 - 1) + (g22 - 1) * (g22 - 1) + 2 * (g01 * g01 + g02 * g02 + g12 * g12));
        if (!(eta <= 0.75)) return Everywhere;
        var sigma = Math.Sqrt(1 - eta) - 1e-12;
        // A·x = s·C by Cramer's rule: E = origin + x is the point the turn takes to the scaled local centre.
        double s = pose.Scale, bx = s * bound.Center.X, by = s * bound.Center.Y, bz = s * bound.Center.Z;
        var det = m0 * (m4 * m8 - m5 * m7) - m1 * (m3 * m8 - m5 * m6) + m2 * (m3 * m7 - m4 * m6);
        var x = (bx * (m4 * m8 - m5 * m7) - m1 * (by * m8 - m5 * bz) + m2 * (by * m7 - m4 * bz)) / det;
        var y = (m0 * (by * m8 - m5 * bz) - bx * (m3 * m8 - m5 * m6) + m2 * (m3 * bz - by * m6)) / det;
        var z = (m0 * (m4 * bz - by * m7) - m1 * (m3 * bz - by * m6) + bx * (m3 * m7 - m4 * m6)) / det;
        double ex = pose.Position.X + x, ey = pose.Position.Y + y, ez = pose.Position.Z + z;
        var fromCentre = Math.Sqrt(bx * bx + by * by + bz * bz);
        var radius = (1 + Margin) * (s * bound.Radius + Margin * fromCentre) / sigma + Margin * (Math.Sqrt(ex * ex + ey * ey + ez * ez) + 1e-2);
        var stretch = (1 + Margin) / sigma;
        var center = new Vector3((float)ex, (float)ey, (float)ez);
        return Vec.IsFinite(center) && double.IsFinite(radius) && double.IsFinite(stretch)
            ? new PartReach(center, (float)radius, (float)stretch)
            : Everywhere;
    }
}
