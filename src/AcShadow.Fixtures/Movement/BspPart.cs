using AcShadow.Fixtures.Collision;

namespace AcShadow.Fixtures.Movement;

/// <summary>One BSP part of the object in its world pose, with its tree and the placement query over it.</summary>
internal sealed class BspPart(PartPose pose, CompiledBsp bsp)
{
    public PartPose Pose { get; } = pose;
    public CompiledBsp Bsp { get; } = bsp;
    public BspSphereQuery Solid { get; } = new(bsp);
}
