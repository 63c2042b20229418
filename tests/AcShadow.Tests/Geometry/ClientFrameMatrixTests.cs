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

    [Fact]
    public void Set_rotate_leaves_the_dat_s_ninety_degrees_as_stored()
    {
        // Frame::set_rotate: w² + z² = 2 * 11863283² * 2^-48 = 1 - 4817239 * 2^-47 (exact in double, about 1 - 3.42e-8);
        // its square root rounds to about 1 - 1.71e-8, the inverse to about 1 + 1.71e-8;
        // w * inverse = 0.70710678118654757 (the double nearest 1/sqrt 2), whose nearest float is 0.70710677 again:
        // it lies 1.2e-8 above 0x3F3504F3 and 4.8e-8 below 0x3F3504F4.
        var q = ClientFrameMatrix.SetRotate(new Quaternion(0f, 0f, Half, Half));
        Assert.NotNull(q);
        Assert.Equal(new uint[] { 0x3F3504F3, 0, 0, 0x3F3504F3 }, Bits(q.Value.W, q.Value.X, q.Value.Y, q.Value.Z));
    }

    [Fact]
    public void Set_rotate_normalises_an_unnormalised_quaternion_in_the_client_s_arithmetic()
    {
        // q = (W 0.9238795f, X 0.1f, Y -0.2f, Z 0.3f): the double sum of squares 0.99355334693..., sqrt 0.99677146173...,
        // inverse 1.00323899548526...; each component times it, rounded to double then to float:
        // W 0.92687196 (0x3F6D477B), X 0.10032390 (0x3DCD769E), Y -0.20064780 (0xBE4D769E), Z 0.30097172 (0x3E9A18F7).
        var q = ClientFrameMatrix.SetRotate(new Quaternion(0.1f, -0.2f, 0.3f, 0.9238795f));
        Assert.NotNull(q);
        Assert.Equal(new uint[] { 0x3F6D477B, 0x3DCD769E, 0xBE4D769E, 0x3E9A18F7 }, Bits(q.Value.W, q.Value.X, q.Value.Y, q.Value.Z));
        Assert.Null(ClientFrameMatrix.SetRotate(default));
    }

    [Fact]
    public void A_placed_rotation_is_kept_as_stored_within_frame_is_valid_s_tolerance()
    {
        // Frame::IsValid: the float sum of squares within 0.0002f * 5 (0.00099999995) of 1.
        // W 0.9995f = 0x3F7FDF3B: W² = 0.99900019... stored as a float, 0.00099981 from 1: valid, kept as stored.
        Assert.Equal(0x3F7FDF3Bu, BitConverter.SingleToUInt32Bits(ClientFrameMatrix.PlacedRotation(new Quaternion(0f, 0f, 0f, 0.9995f)).W));
        // W 0.9994f = 0x3F7FD8AE: W² = 0.99880040, 0.0012 from 1: refused, so normalised as set_rotate does, to exactly 1.
        Assert.Equal(Quaternion.Identity, ClientFrameMatrix.PlacedRotation(new Quaternion(0f, 0f, 0f, 0.9994f)));
        // (0.1, -0.2, 0.3, 0.9238795): sum of squares 0.99355334 is refused too; the set_rotate bits of the test above.
        var q = ClientFrameMatrix.PlacedRotation(new Quaternion(0.1f, -0.2f, 0.3f, 0.9238795f));
        Assert.Equal(new uint[] { 0x3F6D477B, 0x3DCD769E, 0xBE4D769E, 0x3E9A18F7 }, Bits(q.W, q.X, q.Y, q.Z));
        // Nothing to normalise: the identity.
        Assert.Equal(Quaternion.Identity, ClientFrameMatrix.PlacedRotation(new Quaternion(float.NaN, 0f, 0f, 1f)));
    }

    [Fact]
    public void Combine_scales_the_part_origin_unrounded_and_normalises_the_product()
    {
        // Frame::combine(f1, AFrame f2, scale) with f1 = the unnormalised frame above (its matrix entries are the bits of
        // Unnormalised_quaternion_matrix_and_points_match_hand_rounding), f2 = origin (-2.83f, -0.21f, 2.66f), identity
        // rotation, scale 1.3f. f2's origin times the scale held as doubles: (-3.67899977, -0.27299998, 3.45799998).
        // z = sx*m2 + sz*m8 + sy*m5 + 0.75 = 2.26419508 -> 0x4010E892. Rounding the scaled origin to floats first and
        // summing in Frame::localtoglobal's order gives 2.26419509 -> 0x4010E893: the last bit tells the two apart.
        // x -> 8.8693619 (0x410DE8E8), y -> -6.4145265 (0xC0CD43CD).
        var outer = new Frame(new Vector3(12.5f, -3.25f, 0.75f), new Quaternion(0.1f, -0.2f, 0.3f, 0.9238795f));
        var part = ClientFrameMatrix.Combine(outer, new Frame(new Vector3(-2.83f, -0.21f, 2.66f), Quaternion.Identity), 1.3f);
        Assert.Equal(new uint[] { 0x410DE8E8, 0xC0CD43CD, 0x4010E892 }, Bits(part.Position));
        Assert.NotEqual(0x4010E892u, BitConverter.SingleToUInt32Bits(ClientFrameMatrix.From(outer).LocalToGlobal(new Vector3(-2.83f * 1.3f, -0.21f * 1.3f, 2.66f * 1.3f)).Z));
        // The product with the identity is f1's quaternion, which Frame::set_rotate then normalises (the bits above).
        Assert.Equal(new uint[] { 0x3F6D477B, 0x3DCD769E, 0xBE4D769E, 0x3E9A18F7 }, Bits(part.Rotation.W, part.Rotation.X, part.Rotation.Y, part.Rotation.Z));
    }

    [Fact]
    public void Combine_of_two_dat_quarter_turns_rounds_the_product_then_normalises_it()
    {
        // f1: 90 degrees about Z (W = Z = 0.70710677f), origin (10.1f, 20, 30); f2: 90 degrees about X (W = X = 0.70710677f),
        // origin (0.3f, -1.7f, 2.2f); scale 1.5f. Each product component is one term 0.70710677f² (the rest are zeros):
        // 11863283² * 2^-48 = 0.49999998289 (exact in double), stored as the float 0.49999997 (0x3EFFFFFF, 1.3e-8 away,
        // against 1.7e-8 to 0.5);
        // set_rotate's inverse length 1 / sqrt(4 * 0.49999997²) = 1.00000006, and 0.49999997 * 1.00000006 rounds to 0.5.
        // Origin: scaled (0.45, -2.55, 3.3); turned by the quarter turn about Z to (2.55, 0.45, 3.3); plus f1's origin:
        // (12.65, 20.45, 33.3) -> 0x414A6667, 0x41A3999A, 0x42053333.
        var outer = new Frame(new Vector3(10.1f, 20f, 30f), new Quaternion(0f, 0f, Half, Half));
        var part = ClientFrameMatrix.Combine(outer, new Frame(new Vector3(0.3f, -1.7f, 2.2f), new Quaternion(Half, 0f, 0f, Half)), 1.5f);
        Assert.Equal(new uint[] { 0x414A6667, 0x41A3999A, 0x42053333 }, Bits(part.Position));
        Assert.Equal(new uint[] { 0x3F000000, 0x3F000000, 0x3F000000, 0x3F000000 }, Bits(part.Rotation.W, part.Rotation.X, part.Rotation.Y, part.Rotation.Z));
    }

    [Fact]
    public void Directions_use_the_matrix_without_the_origin()
    {
        // Frame::localtoglobalvec of (1.5, -2.25, 0.375) by the unnormalised frame's matrix, z term first, then x, then y:
        // x = -0.30955181 * 0.375 + 0.74000001 * 1.5 + (-0.59432775) * (-2.25) = 2.3311555 (0x401531A7), y -> -1.1427995 (0xBF924741),
        // z -> 0.83608192 (0x3F560977); the same point through Frame::localtoglobal is this plus (12.5, -3.25, 0.75).
        var m = ClientFrameMatrix.From(new Frame(new Vector3(12.5f, -3.25f, 0.75f), new Quaternion(0.1f, -0.2f, 0.3f, 0.9238795f)));
        Assert.Equal(new uint[] { 0x401531A7, 0xBF924741, 0x3F560977 }, Bits(m.LocalToGlobalVec(new Vector3(1.5f, -2.25f, 0.375f))));
        // SPHEREPATH::cache_localspace_sphere's local up: (m1 + m0)*0 + m2 and so on, the matrix's third column (m2, m5, m8).
        Assert.Equal(new uint[] { 0x3EDBEE37, 0x3D84A93A, 0x3F666666 }, Bits(m.LocalUp()));
    }

    private static uint[] Bits(Vector3 v) => Bits(v.X, v.Y, v.Z);

    private static uint[] Bits(params float[] values) => values.Select(BitConverter.SingleToUInt32Bits).ToArray();
}
