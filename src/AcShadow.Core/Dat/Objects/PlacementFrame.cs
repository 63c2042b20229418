using AcShadow.Fixtures.Geometry;

namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// One entry of Setup.PlacementFrames: an animation frame with one Frame per part. In the dat the
/// frame count is always the Setup's part count (the frame is unpacked with NumParts). The frame's
/// animation hooks follow the frames; they have no collision meaning and are kept only as bytes.
/// </summary>
public sealed record PlacementFrame(uint Placement, IReadOnlyList<Frame> Frames)
{
    public string Name => Objects.Placement.Name(Placement);

    public IReadOnlyList<AnimationHook> Hooks { get; init; } = [];
}
