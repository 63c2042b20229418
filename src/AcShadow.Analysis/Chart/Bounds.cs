using System.Numerics;

namespace AcShadow.Analysis.Chart;

/// <summary>An axis-aligned box in entity space.</summary>
public readonly record struct Bounds(Vector3 Min, Vector3 Max)
{
    public static readonly Bounds Empty = new(new Vector3(float.PositiveInfinity), new Vector3(float.NegativeInfinity));

    public bool IsEmpty => !(Min.X <= Max.X && Min.Y <= Max.Y && Min.Z <= Max.Z);
    public Vector3 Center => (Min + Max) * 0.5f;
    public Vector3 Size => Max - Min;

    public Bounds Include(Vector3 p) =>
        !(float.IsFinite(p.X) && float.IsFinite(p.Y) && float.IsFinite(p.Z)) ? this : new(Vector3.Min(Min, p), Vector3.Max(Max, p));

    public Bounds Include(Bounds other) => other.IsEmpty ? this : Include(other.Min).Include(other.Max);

    public Bounds Expand(float by) => IsEmpty ? this : new(Min - new Vector3(by), Max + new Vector3(by));
}
