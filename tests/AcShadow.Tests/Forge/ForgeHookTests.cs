using AcShadow.Forge;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Poses;
using AcShadow.Forging;
using AcShadow.Forging.Spec;
using AcShadow.Tests.Support;
using static AcShadow.Forge.SampleSpecAuthor;

namespace AcShadow.Tests.Forge;

/// <summary>The forge writes animation hooks from the spec, and the sample's placement frames carry every type.</summary>
public sealed class ForgeHookTests
{
    [Fact]
    public void The_sample_double_door_carries_every_hook_type_the_public_readers_define()
    {
        using var portal = SampleDat.OpenPortal();
        var door = portal.ReadSetup(DoubleDoorSetup)!;

        var types = door.PlacementFrames.SelectMany(p => p.Hooks).Select(h => h.Type).Distinct().Order();
        Assert.Equal(Enum.GetValues<AnimationHookType>().Where(t => t != AnimationHookType.NoOp).Order(), types);
        Assert.Equal([-1, 0, 1], door.PlacementFrames.SelectMany(p => p.Hooks).Select(h => h.Direction).Distinct().Order());
    }

    [Fact]
    public void The_sample_ReplaceObject_hooks_hold_both_packed_forms_and_part_indexes_above_255()
    {
        using var portal = SampleDat.OpenPortal();
        var replaces = portal.ReadSetup(DoubleDoorSetup)!.PlacementFrames.SelectMany(p => p.Hooks)
            .Where(h => h.Type == AnimationHookType.ReplaceObject).Select(h => Convert.ToHexString(h.Payload.Span)).ToArray();

        // By hand: ushort part index, then the GfxObj's offset from 0x01000000, short (one ushort) up to 0x7FFF,
        // else 0x8000 | bits 16..29 and a second ushort with bits 0..15.
        Assert.Equal(
        [
            "0000" + "0080" + "0080", // Resting (first in the dat): part 0, 0x01008000: long, the smallest long offset
            "2C01" + "210B",         // Default: part 300, 0x01000B21: short
            "0200" + "0080" + "DEC0", // Default: part 2, 0x0100C0DE: long
        ], replaces);
    }

    [Fact]
    public void The_double_door_with_its_hooks_dumps_the_committed_shapes_with_no_diagnostic_but_its_motion_tables()
    {
        using var output = new TempDir();
        var run = CliRun.Of("dump", "--setup", $"0x{DoubleDoorSetup:X8}", "--out", output.Path);

        Assert.Equal(0, run.ExitCode);
        // The sample gives this door's catalog table no default cycle on purpose: those two pose diagnostics
        // are the only ones; nothing about its hooks.
        Assert.Equal([PoseDiagnosticCodes.NoDefaultState, PoseDiagnosticCodes.DoorMotion],
            run.ErrorLines.Where(l => l.StartsWith($"warning: 0x{DoubleDoorSetup:X8}: ", StringComparison.Ordinal)).Select(l => l.Split(": ")[2]));
        Assert.Equal(2, run.ErrorLines.Count(l => l.Contains("warning")));
        Assert.Contains("2 diagnostic(s)", run.Out);
        foreach (var file in output.Files())
            Assert.Equal(File.ReadAllText(Path.Combine(RepoFixtures, file)), File.ReadAllText(Path.Combine(output.Path, file)));
    }

    private static string RepoFixtures
    {
        get
        {
            for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
                if (File.Exists(Path.Combine(dir.FullName, "AcShadow.sln"))) return Path.Combine(dir.FullName, "fixtures");
            throw new DirectoryNotFoundException("no AcShadow.sln above the test binaries");
        }
    }

    private static string Spec(string hooks) => $$"""
        {
          "gfxObjs": [ { "id": "0x01000001", "physics": true, "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]], "polygons": [ { "vertices": [0,1,2,3] } ] } ],
          "setups": [ { "id": "0x02000010", "parts": ["0x01000001"], "placements": { "Resting": [ {} ] }, "hooks": { {{hooks}} } } ]
        }
        """;

