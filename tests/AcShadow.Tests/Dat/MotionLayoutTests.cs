using System.Numerics;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;

namespace AcShadow.Tests.Dat;

/// <summary>
/// MotionTable and Animation bytes written out by hand from the public layout (DatReaderWriter dats.xml
/// MotionTable/MotionData/AnimData/Animation/AnimationFrame; ACE DatLoader agrees), not by our writer.
/// </summary>
public class MotionLayoutTests
{
    // id 0x09000202, DefaultStyle NonCombat, StyleDefaults {NonCombat: Off}, one cycle (NonCombat, Off) whose
    // MotionData header sits at offset 28 (so one pad byte brings it to 32), with omega; no modifiers; one link
    // (NonCombat, Off) -> On whose MotionData header sits at 80 (one pad byte to 84), playing backwards.
    private static readonly byte[] Table =
    [
        0x02, 0x02, 0x00, 0x09,
        0x3D, 0x00, 0x00, 0x80,
        0x01, 0x00, 0x00, 0x00,
        0x3D, 0x00, 0x00, 0x80, 0x0C, 0x00, 0x00, 0x40,
        0x01, 0x00, 0x00, 0x00,
        0x0C, 0x00, 0x3D, 0x00,
        0x01, 0x05, 0x02, 0x00,
        0x00, 0x01, 0x00, 0x03, 0x00, 0x00, 0x00, 0x00, 0xFF, 0xFF, 0xFF, 0xFF, 0x00, 0x00, 0xF0, 0x41,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x80, 0x3F,
        0x00, 0x00, 0x00, 0x00,
        0x01, 0x00, 0x00, 0x00,
        0x0C, 0x00, 0x3D, 0x00,
        0x01, 0x00, 0x00, 0x00,
        0x0B, 0x00, 0x00, 0x40,
        0x01, 0x00, 0x00, 0x00,
        0x02, 0x01, 0x00, 0x03, 0x02, 0x00, 0x00, 0x00, 0x05, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0xC1,
    ];

    // id 0x03000100, flags PosFrames, 2 parts, 1 frame: PosFrame origin (1, 0, 0) identity; part 0 at
    // (0, -0.1, 0) identity, part 1 at (0, 0, 2) turned 180 deg about Z (W 0, Z 1); no hooks.
    private static readonly byte[] Anim =
    [
        0x00, 0x01, 0x00, 0x03, 0x01, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x80, 0x3F, 0, 0, 0, 0, 0, 0, 0, 0, 0x00, 0x00, 0x80, 0x3F, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
        0, 0, 0, 0, 0xCD, 0xCC, 0xCC, 0xBD, 0, 0, 0, 0, 0x00, 0x00, 0x80, 0x3F, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
        0, 0, 0, 0, 0, 0, 0, 0, 0x00, 0x00, 0x00, 0x40, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x00, 0x00, 0x80, 0x3F,
        0x00, 0x00, 0x00, 0x00,
    ];

    // id 0x03000200, no flags, 1 part, 2 frames. Frame 0: the part at (0, 0, 1) identity, then 2 hooks: a
    // ReplaceObject (type 5, forward) of part 0 by 0x0100C0DE in the long packed form (0x8000, then 0xC0DE: a
    // 6-byte payload that leaves what follows 2 bytes off a 4-byte boundary, unpadded), and an Ethereal (type 6,
    // backward -1) set true as a uint32. Frame 1: the part at (0, 0, 2) turned 90 deg about Z (W = Z = 0.70710677,
    // 0x3F3504F3), no hooks.
    private static readonly byte[] HookedAnim =
    [
        0x00, 0x02, 0x00, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00,
        0, 0, 0, 0, 0, 0, 0, 0, 0x00, 0x00, 0x80, 0x3F, 0x00, 0x00, 0x80, 0x3F, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
        0x02, 0x00, 0x00, 0x00,
        0x05, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x80, 0xDE, 0xC0,
        0x06, 0x00, 0x00, 0x00, 0xFF, 0xFF, 0xFF, 0xFF, 0x01, 0x00, 0x00, 0x00,
        0, 0, 0, 0, 0, 0, 0, 0, 0x00, 0x00, 0x00, 0x40, 0xF3, 0x04, 0x35, 0x3F, 0, 0, 0, 0, 0, 0, 0, 0, 0xF3, 0x04, 0x35, 0x3F,
        0x00, 0x00, 0x00, 0x00,
    ];

    [Fact]
    public void An_animation_frame_reads_its_hooks_exactly_by_type_and_the_next_frame_where_the_hooks_end()
    {
        var a = Animation.Read(new DatBinaryReader(HookedAnim));
        Assert.Equal(0x03000200u, a.Id);
        Assert.Null(a.PosFrames);
        Assert.Equal(2, a.PartFrames.Count);
        var first = a.PartFrames[0];
        Assert.Equal(new Vector3(0, 0, 1), Assert.Single(first.Frames).Position);
        Assert.Equal(
            [(AnimationHookType.ReplaceObject, 1, "partIndex=0 gfxObjId=0x0100C0DE"), (AnimationHookType.Ethereal, -1, "ethereal=true")],
            first.Hooks.Select(h => (h.Type, h.Direction, h.FieldText())));
        var second = Assert.Single(a.PartFrames[1].Frames);
        Assert.Equal(new Vector3(0, 0, 2), second.Position);
        Assert.Equal(new Quaternion(0, 0, 0.70710677f, 0.70710677f), second.Rotation);
        Assert.Empty(a.PartFrames[1].Hooks);

        var w = new DatBinaryWriter();
        a.Write(w);
        Assert.Equal(HookedAnim, w.ToArray());
    }

