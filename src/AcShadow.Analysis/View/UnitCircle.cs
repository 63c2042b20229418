namespace AcShadow.Analysis.View;

/// <summary>
/// Cosines and sines of k·2π/32 from literals of the first octant and the circle's symmetries, not from
/// MathF.Sin/Cos: the C runtime's trigonometry may differ in the last bit between machines, and a view's
/// bytes must not.
/// </summary>
internal static class UnitCircle
{
    public const int Steps = 32;

    // cos and sin of 0, π/16, π/8, 3π/16, π/4.
    private static readonly double[] OctantCos = [1.0, 0.98078528040323044913, 0.92387953251128675613, 0.83146961230254523708, 0.70710678118654752440];
    private static readonly double[] OctantSin = [0.0, 0.19509032201612826785, 0.38268343236508977173, 0.55557023301960222474, 0.70710678118654752440];

    /// <summary>(cos, sin) of <paramref name="k"/>·2π/<see cref="Steps"/>, for any integer k.</summary>
    public static (float Cos, float Sin) At(int k)
    {
        k = ((k % Steps) + Steps) % Steps;
        var (c, s) = k switch
        {
            <= 8 => Quadrant(k),
            <= 16 => (-Quadrant(16 - k).Cos, Quadrant(16 - k).Sin),
            <= 24 => (-Quadrant(k - 16).Cos, -Quadrant(k - 16).Sin),
            _ => (Quadrant(32 - k).Cos, -Quadrant(32 - k).Sin),
        };
        return ((float)c, (float)s);
    }

    private static (double Cos, double Sin) Quadrant(int k) => k <= 4 ? (OctantCos[k], OctantSin[k]) : (OctantSin[8 - k], OctantCos[8 - k]);
}
