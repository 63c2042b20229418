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
    /// <summary>The mover Setup, or null when the dat has no such Setup.</summary>
    public static Mover? Read(IDatSource dat, uint setupId)
    {
        var setup = dat.ReadSetup(setupId);
        if (setup is null) return null;
        return new Mover([.. setup.Spheres.Take(2)], setup.StepUpHeight, setup.StepDownHeight);
    }
}
