using AcShadow.Core.Dat.Binary;
using AcShadow.Fixtures.Geometry;
namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// An Animation (0x03xxxxxx). Layout (DatReaderWriter dats.xml Animation; ACE DatLoader Animation; retail
/// CAnimation::UnPack): Id, Flags (0x1: root-motion PosFrames present), NumParts, NumFrames, PosFrames
/// (NumFrames Frames, when flagged), then NumFrames <see cref="AnimationFrame"/>s of NumParts frames each.
/// PosFrames move the object over time, never a part: they are kept only to write the object back.
/// </summary>
public sealed record Animation(uint Id, uint Flags, int NumParts, IReadOnlyList<Frame>? PosFrames, IReadOnlyList<AnimationFrame> PartFrames)
{
    public const uint HasPosFrames = 0x1;
    private const int FrameBytes = 28;

    public static Animation Read(DatBinaryReader r)
    {
        var id = r.ReadUInt32();
        var flags = r.ReadUInt32();
        var numParts = r.ReadUInt32();
        var numFrames = r.ReadUInt32();
        var posFrames = (flags & HasPosFrames) != 0;
        // Each frame needs its part frames, its hook count and, when flagged, a root frame; dividing the bytes
        // left (rather than multiplying the counts) cannot overflow whatever the counts say.
        var perFrame = (long)numParts * FrameBytes + 4 + (posFrames ? FrameBytes : 0);
        if (numParts > int.MaxValue || numFrames > int.MaxValue || (numFrames > 0 && perFrame > r.Remaining / numFrames))
            throw new DatFormatException($"{numFrames} frame(s) of {numParts} part(s) cannot fit in the {r.Remaining} byte(s) left");
        Frame[]? pos = null;
        if (posFrames)
        {
            pos = new Frame[numFrames];
            for (var i = 0; i < pos.Length; i++) pos[i] = r.ReadFrame();
        }
        var frames = new AnimationFrame[numFrames];
        for (var i = 0; i < frames.Length; i++) frames[i] = AnimationFrame.Read(r, (int)numParts, $"frame {i}");
        return new Animation(id, flags, (int)numParts, pos, frames);
    }

    public void Write(DatBinaryWriter w)
    {
        var flags = PosFrames is null ? Flags & ~HasPosFrames : Flags | HasPosFrames;
        if (PosFrames is { } p && p.Count != PartFrames.Count)
            throw new InvalidOperationException($"Animation 0x{Id:X8}: {p.Count} PosFrames for {PartFrames.Count} frames; the dat stores one per frame");
        w.WriteUInt32(Id);
        w.WriteUInt32(flags);
        w.WriteUInt32((uint)NumParts);
        w.WriteUInt32((uint)PartFrames.Count);
        foreach (var f in PosFrames ?? []) w.WriteFrame(f);
        foreach (var frame in PartFrames)
        {
            if (frame.Frames.Count != NumParts)
                throw new InvalidOperationException($"Animation 0x{Id:X8}: a frame has {frame.Frames.Count} part frame(s); the dat stores exactly NumParts ({NumParts})");
            frame.Write(w);
        }
    }
}
