using System.Numerics;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Tests.Dat;

/// <summary>
/// Setups whose placement frames carry animation hooks. Every hook's bytes below were worked out by hand from
/// the public layout (DatReaderWriter's dats.xml AnimationHook typeswitch, ACE's AnimationHooks classes):
/// <c>uint type, int direction</c>, then the payload, and no padding. Floats are spelled as their IEEE bits
/// (1.0 = 0x3F800000 → 00 00 80 3F). The Setup around them is laid out field by field here too (not by
/// Setup.Write), written into a real dat and read back, so a hook read one byte short or long shows up as a
/// wrong hook count, wrong CylSpheres, Spheres, Height or Radius.
/// </summary>
public class AnimationHookTests
{
    private const uint SetupId = 0x02000ABC;

    private static readonly CylSphere Cyl0 = new(new Vector3(0.25f, -0.5f, 0), 0.75f, 1.5f);
    private static readonly CylSphere Cyl1 = new(new Vector3(-1, 2, 0.125f), 0.3f, 2.25f);
    private static readonly Sphere Sphere0 = new(new Vector3(0, 0, 0.9f), 0.6f);
    private const float Height = 1.875f;
    private const float Radius = 1.0625f;

    /// <summary>One hook as stored: type, direction and payload, in hex (spaces ignored).</summary>
    private sealed record RawHook(string Hex)
    {
        public byte[] Bytes => Convert.FromHexString(Hex.Replace(" ", ""));
        public uint Type => BitConverter.ToUInt32(Bytes, 0);
        public int Direction => BitConverter.ToInt32(Bytes, 4);
        public byte[] Payload => Bytes[8..];
    }

    /// <summary>
    /// One hand-worked hook of every type: the bytes, and the field values they hold (as
    /// <see cref="AnimationHook.FieldText"/> writes them). Direction: 01000000 forward, 00000000 both,
    /// FFFFFFFF backward.
    /// </summary>
    public static readonly TheoryData<string, string, string> EveryType = new()
    {
        { "NoOp", "00000000 01000000", "" },
        { "Sound", "01000000 01000000 2301000A", "soundId=0x0A000123" },
        { "SoundTable", "02000000 00000000 07000000", "soundType=7" },
        { "Attack", "03000000 FFFFFFFF 02000000 0000803F 000000BF 0000003F 000000BF 00000040 0000C03F",
            "partIndex=2 leftX=1 leftY=-0.5 rightX=0.5 rightY=-0.5 radius=2 height=1.5" },
        { "AnimationDone", "04000000 01000000", "" },
        // ushort part index 300 = 0x012C, then GfxObj 0x01000456 as the short form: offset 0x0456 in one ushort.
        { "ReplaceObject", "05000000 01000000 2C01 5604", "partIndex=300 gfxObjId=0x01000456" },
        { "Ethereal", "06000000 01000000 01000000", "ethereal=true" },
        { "TransparentPart", "07000000 01000000 01000000 00000000 0000803F 0000003F", "partIndex=1 start=0 end=1 time=0.5" },
        { "Luminous", "08000000 00000000 0000803F 00000000 00000040", "start=1 end=0 time=2" },
        { "LuminousPart", "09000000 00000000 03000000 00000000 0000803E 0000803F", "partIndex=3 start=0 end=0.25 time=1" },
        { "Diffuse", "0A000000 01000000 0000003F 0000803F 00004040", "start=0.5 end=1 time=3" },
        { "DiffusePart", "0B000000 FFFFFFFF 00010000 0000803F 00000000 00008040", "partIndex=256 start=1 end=0 time=4" },
        { "Scale", "0C000000 01000000 0000C03F 0000003F", "end=1.5 time=0.5" },
        // Emitter info 0x32000010, part 1, Frame (origin 0.5, 0, 1; orientation W 1, X, Y, Z 0), emitter 7.
        { "CreateParticle", "0D000000 01000000 10000032 01000000 0000003F 00000000 0000803F 0000803F 00000000 00000000 00000000 07000000",
            "emitterInfoId=0x32000010 partIndex=1 offset=[0.5, 0, 1]@[1, 0, 0, 0] emitterId=7" },
        { "DestroyParticle", "0E000000 00000000 07000000", "emitterId=7" },
        { "StopParticle", "0F000000 00000000 08000000", "emitterId=8" },
        { "NoDraw", "10000000 01000000 00000000", "noDraw=false" },
        { "DefaultScript", "11000000 00000000", "" },
        { "DefaultScriptPart", "12000000 01000000 2C010000", "partIndex=300" },
        { "CallPES", "13000000 01000000 05000033 0000003F", "scriptId=0x33000005 pause=0.5" },
        { "Transparent", "14000000 FFFFFFFF 00000000 0000803F 00000040", "start=0 end=1 time=2" },
        { "SoundTweaked", "15000000 01000000 0002000A 0000003F 0000803E 0000803F", "soundId=0x0A000200 priority=0.5 probability=0.25 volume=1" },
        { "SetOmega", "16000000 00000000 00000000 00000000 0000C03F", "axis=[0, 0, 1.5]" },
        { "TextureVelocity", "17000000 01000000 0000003F 000080BF", "uSpeed=0.5 vSpeed=-1" },
        { "TextureVelocityPart", "18000000 01000000 2C010000 0000803E 00000000", "partIndex=300 uSpeed=0.25 vSpeed=0" },
        { "SetLight", "19000000 00000000 01000000", "lightsOn=true" },
        // ACE's layout (CreateParticle's payload): emitter info 0x32000011, part 0, identity Frame, emitter 8.
        { "CreateBlockingParticle", "1A000000 00000000 11000032 00000000 00000000 00000000 00000000 0000803F 00000000 00000000 00000000 08000000",
            "emitterInfoId=0x32000011 partIndex=0 offset=[0, 0, 0]@[1, 0, 0, 0] emitterId=8" },
    };

