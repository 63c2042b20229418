namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// One entry of Setup.PlacementFrames: an animation frame with one Frame per part. In the dat the
/// frame count is always the Setup's part count (the frame is unpacked with NumParts).
/// </summary>
public sealed record PlacementFrame(uint Placement, IReadOnlyList<Frame> Frames)
{
    public string Name => Objects.Placement.Name(Placement);
}
