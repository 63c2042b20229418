using AcShadow.Core.Dat.Objects;

namespace AcShadow.Core.Dat;

/// <summary>Where the motion pose reads motion tables and animations (a dat; null for an absent id).</summary>
public interface IMotionSource
{
    MotionTable? ReadMotionTable(uint id);
    Animation? ReadAnimation(uint id);
}
