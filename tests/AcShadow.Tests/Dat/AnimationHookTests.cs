using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Dat;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Tests.Dat;

/// <summary>
/// Setups whose placement frames carry animation hooks. The Setup bytes are spelled out by hand here (not by
/// Setup.Write), written into a real dat and read back, so a hook read one byte short or long shows up as wrong
/// CylSpheres, Spheres, Height or Radius.
/// </summary>
public class AnimationHookTests
{
    private const uint SetupId = 0x02000ABC;

    private static readonly CylSphere Cyl0 = new(new Vector3(0.25f, -0.5f, 0), 0.75f, 1.5f);
    private static readonly CylSphere Cyl1 = new(new Vector3(-1, 2, 0.125f), 0.3f, 2.25f);
    private static readonly Sphere Sphere0 = new(new Vector3(0, 0, 0.9f), 0.6f);
    private const float Height = 1.875f;
    private const float Radius = 1.0625f;

    /// <summary>One hook: its type and direction, the payload, and the zero padding to a multiple of 4.</summary>
    private sealed record RawHook(uint Type, int Direction, byte[] Payload);

    /// <summary>Payload sizes per type, as the layouts spell them (Frame = 3 floats + 4 floats = 28 bytes).</summary>
    private static readonly Dictionary<AnimationHookType, int> PayloadSizes = new()
    {
        [AnimationHookType.NoOp] = 0,
        [AnimationHookType.Sound] = 4,
        [AnimationHookType.SoundTable] = 4,
        [AnimationHookType.Attack] = 4 + 6 * 4,
        [AnimationHookType.AnimationDone] = 0,
        [AnimationHookType.ReplaceObject] = 1 + 2,
        [AnimationHookType.Ethereal] = 4,
        [AnimationHookType.TransparentPart] = 4 + 3 * 4,
        [AnimationHookType.Luminous] = 3 * 4,
        [AnimationHookType.LuminousPart] = 4 + 3 * 4,
        [AnimationHookType.Diffuse] = 3 * 4,
        [AnimationHookType.DiffusePart] = 4 + 3 * 4,
        [AnimationHookType.Scale] = 2 * 4,
        [AnimationHookType.CreateParticle] = 4 + 4 + 28 + 4,
        [AnimationHookType.DestroyParticle] = 4,
        [AnimationHookType.StopParticle] = 4,
        [AnimationHookType.NoDraw] = 4,
        [AnimationHookType.DefaultScript] = 0,
        [AnimationHookType.DefaultScriptPart] = 4,
        [AnimationHookType.CallPES] = 4 + 4,
        [AnimationHookType.Transparent] = 3 * 4,
        [AnimationHookType.SoundTweaked] = 4 + 3 * 4,
        [AnimationHookType.SetOmega] = 3 * 4,
        [AnimationHookType.TextureVelocity] = 2 * 4,
        [AnimationHookType.TextureVelocityPart] = 4 + 2 * 4,
        [AnimationHookType.SetLight] = 4,
        [AnimationHookType.CreateBlockingParticle] = 4 + 4 + 28 + 4,
    };

    private static byte[] Bytes(Action<DatBinaryWriter> write)
    {
        var w = new DatBinaryWriter();
        write(w);
        return w.ToArray();
    }

    private static byte[] ParticlePayload(uint emitterInfo, uint part, uint emitterId) => Bytes(w =>
    {
        w.WriteUInt32(emitterInfo);
        w.WriteUInt32(part);
        w.WriteVector3(new Vector3(0.1f, 0.2f, 0.3f));
        w.WriteQuaternion(Quaternion.Identity);
        w.WriteUInt32(emitterId);
    });

    /// <summary>ReplaceObject, short form: part index byte, then the GfxObj id minus 0x01000000 in one ushort.</summary>
    private static readonly byte[] ReplaceShort = [2, 0x56, 0x04]; // part 2 → GfxObj 0x01000456

    /// <summary>ReplaceObject, long form: top bit of the first ushort set, id bits 16..29 there, bits 0..15 in a second ushort.</summary>
    private static readonly byte[] ReplaceLong = [1, 0x01, 0x80, 0x45, 0x23]; // part 1 → GfxObj 0x01012345

    private static readonly RawHook[] DefaultHooks =
    [
        new(1, 1, Bytes(w => w.WriteUInt32(0x0A000123))),                 // Sound
        new(5, 0, ReplaceShort),                                          // ReplaceObject, 2-byte id: 11 bytes + 1 pad
        new(6, -1, Bytes(w => w.WriteUInt32(1))),                         // Ethereal
        new(5, 1, ReplaceLong),                                           // ReplaceObject, 4-byte id: 13 bytes + 3 pad
        new(13, 1, ParticlePayload(0x32000010, 1, 7)),                    // CreateParticle
    ];

