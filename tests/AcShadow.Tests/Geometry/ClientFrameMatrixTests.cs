using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Tests.Geometry;

/// <summary>
/// The client's frame arithmetic (Frame::cache, Frame::localtoglobal, Frame::globaltolocal) against values worked
/// out outside the code under test: each x87 operation rounded as an IEEE double (the client runs the x87 at 53-bit
/// precision), each float store rounded to single precision. Expected values are float bit patterns.
/// </summary>
public class ClientFrameMatrixTests
{
    // The dat's 90 degrees about Z: W = Z = 0.70710677f = 0x3F3504F3 = 11863283 * 2^-24 (not unit length).
    private static readonly float Half = BitConverter.UInt32BitsToSingle(0x3F3504F3);

    [Fact]
    public void Ninety_degrees_about_z_keeps_the_stored_components()
    {
        // d2 = 2qz = 11863283 * 2^-23; zd = qz*d2 = wd = 11863283^2 * 2^-47 = 1 - 4817239 * 2^-47, exact in double.
        // m0 = m4 = 1 - zd = 4817239 * 2^-47 (exact as a float: 0x331302AE, about 3.42e-8, not 0).
        // m1 = xc + wd = wd, rounded to float: 1 - 0.574 * 2^-24 rounds to 1 - 2^-24 = 0x3F7FFFFF; m3 = -wd = 0xBF7FFFFF.
        // m8 = (1 - 0) - 0 = 1; m2, m5, m6, m7 are sums and differences of zeros = +0.
        var m = ClientFrameMatrix.From(new Frame(Vector3.Zero, new Quaternion(0f, 0f, Half, Half)));
        Assert.Equal(
            new uint[] { 0x331302AE, 0x3F7FFFFF, 0, 0xBF7FFFFF, 0x331302AE, 0, 0, 0, 0x3F800000 },
            Bits(m.M0, m.M1, m.M2, m.M3, m.M4, m.M5, m.M6, m.M7, m.M8));

        // The x axis goes to (m0, m1, m2) = (3.42e-8, 0.99999994, 0), not (0, 1, 0); the y axis comes back to (m1, m4, m7).
        Assert.Equal(new uint[] { 0x331302AE, 0x3F7FFFFF, 0 }, Bits(m.LocalToGlobal(Vector3.UnitX)));
        Assert.Equal(new uint[] { 0x3F7FFFFF, 0x331302AE, 0 }, Bits(m.GlobalToLocal(Vector3.UnitY)));
    }

    [Fact]
    public void Ninety_degrees_about_z_with_an_origin_rounds_once_per_store()
    {
        // Origin (10.1f, 20, 30), point (1, 2, 3): x = 0*3 + m0*1 + m3*2 + 10.1f = 8.1f + 2^-23 + 3.42e-8 -> 0x4101999A (8.1f);
        // y = 0 + m1 + 2*m4 + 20 -> 21 (0x41A80000); z = 1*3 + 0 + 0 + 30 = 33 (0x42040000).
        var frame = new Frame(new Vector3(10.1f, 20f, 30f), new Quaternion(0f, 0f, Half, Half));
        var m = ClientFrameMatrix.From(frame);
        Assert.Equal(new uint[] { 0x4101999A, 0x41A80000, 0x42040000 }, Bits(m.LocalToGlobal(new Vector3(1f, 2f, 3f))));
        // Back: d = (1 - 10.1f, 2 - 20, 3 - 30) stored as floats = (-9.1f, -18, -27);
        // x = -27*0 + (-9.1f)*m0 + (-18)*m1 -> -18 (0xC1900000); y = (-9.1f)*m3 + (-18)*m4 -> 9.1f (0x41119999); z = -27.
        Assert.Equal(new uint[] { 0xC1900000, 0x41119999, 0xC1D80000 }, Bits(m.GlobalToLocal(new Vector3(1f, 2f, 3f))));
    }

    [Fact]
    public void Unnormalised_quaternion_matrix_and_points_match_hand_rounding()
    {
        // q = (W 0.9238795f, X 0.1f, Y -0.2f, Z 0.3f): |q|^2 = 0.9936, used as stored. Matrix entries as Frame::cache
        // forms them, each rounded to float once: m0 = 1 - 2yy - 2zz = 0.74f, m4 = 1 - 2xx - 2zz = 0.8f, m8 = 0.9f, ...
        var frame = new Frame(new Vector3(12.5f, -3.25f, 0.75f), new Quaternion(0.1f, -0.2f, 0.3f, 0.9238795f));
        var m = ClientFrameMatrix.From(frame);
        Assert.Equal(
            new uint[] { 0x3F3D70A4, 0x3F03AAFB, 0x3EDBEE37, 0xBF1825DD, 0x3F4CCCCD, 0x3D84A93A, 0xBE9E7D93, 0xBE9C0B97, 0x3F666666 },
            Bits(m.M0, m.M1, m.M2, m.M3, m.M4, m.M5, m.M6, m.M7, m.M8));

        Assert.Equal(new uint[] { 0x4153D70A, 0xC02F1541, 0x3F96FB8E }, Bits(m.LocalToGlobal(Vector3.UnitX)));
        Assert.Equal(new uint[] { 0x416D4C6A, 0xC08C91D0, 0x3FCB04BC }, Bits(m.LocalToGlobal(new Vector3(1.5f, -2.25f, 0.375f))));
        Assert.Equal(new uint[] { 0x42E064EB, 0x40DB62B4, 0x42500F31 }, Bits(m.LocalToGlobal(new Vector3(101.3f, -47.9f, 12.06f))));
        Assert.Equal(new uint[] { 0xC0EC5C55, 0x412C7CFD, 0x3FF315B5 }, Bits(m.GlobalToLocal(Vector3.UnitY)));
        Assert.Equal(new uint[] { 0xC0F92D17, 0x40EA06AC, 0x4030D19E }, Bits(m.GlobalToLocal(new Vector3(1.5f, -2.25f, 0.375f))));
        Assert.Equal(new uint[] { 0x423E6C09, 0xC2AF8703, 0xC06CDC75 }, Bits(m.GlobalToLocal(new Vector3(101.3f, -47.9f, 12.06f))));
    }

    [Fact]
    public void Global_to_local_z_uses_the_unrounded_offset_as_the_client_does()
    {
        // Origin z 0.003f, point z 57.77f: the offset 57.767f is not a float. Frame::globaltolocal stores it as a float
        // for x and y but keeps it on the x87 stack for z: z = 0x424D2670; rounding it first would give 0x424D2671.
        var frame = new Frame(new Vector3(0.001f, -0.002f, 0.003f), new Quaternion(0.1f, -0.2f, 0.3f, 0.9238795f));
        var local = ClientFrameMatrix.From(frame).GlobalToLocal(new Vector3(3.5f, -1.25f, 57.77f));
        Assert.Equal(new uint[] { 0x41D61724, 0x3F29F910, 0x424D2670 }, Bits(local));
    }

    private static uint[] Bits(Vector3 v) => Bits(v.X, v.Y, v.Z);

    private static uint[] Bits(params float[] values) => values.Select(BitConverter.SingleToUInt32Bits).ToArray();
}
