using System.Globalization;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Core.Scenes;

/// <summary>
/// A placed object's world position: the landblock's world origin plus its landblock-relative origin.
/// The sum is done in decimal on the float's shortest text, so 32448 + 0.1f gives 32448.1 and not the
/// binary expansion of 0.1f; the orientation is the landblock-relative one (landblocks are not rotated).
/// </summary>
public static class WorldFrame
{
    public static (double X, double Y, double Z) Origin(LandblockCoordinates landblock, Frame frame) =>
        (Add(landblock.WorldOriginX, frame.Position.X), Add(landblock.WorldOriginY, frame.Position.Y), Add(0d, frame.Position.Z));

    private static double Add(double origin, float offset)
    {
        if (!float.IsFinite(offset) || MathF.Abs(offset) > 1e15f) return origin + offset;
        var sum = (decimal)origin + decimal.Parse(offset.ToString("R", CultureInfo.InvariantCulture), NumberStyles.Float, CultureInfo.InvariantCulture);
        return (double)sum;
    }
}