    private static readonly RawHook[] RestingHooks =
    [
        new(5, -1, ReplaceLong),                                          // first hook of the frame is the unaligned one
        new(26, 0, ParticlePayload(0x32000011, 0, 8)),                    // CreateBlockingParticle
        new(4, 0, []),                                                    // AnimationDone
        new(3, 1, Bytes(w => { w.WriteUInt32(1); for (var i = 0; i < 6; i++) w.WriteSingle(i * 0.5f); })), // Attack
        new(22, 0, Bytes(w => w.WriteVector3(new Vector3(0, 0, 1.5f)))), // SetOmega
        new(21, 1, Bytes(w => { w.WriteUInt32(0x0A000200); w.WriteSingle(0.5f); w.WriteSingle(0.9f); w.WriteSingle(0.8f); })), // SoundTweaked
        new(5, 0, ReplaceShort),                                          // and a short one last, right before the CylSpheres
    ];

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
            Frame.Identity.Write(w);
            new Frame(new Vector3(0, 0, 1), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.5f)).Write(w);
            w.WriteUInt32((uint)hooks.Length);
            foreach (var hook in hooks)
            {
                w.WriteUInt32(hook.Type);
                w.WriteInt32(hook.Direction);
                w.WriteBytes(hook.Payload);
                for (var pad = (8 + hook.Payload.Length) % 4; pad is > 0 and < 4; pad++) w.WriteByte(0);
            }
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

    [Fact]
    public void Hooks_of_several_types_are_stepped_over_byte_exactly()
    {
        using var dat = Dat(SetupBytes((Placement.Default, DefaultHooks), (Placement.Resting, RestingHooks)));
        var setup = dat.ReadSetup(SetupId)!;

        AssertFieldsAfterHooks(setup);
        Assert.Equal([Placement.Default, Placement.Resting], setup.PlacementFrames.Select(p => p.Placement));
        AssertHooks(DefaultHooks, setup.PlacementFrames[0].Hooks);
        AssertHooks(RestingHooks, setup.PlacementFrames[1].Hooks);
        Assert.Equal(new Vector3(0, 0, 1), setup.FindPlacement(Placement.Resting)!.Frames[1].Origin);
    }

    [Fact]
    public void Both_forms_of_the_ReplaceObject_part_id_are_kept()
    {
        using var dat = Dat(SetupBytes((Placement.Default, DefaultHooks)));
        var hooks = dat.ReadSetup(SetupId)!.PlacementFrames[0].Hooks.Where(h => h.Type == AnimationHookType.ReplaceObject).ToArray();

        Assert.Equal(2, hooks.Length);
        Assert.Equal(ReplaceShort, hooks[0].Payload.ToArray());
        Assert.Equal(ReplaceLong, hooks[1].Payload.ToArray());
    }

    [Fact]
    public void Every_known_hook_type_has_the_documented_length()
    {
        Assert.Equal(Enum.GetValues<AnimationHookType>().Order(), PayloadSizes.Keys.Order());
        var all = PayloadSizes
            .Select(kv => new RawHook((uint)kv.Key, 1, kv.Key == AnimationHookType.ReplaceObject
                ? ReplaceShort
                : Enumerable.Range(1, kv.Value).Select(b => (byte)b).ToArray()))
            .ToArray();

        using var dat = Dat(SetupBytes((Placement.Resting, all)));
        var setup = dat.ReadSetup(SetupId)!;

        AssertHooks(all, setup.PlacementFrames[0].Hooks);
        AssertFieldsAfterHooks(setup);
    }

    [Fact]
    public void A_setup_with_hooks_writes_back_the_bytes_it_was_read_from()
    {
        var original = SetupBytes((Placement.Default, DefaultHooks), (Placement.Resting, RestingHooks), (0x11u, []));
        using var dat = Dat(original);
        var setup = dat.ReadSetup(SetupId)!;

        var written = Bytes(setup.Write);

        Assert.Equal(original, written);
    }

    [Fact]
    public void Hooks_built_in_memory_survive_a_dat_round_trip()
    {
        var hooks = new[]
        {
            new AnimationHook(AnimationHookType.ReplaceObject, -1, ReplaceLong),
            new AnimationHook(AnimationHookType.NoDraw, 0, Bytes(w => w.WriteUInt32(1))),
            new AnimationHook(AnimationHookType.ReplaceObject, 1, ReplaceShort),
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
        RawHook[] hooks = [new(1, 1, Bytes(w => w.WriteUInt32(5))), new(type, 0, Bytes(w => w.WriteUInt32(0)))];
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
        var bytes = SetupBytes((Placement.Resting, [new(13, 1, ParticlePayload(0x32000010, 1, 7))]));
        var hookStart = 4 * 3 + 8 + 4 * 3 + 4 + 2 * 28 + 4;
        using var dat = Dat(bytes[..(hookStart + 8 + 20)]);

        Assert.Throws<DatFormatException>(() => dat.ReadSetup(SetupId));
    }

    [Fact]
    public void A_hook_whose_payload_does_not_fit_its_type_cannot_be_made()
    {
        Assert.Throws<ArgumentException>(() => new AnimationHook(AnimationHookType.ReplaceObject, 0, [1, 0x01, 0x80])); // long form, 2 bytes short
        Assert.Throws<ArgumentException>(() => new AnimationHook(AnimationHookType.ReplaceObject, 0, [1, 0x01, 0x00, 0, 0])); // short form, 2 bytes long
        Assert.Throws<ArgumentException>(() => new AnimationHook(AnimationHookType.Sound, 0, [1, 2, 3]));
        Assert.Throws<ArgumentException>(() => new AnimationHook((AnimationHookType)27, 0, []));
    }
}
