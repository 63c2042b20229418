using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// A box, in double bounds, around every float centre a computation can give for a set of inputs: a voxel's
/// centres padded past the float mapping that puts a centre in it, then the same box carried through the float
/// turns a query makes (<see cref="Turned"/>, <see cref="Scaled"/>), each step widened by a bound on its rounding.
/// What is decided over the box is decided for every centre the query can compute there.
/// </summary>
internal readonly record struct CentreBox(double LoX, double LoY, double LoZ, double HiX, double HiY, double HiZ)
{
    /// <summary>Relative bound on the rounding of one float expression of a few terms (an ulp is 6e-8), with room to spare.</summary>
    private const double Rounding = 1e-6;

    /// <summary>Finite and not inverted: a box decisions can be taken over.</summary>
    public bool IsUsable =>
        double.IsFinite(LoX) && double.IsFinite(LoY) && double.IsFinite(LoZ) && double.IsFinite(HiX) && double.IsFinite(HiY) && double.IsFinite(HiZ)
        && LoX <= HiX && LoY <= HiY && LoZ <= HiZ && Math.Max(Math.Max(Math.Abs(LoX), Math.Abs(HiX)), Math.Max(Math.Max(Math.Abs(LoY), Math.Abs(HiY)), Math.Max(Math.Abs(LoZ), Math.Abs(HiZ)))) < 1e7;

    /// <summary>
    /// Every result of <see cref="ClientFrameMatrix.GlobalToLocal"/> for a centre in the box: the offsets from the
    /// origin, then the transpose's sums, each widened by its rounding (the stored and the held z offset both lie in
    /// the widened offset range).
    /// </summary>
    public CentreBox Turned(in ClientFrameMatrix m)
    {
        var (dxLo, dxHi) = Offset(LoX, HiX, m.Origin.X);
        var (dyLo, dyHi) = Offset(LoY, HiY, m.Origin.Y);
        var (dzLo, dzHi) = Offset(LoZ, HiZ, m.Origin.Z);
        var (xLo, xHi) = Sum(m.M2, dzLo, dzHi, m.M0, dxLo, dxHi, m.M1, dyLo, dyHi);
        var (yLo, yHi) = Sum(m.M5, dzLo, dzHi, m.M3, dxLo, dxHi, m.M4, dyLo, dyHi);
        var (zLo, zHi) = Sum(m.M8, dzLo, dzHi, m.M6, dxLo, dxHi, m.M7, dyLo, dyHi);
        return new CentreBox(xLo, yLo, zLo, xHi, yHi, zHi);
    }

    /// <summary>Every float product of a centre in the box and <paramref name="factor"/> (a part's 1 / scale).</summary>
    public CentreBox Scaled(float factor)
    {
        static (double, double) Axis(double lo, double hi, double k)
        {
            double a = lo * k, b = hi * k, pad = Rounding * Math.Max(Math.Abs(a), Math.Abs(b)) + 1e-30;
            return (Math.Min(a, b) - pad, Math.Max(a, b) + pad);
        }
        var (xLo, xHi) = Axis(LoX, HiX, factor);
        var (yLo, yHi) = Axis(LoY, HiY, factor);
        var (zLo, zHi) = Axis(LoZ, HiZ, factor);
        return new CentreBox(xLo, yLo, zLo, xHi, yHi, zHi);
    }

    /// <summary>
    /// A float test |c − point|² ≤ distance² (each difference, square and sum rounded to float) over the box: the
    /// squares' rounding is bounded relatively, since every term is non-negative.
    /// </summary>
    public BoxDecision Within(Vector3 point, float distance)
    {
        const double Slack = 4e-6;
        var limit = (double)distance * distance;
        var (lo, hi) = DistanceSquared(point);
        if (!double.IsFinite(limit) || !(hi < 1e30)) return BoxDecision.Mixed;
        if (hi * (1 + Slack) + 1e-30 < limit * (1 - Slack)) return BoxDecision.True;
        if (lo * (1 - Slack) - 1e-30 > limit * (1 + Slack)) return BoxDecision.False;
        return BoxDecision.Mixed;
    }

    /// <summary>The least and greatest squared distance from a point to the box.</summary>
    public (double Lo, double Hi) DistanceSquared(Vector3 p)
    {
        double lo = 0, hi = 0;
        Axis(p.X, LoX, HiX, ref lo, ref hi);
        Axis(p.Y, LoY, HiY, ref lo, ref hi);
        Axis(p.Z, LoZ, HiZ, ref lo, ref hi);
        return (lo, hi);

        static void Axis(double p, double lo, double hi, ref double near, ref double far)
        {
            var gap = p < lo ? lo - p : p > hi ? p - hi : 0.0;
            var reach = Math.Max(Math.Abs(p - lo), Math.Abs(hi - p));
            near += gap * gap;
            far += reach * reach;
        }
    }

    private static (double Lo, double Hi) Offset(double lo, double hi, float origin)
    {
        double a = lo - origin, b = hi - origin, pad = Rounding * Math.Max(Math.Abs(a), Math.Abs(b)) + 1e-30;
        return (a - pad, b + pad);
    }

    private static (double Lo, double Hi) Sum(float k0, double lo0, double hi0, float k1, double lo1, double hi1, float k2, double lo2, double hi2)
    {
        double lo = 0, hi = 0, scale = 0;
        Term(k0, lo0, hi0, ref lo, ref hi, ref scale);
        Term(k1, lo1, hi1, ref lo, ref hi, ref scale);
        Term(k2, lo2, hi2, ref lo, ref hi, ref scale);
        var pad = Rounding * scale + 1e-30;
        return (lo - pad, hi + pad);

        static void Term(double k, double lo, double hi, ref double min, ref double max, ref double scale)
        {
            min += k >= 0 ? k * lo : k * hi;
            max += k >= 0 ? k * hi : k * lo;
            scale += Math.Abs(k) * Math.Max(Math.Abs(lo), Math.Abs(hi));
        }
    }
}