    [Fact]
    public void An_animation_whose_counts_multiply_past_any_size_is_refused_not_allocated()
    {
        // NumParts and NumFrames both 0x7FFFFFFF: their product of bytes overflows a 64-bit count.
        byte[] bytes = [0x00, 0x02, 0x00, 0x03, 0, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0x7F, 0xFF, 0xFF, 0xFF, 0x7F, 0, 0, 0, 0];
        var e = Assert.Throws<DatFormatException>(() => Animation.Read(new DatBinaryReader(bytes)));
        Assert.Contains("cannot fit", e.Message);
    }

    [Fact]
    public void A_hand_written_motion_table_reads_field_by_field_and_writes_back_byte_for_byte()
    {
        var t = MotionTable.Read(new DatBinaryReader(Table));
        Assert.Equal(0x09000202u, t.Id);
        Assert.Equal(MotionCommand.NonCombat, t.DefaultStyle);
        Assert.True(t.TryGetStyleDefault(MotionCommand.NonCombat, out var substate));
        Assert.Equal(MotionCommand.Off, substate);
        var cycle = t.FindCycle(MotionCommand.Key(MotionCommand.NonCombat, MotionCommand.Off))!;
        Assert.Equal(0x003D000Cu, MotionCommand.Key(MotionCommand.NonCombat, MotionCommand.Off));
        Assert.Equal(5, cycle.Bitfield);
        Assert.Equal([new AnimData(0x03000100, 0, -1, 30f)], cycle.Anims);
        Assert.Null(cycle.Velocity);
        Assert.Equal(new Vector3(0, 0, 1), cycle.Omega);
        Assert.Empty(t.Modifiers);
        var link = t.FindLink(0x003D000C, MotionCommand.On)!;
        Assert.Equal([new AnimData(0x03000102, 2, 5, -30f)], link.Anims);

        var w = new DatBinaryWriter();
        t.Write(w);
        Assert.Equal(Table, w.ToArray());
    }

    [Fact]
    public void A_hand_written_animation_reads_its_root_and_part_frames_and_writes_back_byte_for_byte()
    {
        var a = Animation.Read(new DatBinaryReader(Anim));
        Assert.Equal(0x03000100u, a.Id);
        Assert.Equal(2, a.NumParts);
        Assert.Equal(new Vector3(1, 0, 0), Assert.Single(a.PosFrames!).Position);
        var frame = Assert.Single(a.PartFrames);
        Assert.Equal(new Vector3(0, -0.1f, 0), frame.Frames[0].Position);
        Assert.Equal(Quaternion.Identity, frame.Frames[0].Rotation);
        Assert.Equal(new Vector3(0, 0, 2), frame.Frames[1].Position);
        Assert.Equal(new Quaternion(0, 0, 1, 0), frame.Frames[1].Rotation);
        Assert.Empty(frame.Hooks);

        var w = new DatBinaryWriter();
        a.Write(w);
        Assert.Equal(Anim, w.ToArray());
    }

    [Fact]
    public void A_setup_keeps_its_five_default_ids_in_dat_order()
    {
        var setup = Support.Records.Setup(0x02000001, [0x01000001]) with
        {
            DefaultAnimation = 0x03000001, DefaultScript = 0x33000002, DefaultMotionTable = 0x09000003, DefaultSoundTable = 0x20000004, DefaultScriptTable = 0x34000005,
        };
        var w = new DatBinaryWriter();
        setup.Write(w);
        var bytes = w.ToArray();
        // The Setup ends with the light count (0) and then the five ids, each a u32.
        Assert.Equal([0x01, 0x00, 0x00, 0x03, 0x02, 0x00, 0x00, 0x33, 0x03, 0x00, 0x00, 0x09, 0x04, 0x00, 0x00, 0x20, 0x05, 0x00, 0x00, 0x34], bytes[^20..]);
        var read = Setup.Read(new DatBinaryReader(bytes));
        Assert.Equal((0x03000001u, 0x33000002u, 0x09000003u, 0x20000004u, 0x34000005u),
            (read.DefaultAnimation, read.DefaultScript, read.DefaultMotionTable, read.DefaultSoundTable, read.DefaultScriptTable));
    }

    [Fact]
    public void A_cycle_count_the_bytes_cannot_hold_is_refused()
    {
        var bytes = (byte[])Table.Clone();
        bytes[20] = 0xFF;
        var e = Assert.Throws<DatFormatException>(() => MotionTable.Read(new DatBinaryReader(bytes)));
        Assert.Contains("cycle count 255", e.Message);
    }

    [Fact]
    public void A_cycle_key_listed_twice_is_refused()
    {
        var cycle = Table[24..60];
        byte[] bytes = [.. Table[..20], 0x02, 0x00, 0x00, 0x00, .. cycle, .. cycle, .. Table[60..]];
        var e = Assert.Throws<DatFormatException>(() => MotionTable.Read(new DatBinaryReader(bytes)));
        Assert.Contains("0x003D000C twice", e.Message);
    }

    [Fact]
    public void An_animation_whose_frames_cannot_fit_and_a_truncated_one_are_refused()
    {
        var huge = (byte[])Anim.Clone();
        huge[12] = 0xFF;
        huge[13] = 0xFF;
        Assert.Throws<DatFormatException>(() => Animation.Read(new DatBinaryReader(huge)));
        Assert.Throws<DatFormatException>(() => Animation.Read(new DatBinaryReader(Anim[..^6])));
    }
}
