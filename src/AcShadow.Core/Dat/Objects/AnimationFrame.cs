using AcShadow.Core.Dat.Binary;
using AcShadow.Fixtures.Geometry;
namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// One frame of an Animation: a Frame per animated part (the count is the Animation's NumParts, not stored
/// here), then the frame's hooks, read by the one hook reader (<see cref="AnimationHook.Read"/>).
/// </summary>
public sealed record AnimationFrame(IReadOnlyList<Frame> Frames, IReadOnlyList<AnimationHook> Hooks)
{
    public static AnimationFrame Read(DatBinaryReader r, int parts, string where)
    {
        var frames = new Frame[parts];
        for (var i = 0; i < parts; i++) frames[i] = r.ReadFrame();
        var hooks = new AnimationHook[r.ReadCount(r.ReadUInt32(), AnimationHookLayout.HeaderBytes, "animation hook")];
        for (var h = 0; h < hooks.Length; h++) hooks[h] = AnimationHook.Read(r, $"{where}, hook {h + 1} of {hooks.Length}");
        return new AnimationFrame(frames, hooks);
    }

    public void Write(DatBinaryWriter w)
    {
        foreach (var f in Frames) w.WriteFrame(f);
        w.WriteUInt32((uint)Hooks.Count);
        foreach (var hook in Hooks) hook.Write(w);
    }
}
