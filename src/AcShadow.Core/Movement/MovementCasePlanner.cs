using System.Globalization;
using System.Numerics;
using AcShadow.Fixtures.Movement;

namespace AcShadow.Core.Movement;

/// <summary>
/// The case generator (movement.md §3): for a door the tier-1 set of §3.1 (two sides × 11 lateral offsets ×
/// 7 headings × walk and run), for any other object the 16 compass headings of §3.2 aimed at the footprint's
/// centre × 7 lateral offsets × walk and run. Every walk starts standing on the floor in contact and lasts until
/// the mover's origin is r0 + t + 1 m past the gate at the intended speed (t = 0 for other objects).
/// </summary>
public static class MovementCasePlanner
{
    public const float WalkSpeed = 3.12f;

    /// <summary>Running at Run skill 300 (run rate 2.65 × 4.0 m/s).</summary>
    public const float RunSpeed = 10.6f;

    public const float Quantum = 1f / 30f;

    /// <summary>The clearance before and after the object a walk adds to the mover's radius (§3.1).</summary>
    private const float Clearance = 1f;

    // Headings with their cosine and sine written out: the platform's sin and cos may differ in the last bit,
    // and the cases must be byte-identical on every machine.
    private static readonly (float Degrees, float Cos, float Sin)[] DoorHeadings =
    [
        (0f, 1f, 0f), (10f, 0.98480775f, 0.17364818f), (-10f, 0.98480775f, -0.17364818f), (30f, 0.8660254f, 0.5f),
        (-30f, 0.8660254f, -0.5f), (60f, 0.5f, 0.8660254f), (-60f, 0.5f, -0.8660254f),
    ];

    private const float C225 = 0.9238795f, S225 = 0.38268343f, S45 = 0.70710677f;

    /// <summary>The 16 compass directions, 22.5° apart from +x, counter-clockwise.</summary>
    private static readonly (float X, float Y)[] Compass =
    [
        (1f, 0f), (C225, S225), (S45, S45), (S225, C225), (0f, 1f), (-S225, C225), (-S45, S45), (-C225, S225),
        (-1f, 0f), (-C225, -S225), (-S45, -S45), (-S225, -C225), (0f, -1f), (S225, -C225), (S45, -S45), (C225, -S225),
    ];
    private static readonly (string Name, float Speed)[] Speeds = [("walk", WalkSpeed), ("run", RunSpeed)];

    public static IReadOnlyList<MovementCasePlan> Door(MovementFootprint footprint, Mover mover, string state)
    {
        var r0 = Radius0(mover);
        var hw = footprint.HalfWidth;
        float[] laterals = [0f, 0.45f, -0.45f, 0.5f * hw, -0.5f * hw, hw - r0, -(hw - r0), hw, -hw, hw + r0 / 2f, -(hw + r0 / 2f)];
        var across = footprint.AcrossIsY ? Vector3.UnitY : Vector3.UnitX;
        var wide = footprint.AcrossIsY ? Vector3.UnitX : Vector3.UnitY;
        var center = MovementSubject.Origin + footprint.Center;
        var before = r0 + footprint.Thickness / 2f + Clearance;
        var after = r0 + footprint.Thickness + Clearance;
        var plans = new List<MovementCasePlan>();
        foreach (var (side, normal) in new[] { ("out-in", across), ("in-out", -across) })
            foreach (var lateral in laterals)
                foreach (var heading in DoorHeadings)
                    foreach (var (speedName, speed) in Speeds)
                    {
                        var start = center - before * normal + lateral * wide;
                        var id = string.Create(CultureInfo.InvariantCulture, $"{state}/{side}/lat{lateral:+0.000;-0.000}/hdg{heading.Degrees:+00;-00}/{speedName}");
                        plans.Add(Plan(id, state, heading, start, normal, before + after, speed, mover, center));
                    }
        return plans;
    }

    public static IReadOnlyList<MovementCasePlan> Object(MovementFootprint footprint, Mover mover, string state)
    {
        var r0 = Radius0(mover);
        var halfExtent = MathF.Max(footprint.Max.X - footprint.Min.X, footprint.Max.Y - footprint.Min.Y) * 0.5f;
        float[] laterals = [0f, 0.5f * r0, -0.5f * r0, r0, -r0, halfExtent, -halfExtent];
        var center = MovementSubject.Origin + footprint.Center;
        var before = footprint.Reach + r0 + Clearance;
        var plans = new List<MovementCasePlan>();
        for (var k = 0; k < 16; k++)
        {
            var compass = k * 22.5f;
            var normal = new Vector3(Compass[k].X, Compass[k].Y, 0f);
            var wide = new Vector3(-normal.Y, normal.X, 0f);
            foreach (var lateral in laterals)
                foreach (var (speedName, speed) in Speeds)
                {
                    var start = center - before * normal + lateral * wide;
                    var id = string.Create(CultureInfo.InvariantCulture, $"{state}/dir{compass:000.0}/lat{lateral:+0.000;-0.000}/{speedName}");
                    plans.Add(Plan(id, state, DoorHeadings[0], start, normal, 2f * before, speed, mover, center));
                }
        }
        return plans;
    }

    /// <summary>Sphere 0 as SPHEREPATH::init_sphere takes it: the Setup's first, or retail's dummy sphere.</summary>
    private static Fixtures.Geometry.Sphere Sphere0(Mover mover) => mover.Spheres.Count > 0 ? mover.Spheres[0] : MovementConstants.DummySphere;

    private static float Radius0(Mover mover) => Sphere0(mover).Radius * mover.Scale;

    /// <summary>
    /// A walk from <paramref name="start"/> (lifted so sphere 0 rests on the floor) at <paramref name="heading"/>
    /// from <paramref name="normal"/>, for enough frames to cover <paramref name="distance"/> along it.
    /// </summary>
    private static MovementCasePlan Plan(string id, string state, (float Degrees, float Cos, float Sin) heading, Vector3 start, Vector3 normal,
        float distance, float speed, Mover mover, Vector3 gatePoint)
    {
        var left = new Vector3(-normal.Y, normal.X, 0f);
        var direction = heading.Cos * normal + heading.Sin * left;
        var velocity = speed * direction;
        var frames = (int)MathF.Ceiling(distance / (speed * Quantum * heading.Cos));
        var sphere0 = Sphere0(mover);
        var lift = (sphere0.Radius - sphere0.Center.Z) * mover.Scale;
        var walk = new Walk(start with { Z = MovementSubject.FloorZ + lift }, velocity, MovementSubject.FloorZ, frames, Quantum);
        var d = -(normal.X * gatePoint.X + normal.Y * gatePoint.Y + normal.Z * gatePoint.Z);
        return new MovementCasePlan(id, state, heading.Degrees, walk, new Plane(normal, d));
    }
}
