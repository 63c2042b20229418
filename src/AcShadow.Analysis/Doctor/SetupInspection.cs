using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Poses;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Doctor;

/// <summary>
/// The retail Setup claims checked on one Setup (retail-collision.md, "One object, many parts" and "Where
/// each part sits"): the HasPhysicsBSP flag (0x8) against <c>CPartArray::CacheHasPhysicsBSP</c>'s answer from
/// the parts; which placements exist (<c>CPartArray::SetPlacementFrame</c> takes Resting, else Default);
/// whether DefaultScale is uniform where BSP collision uses only its Z; which parts retail leaves unposed.
/// Also counts the placement frames' hook types.
/// </summary>
internal static class SetupInspection
{
    public static void Inspect(Setup setup, GfxObjPhysics gfx, DoctorTallies t)
    {
        t.SetupsChecked.Add();
        foreach (var placement in setup.PlacementFrames)
            foreach (var hook in placement.Hooks)
            {
                t.PlacementHooks.Add();
                t.HookTypes[Math.Min((int)hook.Type, t.HookTypes.Length - 1)].Add();
            }

        var partsBsp = false;
        long missing = 0;
        foreach (var part in setup.Parts)
            switch (gfx.Get(part))
            {
                case GfxObjPhysics.State.Bsp: partsBsp = true; break;
                case GfxObjPhysics.State.Absent or GfxObjPhysics.State.Unreadable: missing++; break;
            }
        t.PartMissing.Add(setup.Id, missing);
        var flag = setup.Flags.HasFlag(SetupFlags.HasPhysicsBsp);
        if (flag && !partsBsp) t.FlagSetPartsNone.Add(setup.Id);
        if (!flag && partsBsp) t.FlagClearPartsBsp.Add(setup.Id);

        var resting = setup.FindPlacement(Placement.Resting) is not null;
        var @default = setup.FindPlacement(Placement.Default) is not null;
        var other = setup.PlacementFrames.Any(p => p.Placement is not (Placement.Resting or Placement.Default));
        if (resting) t.WithResting.Add();
        if (@default) t.WithDefault.Add();
        if (other) t.WithOther.Add();
        if (setup.PlacementFrames.Count == 0) t.WithNoPlacement.Add();
        if (!resting && !@default && other) t.NeitherRestingNorDefault.Add(setup.Id);

        if (setup.DefaultScale.Count > 0)
        {
            t.WithDefaultScale.Add();
            long nonUniform = 0;
            for (var i = 0; i < setup.DefaultScale.Count && i < setup.Parts.Count; i++)
            {
                var s = setup.DefaultScale[i];
                if ((s.X != s.Z || s.Y != s.Z) && gfx.Get(setup.Parts[i]) == GfxObjPhysics.State.Bsp) nonUniform++;
            }
            t.NonUniformBspScale.Add(setup.Id, nonUniform);
        }

        // CPartArray::UpdateParts poses min(NumParts, frames) parts; with no frame a one-part object sits at the entity origin.
        t.PartsTotal.Add(setup.Parts.Count);
        var frame = PlacementResolver.Choose(setup, ShapePolicy.Retail);
        var posed = frame is not null ? Math.Min(setup.Parts.Count, frame.Frames.Count) : setup.Parts.Count == 1 ? 1 : 0;
        t.PartsWithoutPose.Add(setup.Id, setup.Parts.Count - posed);
    }
}
