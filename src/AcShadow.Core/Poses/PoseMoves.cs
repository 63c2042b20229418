using System.Globalization;
using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Core.Poses;

/// <summary>
/// Which parts a motion pose moves away from where the placement pose puts them, by more than
/// <see cref="MovedMetres"/> or <see cref="MovedDegrees"/>: the rule behind a shadow file's
/// <c>pose-moved</c> diagnostic, audit's poseDiffers column and the doctor's motion-pose check.
/// </summary>
public static class PoseMoves
{
    /// <summary>How far a part may move from its placement pose before the two poses are said to differ.</summary>
    public const float MovedMetres = 0.001f, MovedDegrees = 0.1f;

    /// <summary>"part I by M m and D deg" for each part that moved; empty when none did or there is no motion pose.</summary>
    public static IReadOnlyList<string> Between(Setup setup, ResolvedPose pose)
    {
        if (pose.MotionFrames is null) return [];
        var moves = new List<string>();
        var count = Math.Min(setup.Parts.Count, pose.MotionFrames.Count);
        for (var i = 0; i < count; i++)
        {
            if (PlacementPose(pose.Placement, setup.Parts.Count, i) is not { } p) continue;
            var m = pose.MotionFrames[i];
            var metres = Vector3.Distance(p.Position, m.Position);
            // The angle between two rotations (a report, not a frame the client moves points with): unit quaternions compared.
            var dot = Math.Abs((double)Quaternion.Dot(Quaternion.Normalize(p.Rotation), Quaternion.Normalize(m.Rotation)));
            var degrees = (float)(2 * Math.Acos(Math.Min(1, dot)) * 180 / Math.PI);
            if (metres > MovedMetres || degrees > MovedDegrees)
                moves.Add(string.Create(CultureInfo.InvariantCulture, $"part {i} by {metres:0.###} m and {degrees:0.#} deg"));
        }
        return moves;
    }

    /// <summary>Where the placement pose puts part <paramref name="index"/>, or null when it gives it no pose.</summary>
    private static Frame? PlacementPose(PlacementFrame? placement, int partCount, int index) =>
        placement is { } frame ? (index < frame.Frames.Count ? frame.Frames[index] : null) : partCount == 1 ? Frame.Identity : null;
}