    private static string Error(string hooks)
    {
        var e = Assert.Throws<SpecException>(() => SpecCompiler.Compile(SpecJson.Parse(Spec(hooks))));
        Assert.DoesNotContain('\n', e.Message);
        return e.Message;
    }

    [Fact]
    public void A_spec_hook_is_written_with_its_fields_in_the_public_layout()
    {
        var dats = SpecCompiler.Compile(SpecJson.Parse(Spec("""
            "Resting": [
              { "type": "ReplaceObject", "direction": "Both", "fields": { "partIndex": 65535, "gfxObjId": "0x0100FFFF" } },
              { "type": "NoOp" },
              { "type": "SoundTweaked", "direction": "Backward", "fields": { "soundId": "0x0A000001", "priority": 1, "probability": 0.5, "volume": 2 } }
            ]
            """)));
        using var dat = DatDatabase.Open(new MemoryStream(dats.Portal), "client_portal.dat");
        var hooks = dat.ReadSetup(0x02000010)!.PlacementFrames[0].Hooks;

        Assert.Equal(
        [
            "05000000" + "00000000" + "FFFF" + "0080" + "FFFF",
            "00000000" + "01000000",
            "15000000" + "FFFFFFFF" + "0100000A" + "0000803F" + "0000003F" + "00000040",
        ], hooks.Select(h => Convert.ToHexString(Bytes(h.Write))));
    }

    private static byte[] Bytes(Action<DatBinaryWriter> write)
    {
        var w = new DatBinaryWriter();
        write(w);
        return w.ToArray();
    }

    [Theory]
    [InlineData("""{ "type": "Explode" }""", "hooks \"Resting\"[0]: hook type \"Explode\" is not one of")]
    [InlineData("""{ "type": "5" }""", "hook type \"5\" is not one of")]
    [InlineData("""{ "type": "Sound" }""", "hooks \"Resting\"[0]: Sound needs field \"soundId\" (its fields are soundId)")]
    [InlineData("""{ "type": "Scale", "fields": { "end": 1, "time": 2, "start": 0 } }""", "Scale has no field \"start\"; its fields are end, time")]
    [InlineData("""{ "type": "AnimationDone", "fields": { "x": 1 } }""", "AnimationDone has no field \"x\"; its fields are none")]
    [InlineData("""{ "type": "ReplaceObject", "fields": { "partIndex": 65536, "gfxObjId": "0x01000001" } }""", "partIndex: expected a whole number from 0 to 65535")]
    [InlineData("""{ "type": "ReplaceObject", "fields": { "partIndex": 1, "gfxObjId": "0x02000001" } }""", "gfxObjId: 0x02000001 is outside the GfxObj range")]
    [InlineData("""{ "type": "Sound", "fields": { "soundId": 5 } }""", "soundId: expected a hex id like")]
    [InlineData("""{ "type": "Ethereal", "fields": { "ethereal": 1 } }""", "ethereal: expected true or false")]
    [InlineData("""{ "type": "Scale", "direction": "Sideways", "fields": { "end": 1, "time": 2 } }""", "direction \"Sideways\" is not Forward, Backward or Both")]
    [InlineData("""{ "type": "SetOmega", "fields": { "axis": [0, 1] } }""", "axis: expected [x, y, z]")]
    [InlineData("""{ "type": "CreateParticle", "fields": { "emitterInfoId": "0x32000001", "partIndex": 0, "emitterId": 1, "offset": { "origin": [0, 0, 0], "orientation": { "w": 2, "x": 0, "y": 0, "z": 0 } } } }""", "offset orientation: quaternion length is 2, not 1")]
    public void A_bad_hook_is_refused_naming_it_and_the_fix(string hook, string expected) =>
        Assert.Contains(expected, Error($"\"Resting\": [ {hook} ]"));

    [Fact]
    public void Hooks_for_a_placement_the_setup_does_not_have_are_refused() =>
        Assert.Equal("setups[0] (0x02000010): hooks names placement \"Default\", which is not one of its placements; hooks belong to a placement's frame",
            Error("\"Default\": [ { \"type\": \"AnimationDone\" } ]"));
}
