using System.Numerics;
using AcShadow.Fixtures;

namespace AcShadow.Tests.Fixtures;

/// <summary>
/// A placed object's frame as the client holds it: Frame::UnPack and CPhysicsObj::set_initial_frame keep the stored
/// quaternion when Frame::IsValid accepts it; only a frame the client would refuse is normalised (as Frame::set_rotate
/// does). Expected values are float bits worked by hand (double per x87 operation, float at each store).
/// </summary>
public class PlacedFrameTests
{
    private static FixtureSet Committed => FixtureSet.Open(CommittedFixturesTests.RepositoryFixtures());

    [Fact]
    public void A_valid_stored_rotation_is_used_as_stored()
    {
        // (X 0.1f, Y -0.2f, Z 0.3f, W 0.9276f): the float sum of squares 1.00044179 is within 0.001 of 1, so it is kept
        // (normalising it would make W 0.92739516, 0x3F6D69C5). The world point (101.3, -47.9, 12.06) into the frame at
        // (12.5, -3.25, 0.75) by Frame::globaltolocal with that quaternion's matrix (m0 0.74f, m1 0x3F043D47, m2 0x3EDCB147,
        // m3 0xBF18B829, m4 0.8f, m5 0x3D862F5A, m6 0xBE9F40A3, m7 0xBE9C6D1F, m8 0.9f): (47.522659, -87.953506, -3.7998843).
        // The normalised quaternion would give (0x423E29DE, 0xC2AFDE66, 0xC072C3FF).
        var placed = Committed.Setup(0x020019FF).PlaceAt(new Vector3(12.5f, -3.25f, 0.75f), new Quaternion(0.1f, -0.2f, 0.3f, 0.9276f));
        Assert.Equal(0x3F6D7732u, BitConverter.SingleToUInt32Bits(placed.Rotation.W));
        Assert.Equal(new uint[] { 0x423E1734, 0xC2AFE832, 0xC073314E }, Bits(placed.ToEntity(new Vector3(101.3f, -47.9f, 12.06f))));
    }

    [Fact]
    public void A_rotation_the_client_would_refuse_is_normalised_as_set_rotate_does()
    {
        // (0.1f, -0.2f, 0.3f, 0.9238795f): sum of squares 0.99355334, outside Frame::IsValid's 0.001; set_rotate makes it
        // (W 0x3F6D477B, X 0x3DCD769E, Y 0xBE4D769E, Z 0x3E9A18F7), whose matrix takes the same world point to
        // (47.338203, -88.043434, -3.7983546). The stored quaternion's matrix would give (0x423E6C09, 0xC2AF8703, 0xC06CDC75).
        var placed = Committed.Setup(0x020019FF).PlaceAt(new Vector3(12.5f, -3.25f, 0.75f), new Quaternion(0.1f, -0.2f, 0.3f, 0.9238795f));
        Assert.Equal(new uint[] { 0x3F6D477B, 0x3DCD769E, 0xBE4D769E, 0x3E9A18F7 }, Bits(placed.Rotation.W, placed.Rotation.X, placed.Rotation.Y, placed.Rotation.Z));
        Assert.Equal(new uint[] { 0x423D5A52, 0xC2B0163D, 0xC073183E }, Bits(placed.ToEntity(new Vector3(101.3f, -47.9f, 12.06f))));
    }

    private static uint[] Bits(Vector3 v) => Bits(v.X, v.Y, v.Z);

    private static uint[] Bits(params float[] values) => values.Select(BitConverter.SingleToUInt32Bits).ToArray();
}
