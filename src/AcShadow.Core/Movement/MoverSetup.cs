using AcShadow.Core.Dat;
using AcShadow.Fixtures.Movement;

namespace AcShadow.Core.Movement;

/// <summary>
/// The mover a case walks: a Setup's first two spheres (SPHEREPATH::init_sphere takes at most two), its
/// StepUpHeight and StepDownHeight, at scale 1, with EdgeSlide on (the weenie default movement.md §3.1
/// assumes for players).
/// </summary>
public static class MoverSetup
{
    /// <summary>
    /// The human mover in circulation (holtburger's values, the forged sample person's too): spheres (0, 0, 0.475)
    /// and (0, 0, 1.35), r 0.48, step up 0.6 m, step down 1.5 m. Unverified against a retail dat (movement.md):
    /// `scene` walks with it only when no --mover names the character's Setup.
    /// </summary>
    public static Mover StandardHuman { get; } = new(
        [new Fixtures.Geometry.Sphere(new System.Numerics.Vector3(0f, 0f, 0.475f), 0.48f), new Fixtures.Geometry.Sphere(new System.Numerics.Vector3(0f, 0f, 1.35f), 0.48f)],
        0.6f, 1.5f);

    /// <summary>The mover Setup, or null when the dat has no such Setup.</summary>
    public static Mover? Read(IDatSource dat, uint setupId)
    {
        var setup = dat.ReadSetup(setupId);
        if (setup is null) return null;
        return new Mover([.. setup.Spheres.Take(2)], setup.StepUpHeight, setup.StepDownHeight);
    }
}
