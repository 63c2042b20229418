using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Poses;

/// <summary>
/// Chooses the placement frame the parts are posed by.
/// Retail (CPartArray::SetPlacementFrame): Resting (0x65), else Default (0), else no frame at all.
/// Union (the seed design): Resting, else Default, else the first placement in the Setup — a divergence
/// from retail that the tool exposes rather than hides.
/// </summary>
public static class PlacementResolver
{
    public static PlacementFrame? Choose(Setup setup, ShapePolicy policy)
    {
        var frame = setup.FindPlacement(Placement.Resting) ?? setup.FindPlacement(Placement.Default);
        if (frame is null && policy == ShapePolicy.Union && setup.PlacementFrames.Count > 0)
            frame = setup.PlacementFrames[0];
        return frame;
    }

    /// <summary>What the output files record about the choice (the frame itself stays in the dat model).</summary>
    public static PlacementResolution Describe(PlacementFrame? frame) =>
        new(Placement.Name(Placement.Resting), frame?.Name ?? PlacementResolution.NoneName);
}