    /// <summary>ReplaceObject, long form: first ushort 0x8001 (top bit set, offset bits 16..29 = 1), then 0x2345.</summary>
    private static readonly RawHook ReplaceLong = new("05000000 00000000 0200 0180 4523"); // part 2 → GfxObj 0x01012345

    /// <summary>ReplaceObject, short form with the largest short offset, 0x7FFF.</summary>
    private static readonly RawHook ReplaceShortMax = new("05000000 FFFFFFFF 0000 FF7F"); // part 0 → GfxObj 0x01007FFF

    /// <summary>
    /// ReplaceObject, long form of a small offset (0x8000 | 0, then 0x4000): DatReaderWriter writes offsets from
    /// 0x4000 up this way, and every reader takes it.
    /// </summary>
    private static readonly RawHook ReplaceLongSmall = new("05000000 01000000 FF01 0080 0040"); // part 511 → GfxObj 0x01004000

    private static readonly RawHook Sound = new("01000000 01000000 2301000A");

    private static byte[] Bytes(Action<DatBinaryWriter> write)
    {
        var w = new DatBinaryWriter();
        write(w);
        return w.ToArray();
    }

    /// <summary>A two-part Setup laid out field by field, as the dat stores it.</summary>
    private static byte[] SetupBytes(params (uint Key, RawHook[] Hooks)[] placements) => Bytes(w =>
    {
        w.WriteUInt32(SetupId);
        w.WriteUInt32(0);                       // flags: no parent index, no default scale
        w.WriteUInt32(2);                       // parts
        w.WriteUInt32(0x01000456);
        w.WriteUInt32(0x01000457);
        w.WriteInt32(0);                        // holding locations
        w.WriteInt32(0);                        // connection points
        w.WriteInt32(placements.Length);
        foreach (var (key, hooks) in placements)
        {
            w.WriteUInt32(key);
            w.WriteFrame(Frame.Identity);
            w.WriteFrame(new Frame(new Vector3(0, 0, 1), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.5f)));
            w.WriteUInt32((uint)hooks.Length);
            foreach (var hook in hooks) w.WriteBytes(hook.Bytes);
        }
        w.WriteUInt32(2);
        Cyl0.Write(w);
        Cyl1.Write(w);
        w.WriteUInt32(1);
        Sphere0.Write(w);
        w.WriteSingle(Height);
        w.WriteSingle(Radius);
        w.WriteSingle(0.25f);                   // step up
        w.WriteSingle(0.5f);                    // step down
        new Sphere(new Vector3(0, 0, 1), 2).Write(w);
        new Sphere(new Vector3(0, 0, 1), 2.5f).Write(w);
        w.WriteInt32(0);                        // lights
        for (var i = 0; i < 5; i++) w.WriteUInt32(0); // default animation, script, motion, sound, script tables
    });

    private static DatDatabase Dat(byte[] setupBytes)
    {
        var bytes = DatArchiveWriter.Write(new Dictionary<uint, byte[]> { [SetupId] = setupBytes }, new DatArchiveWriter.Options(DatFileKind.Portal));
        return DatDatabase.Open(new MemoryStream(bytes), "hooks_portal.dat");
    }

    private static void AssertFieldsAfterHooks(Setup setup)
    {
        Assert.Equal([Cyl0, Cyl1], setup.CylSpheres);
        Assert.Equal([Sphere0], setup.Spheres);
        Assert.Equal(Height, setup.Height);
        Assert.Equal(Radius, setup.Radius);
        Assert.Equal(0.25f, setup.StepUpHeight);
        Assert.Equal(0.5f, setup.StepDownHeight);
        Assert.Equal(new Sphere(new Vector3(0, 0, 1), 2.5f), setup.SelectionSphere);
    }

    private static void AssertHooks(RawHook[] expected, IReadOnlyList<AnimationHook> actual)
    {
        Assert.Equal(expected.Length, actual.Count);
        for (var i = 0; i < expected.Length; i++)
        {
            Assert.Equal(expected[i].Type, (uint)actual[i].Type);
            Assert.Equal(expected[i].Direction, actual[i].Direction);
            Assert.Equal(expected[i].Payload, actual[i].Payload.ToArray());
        }
    }

    [Theory]
    [MemberData(nameof(EveryType))]
    public void Each_hook_type_reads_its_hand_worked_bytes_exactly(string type, string hex, string fields)
    {
        // The hook under test, then one more, in two placements: the second hook and the fields after the
        // placements only read right when the first hook took exactly its bytes.
        RawHook[] hooks = [new(hex), Sound];
        var original = SetupBytes((Placement.Default, hooks), (Placement.Resting, [new(hex)]));
        using var dat = Dat(original);

        var setup = dat.ReadSetup(SetupId)!;

        Assert.Equal(Enum.Parse<AnimationHookType>(type), setup.PlacementFrames[0].Hooks[0].Type);
        AssertHooks(hooks, setup.PlacementFrames[0].Hooks);
        AssertHooks([new(hex)], setup.PlacementFrames[1].Hooks);
        Assert.Equal(fields, setup.PlacementFrames[0].Hooks[0].FieldText());
        AssertFieldsAfterHooks(setup);
        Assert.Equal(original, Bytes(setup.Write));
    }

    [Fact]
    public void Every_hook_type_has_a_hand_worked_case()
    {
        var covered = EveryType.Select(row => Enum.Parse<AnimationHookType>((string)row[0])).Order();
        Assert.Equal(Enum.GetValues<AnimationHookType>().Order(), covered);
    }

    [Fact]
    public void Both_forms_of_the_ReplaceObject_id_are_read_and_the_next_hook_follows_unpadded()
    {
        // A long form leaves the next hook 2 bytes off a 4-byte boundary: it is read from there, not aligned.
        RawHook[] hooks = [ReplaceLong, Sound, ReplaceShortMax, ReplaceLongSmall, Sound];
        using var dat = Dat(SetupBytes((Placement.Resting, hooks)));
        var read = dat.ReadSetup(SetupId)!.PlacementFrames[0].Hooks;

        AssertHooks(hooks, read);
        Assert.Equal("partIndex=2 gfxObjId=0x01012345", read[0].FieldText());
        Assert.Equal("partIndex=0 gfxObjId=0x01007FFF", read[2].FieldText());
        Assert.Equal("partIndex=511 gfxObjId=0x01004000", read[3].FieldText());
    }

    [Fact]
    public void A_setup_with_hooks_writes_back_the_bytes_it_was_read_from()
    {
        var every = EveryType.Select(row => new RawHook((string)row[1])).ToArray();
        var original = SetupBytes((Placement.Default, every), (Placement.Resting, [ReplaceLong, ReplaceShortMax]), (0x11u, []));
        using var dat = Dat(original);
        var setup = dat.ReadSetup(SetupId)!;

        Assert.Equal(original, Bytes(setup.Write));
        AssertFieldsAfterHooks(setup);
    }

    [Fact]
    public void Hooks_built_in_memory_survive_a_dat_round_trip()
    {
        var hooks = new[]
        {
            new AnimationHook(AnimationHookType.ReplaceObject, -1, ReplaceLong.Payload),
            new AnimationHook(AnimationHookType.NoDraw, 0, [1, 0, 0, 0]),
            new AnimationHook(AnimationHookType.ReplaceObject, 1, ReplaceShortMax.Payload),
        };
        var placement = new PlacementFrame(Placement.Resting, [Frame.Identity]) { Hooks = hooks };
        var setup = new Setup(SetupId, SetupFlags.None, [0x01000456], [], [], [placement], [Cyl0, Cyl1], [Sphere0],
            Height, Radius, 0.25f, 0.5f, default, new Sphere(new Vector3(0, 0, 1), 2.5f));

        using var dat = Dat(Bytes(setup.Write));
        var read = dat.ReadSetup(SetupId)!;

        Assert.Equal(hooks, read.PlacementFrames[0].Hooks);
        AssertFieldsAfterHooks(read);
    }

    [Fact]
    public void A_placement_without_hooks_has_an_empty_list()
    {
        using var dat = Dat(SetupBytes((Placement.Default, [])));
        Assert.Empty(dat.ReadSetup(SetupId)!.PlacementFrames[0].Hooks);
        Assert.Empty(new PlacementFrame(Placement.Default, [Frame.Identity]).Hooks);
    }

    [Theory]
    [InlineData(27u, "0x0000001B")]
    [InlineData(0xFFFFFFFFu, "0xFFFFFFFF")]
    public void An_unknown_hook_type_is_refused_naming_setup_placement_and_type(uint type, string hex)
    {
        RawHook[] hooks = [Sound, new($"{Convert.ToHexString(BitConverter.GetBytes(type))} 00000000 00000000")];
        using var dat = Dat(SetupBytes((Placement.Default, []), (Placement.Resting, hooks)));

        var e = Assert.Throws<DatFormatException>(() => dat.ReadSetup(SetupId));

        Assert.Contains("Setup 0x02000ABC", e.Message);
        Assert.Contains("placement Resting", e.Message);
        Assert.Contains("hook 2 of 2", e.Message);
        Assert.Contains($"type {type} ({hex})", e.Message);
    }

    [Fact]
    public void A_setup_cut_inside_a_hook_payload_is_refused_not_misread()
    {
        var particle = new RawHook((string)EveryType.Single(row => (string)row[0] == "CreateParticle")[1]);
        var bytes = SetupBytes((Placement.Resting, [particle]));
        var hookStart = 4 * 3 + 8 + 4 * 3 + 4 + 2 * 28 + 4;
        using var dat = Dat(bytes[..(hookStart + 8 + 20)]);

        Assert.Throws<DatFormatException>(() => dat.ReadSetup(SetupId));
    }

    [Fact]
    public void A_setup_cut_inside_a_long_form_id_is_refused_not_misread()
    {
        var bytes = SetupBytes((Placement.Resting, [ReplaceLong]));
        var hookStart = 4 * 3 + 8 + 4 * 3 + 4 + 2 * 28 + 4;
        using var dat = Dat(bytes[..(hookStart + 8 + 4)]); // part index and the first ushort of the id, not the second

        Assert.Throws<DatFormatException>(() => dat.ReadSetup(SetupId));
    }

    [Fact]
    public void A_hook_whose_payload_does_not_fit_its_type_cannot_be_made()
    {
        Assert.Throws<ArgumentException>(() => new AnimationHook(AnimationHookType.ReplaceObject, 0, [0x02, 0x00, 0x01, 0x80])); // long form, 2 bytes short
        Assert.Throws<ArgumentException>(() => new AnimationHook(AnimationHookType.ReplaceObject, 0, [0x02, 0x00, 0x56, 0x04, 0, 0])); // short form, 2 bytes long
        Assert.Throws<ArgumentException>(() => new AnimationHook(AnimationHookType.ReplaceObject, 0, [0x02, 0x56, 0x04])); // the old byte-index layout
        Assert.Throws<ArgumentException>(() => new AnimationHook(AnimationHookType.Sound, 0, [1, 2, 3]));
        Assert.Throws<ArgumentException>(() => new AnimationHook((AnimationHookType)27, 0, []));
    }

    [Theory]
    [InlineData(0x01000000u, "0000")]
    [InlineData(0x01007FFFu, "FF7F")]
    [InlineData(0x01008000u, "00800080")]
    [InlineData(0x01012345u, "01804523")]
    [InlineData(0x40FFFFFFu, "FFBFFFFF")]
    public void Packed_GfxObj_ids_are_written_as_the_public_readers_read_them(uint id, string hex)
    {
        var bytes = Bytes(w => w.WritePackedDataId(id, AnimationHookField.GfxObjBase));

        Assert.Equal(hex, Convert.ToHexString(bytes));
        Assert.Equal(id, new DatBinaryReader(bytes).ReadPackedDataId(AnimationHookField.GfxObjBase));
    }

    [Theory]
    [InlineData(0x00FFFFFFu)]
    [InlineData(0x41000000u)]
    public void A_GfxObj_id_the_packed_form_cannot_hold_is_refused(uint id) =>
        Assert.Throws<ArgumentOutOfRangeException>(() => Bytes(w => w.WritePackedDataId(id, AnimationHookField.GfxObjBase)));
}
