using System.Numerics;

namespace AcShadow.Analysis.Fitting;

/// <summary>
/// The principal axes of a point set: the eigenvectors of its covariance, found by cyclic Jacobi
/// rotations in double (square roots only, no trigonometry, so every machine gets the same bits),
/// returned as a unit quaternion whose x, y, z axes are they (right-handed, w ≥ 0).
/// </summary>
public static class PrincipalAxes
{
    public static Quaternion Of(IReadOnlyList<Vector3> points)
    {
        if (points.Count == 0) return Quaternion.Identity;
        double mx = 0, my = 0, mz = 0;
        foreach (var p in points) { mx += p.X; my += p.Y; mz += p.Z; }
        mx /= points.Count; my /= points.Count; mz /= points.Count;
        var a = new double[3, 3];
        foreach (var p in points)
        {
            double[] d = [p.X - mx, p.Y - my, p.Z - mz];
            for (var i = 0; i < 3; i++)
                for (var j = 0; j < 3; j++) a[i, j] += d[i] * d[j];
        }
        var v = Jacobi(a);
        // Columns of v are the axes; make them right-handed so they form a rotation.
        var x = new Vector3((float)v[0, 0], (float)v[1, 0], (float)v[2, 0]);
        var y = new Vector3((float)v[0, 1], (float)v[1, 1], (float)v[2, 1]);
        var z = Vector3.Cross(x, y);
        var m = new Matrix4x4(x.X, x.Y, x.Z, 0, y.X, y.Y, y.Z, 0, z.X, z.Y, z.Z, 0, 0, 0, 0, 1);
        // A fitted axis set, not a frame read from the dat: unit length is what the box fit and the plain rotation need.
        var q = Quaternion.Normalize(Quaternion.CreateFromRotationMatrix(m));
        return q.W < 0 ? new Quaternion(-q.X, -q.Y, -q.Z, -q.W) : q;
    }

    /// <summary>Eigenvectors (columns) of a symmetric 3×3 matrix, sorted by descending eigenvalue.</summary>
    private static double[,] Jacobi(double[,] a)
    {
        var v = new double[3, 3] { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
        for (var sweep = 0; sweep < 50; sweep++)
        {
            var off = Math.Abs(a[0, 1]) + Math.Abs(a[0, 2]) + Math.Abs(a[1, 2]);
            var scale = Math.Abs(a[0, 0]) + Math.Abs(a[1, 1]) + Math.Abs(a[2, 2]);
            if (off <= 1e-15 * Math.Max(scale, 1e-300)) break;
            for (var p = 0; p < 2; p++)
                for (var q = p + 1; q < 3; q++)
                {
                    if (a[p, q] == 0) continue;
                    var theta = (a[q, q] - a[p, p]) / (2 * a[p, q]);
                    var t = Math.Sign(theta == 0 ? 1 : theta) / (Math.Abs(theta) + Math.Sqrt(theta * theta + 1));
                    var c = 1 / Math.Sqrt(t * t + 1);
                    var s = t * c;
                    for (var k = 0; k < 3; k++)
                    {
                        double akp = a[k, p], akq = a[k, q];
                        a[k, p] = c * akp - s * akq;
                        a[k, q] = s * akp + c * akq;
                    }
                    for (var k = 0; k < 3; k++)
                    {
                        double apk = a[p, k], aqk = a[q, k];
                        a[p, k] = c * apk - s * aqk;
                        a[q, k] = s * apk + c * aqk;
                    }
                    for (var k = 0; k < 3; k++)
                    {
                        double vkp = v[k, p], vkq = v[k, q];
                        v[k, p] = c * vkp - s * vkq;
                        v[k, q] = s * vkp + c * vkq;
                    }
                }
        }
        var order = new[] { 0, 1, 2 }.OrderByDescending(i => a[i, i]).ThenBy(i => i).ToArray();
        var sorted = new double[3, 3];
        for (var c = 0; c < 3; c++)
            for (var r = 0; r < 3; r++) sorted[r, c] = v[r, order[c]];
        return sorted;
    }
}
