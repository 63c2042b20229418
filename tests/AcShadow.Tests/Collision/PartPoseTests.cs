using System.Numerics;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Tests.Collision;

/// <summary>
/// A part's pose moves the probe sphere as SPHEREPATH::cache_localspace_sphere does: Frame::globaltolocal with the
/// matrix from the stored quaternion, then times the float 1 / scale. Expected values are float bit patterns worked
/// out by hand (the matrix entries are derived in ClientFrameMatrixTests).
/// </summary>
public class PartPoseTests
{
    // The dat's 90 degrees about Z: W = Z = 0.70710677f, not unit length; m0 = m4 = 0x331302AE, m1 = 0x3F7FFFFF.
    private static readonly float Half = BitConverter.UInt32BitsToSingle(0x3F3504F3);
    private static readonly PartPose Pose = new(Vector3.Zero, new Quaternion(0f, 0f, Half, Half), 2f);

    [Fact]
    public void The_sphere_goes_through_the_transpose_then_halves_exactly()
    {
        // globaltolocal(0, 1, 0) = (m1, m4, m7) = (0x3F7FFFFF, 0x331302AE, 0); times 0.5 lowers each exponent by one.
        var (center, radius) = Pose.ToLocal(Vector3.UnitY, 1f);
        Assert.Equal(new uint[] { 0x3EFFFFFF, 0x329302AE, 0 }, Bits(center));
        Assert.Equal(0x3F000000u, BitConverter.SingleToUInt32Bits(radius));
    }

    [Fact]
    public void A_local_point_is_scaled_before_the_matrix()
    {
        // (0.5, 0, 0) scaled by 2 is the x axis; localtoglobal gives (m0, m1, m2), not the normalised (0, 1, 0).
        Assert.Equal(new uint[] { 0x331302AE, 0x3F7FFFFF, 0 }, Bits(Pose.ToEntity(new Vector3(0.5f, 0f, 0f))));
    }

    [Fact]
    public void A_part_in_its_entity_holds_the_rotation_set_rotate_makes()
    {
        // CPartArray::UpdateParts places a part by Frame::combine, whose Frame::set_rotate normalises: the dat's quarter turn
        // comes back as stored (ClientFrameMatrixTests), while four components of 0.49999997 (0.5 - 2^-25) have the sum of
        // squares 1 - 2^-23 + 2^-48, inverse length 1 + 2^-24 + ..., and each product 0.5 - about 2^-49 rounds to 0.5.
        Assert.Equal(Pose.Rotation, PartPose.InEntity(Vector3.Zero, Pose.Rotation, 2f).Rotation);
        var q = BitConverter.UInt32BitsToSingle(0x3EFFFFFF);
        Assert.Equal(new Quaternion(0.5f, 0.5f, 0.5f, 0.5f), PartPose.InEntity(Vector3.Zero, new Quaternion(q, q, q, q), 1f).Rotation);
    }

    private static uint[] Bits(Vector3 v) =>
        [BitConverter.SingleToUInt32Bits(v.X), BitConverter.SingleToUInt32Bits(v.Y), BitConverter.SingleToUInt32Bits(v.Z)];
}
