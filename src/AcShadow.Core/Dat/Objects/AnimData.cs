using AcShadow.Core.Dat.Binary;
namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// One animation a MotionData plays (16 bytes): the Animation id, the frame range (HighFrame −1 = to the
/// end) and the frame rate (negative plays backwards).
/// </summary>
public readonly record struct AnimData(uint AnimId, int LowFrame, int HighFrame, float Framerate)
{
    public const int Bytes = 16;

    public static AnimData Read(DatBinaryReader r) => new(r.ReadUInt32(), r.ReadInt32(), r.ReadInt32(), r.ReadSingle());

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt32(AnimId);
        w.WriteInt32(LowFrame);
        w.WriteInt32(HighFrame);
        w.WriteSingle(Framerate);
    }
}
