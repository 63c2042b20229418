using AcShadow.Forge;
using AcShadow.Fixtures;
using System.Numerics;
using AcShadow.Cli.Infrastructure;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Movement;
using AcShadow.Forging;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Movement;

/// <summary>
/// `acshadow move` on the sample: the door's cases as a collision author gets them (the written file read back
/// through the consumer reader, its BSPs from the gfxobjs/ beside it), their outcomes, and the same bytes
/// whatever the thread count.
/// </summary>
public sealed class MoveCommandTests : IClassFixture<MoveCommandTests.DoorSuite>
{
    /// <summary>The sample door's suite written once by `move --setup 0x020019FF --jobs 2`.</summary>
    public sealed class DoorSuite : IDisposable
    {
        public TempDir Dir { get; } = new();
        public CliRun Run { get; }

        public DoorSuite() => Run = CliRun.Of("move", "--setup", "0x020019FF", "--jobs", "2", "--out", Dir.Path);

        public string FilePath => Path.Combine(Dir.Path, "movement", "0x020019FF.movement.json");

        public MovementSuite Read() => FixtureSet.Open(Dir.Path).Movement(0x020019FF);

        public void Dispose() => Dir.Dispose();
    }

    private readonly DoorSuite _door;

    public MoveCommandTests(DoorSuite door) => _door = door;

    /// <summary>Head-on and 0.45 m off-centre (either side, from either side of the door, walking): what the door bug is about.</summary>
    private static bool IsHeadOnWalk(MovementCase c) =>
        c.Id.EndsWith("/hdg+00/walk", StringComparison.Ordinal) && (c.Id.Contains("/lat+0.000/") || c.Id.Contains("/lat+0.450/") || c.Id.Contains("/lat-0.450/"));

    [Fact]
    public void The_closed_door_blocks_every_head_on_and_off_centre_walk_without_crossing_the_leaf_face()
    {
        Assert.Equal(ExitCodes.Ok, _door.Run.ExitCode);
        var suite = _door.Read();
        var closed = suite.Cases.Where(c => c.State == "closed" && IsHeadOnWalk(c)).ToArray();
        Assert.Equal(6, closed.Length);
        var r0 = suite.Mover.Spheres[0].Radius;
        foreach (var c in closed)
        {
            Assert.Equal(MovementOutcome.Blocked, c.Outcome.Class);
            Assert.False(c.Outcome.CrossedGate);
            Assert.False(c.Fragile);
            // The leaf's faces are 0.13 m either side of the gate (its mid-plane): sphere 0 never passes the near one.
            Assert.All(c.Expected, f => Assert.True(Side(c.Gate, f.Position) + r0 <= -0.13f + 1e-3f, $"{c.Id} frame {f.Frame}"));
            Assert.Contains(c.Expected, f => f.HitObject);
        }
    }

    [Fact]
    public void The_open_door_lets_the_same_walks_through()
    {
        var open = _door.Read().Cases.Where(c => c.State == "open" && IsHeadOnWalk(c)).ToArray();
        Assert.Equal(6, open.Length);
        Assert.All(open, c =>
        {
            Assert.Equal(MovementOutcome.Reached, c.Outcome.Class);
            Assert.True(c.Outcome.CrossedGate);
        });
    }

    [Fact]
    public void A_collision_author_running_the_cases_from_the_file_gets_the_expected_frames_back()
    {
        // The reference stands in for the author's engine: loaded from the file alone, every case reruns to the
        // frames written (short frames carry the state before them) and to the written outcome.
        var suite = _door.Read();
        Assert.Equal(2 * 11 * 7 * 2 * 2, suite.Cases.Count);
        Assert.Equal(SampleSpecAuthor.MoverSetup, suite.MoverSetupId);
        foreach (var c in suite.Cases)
        {
            var frames = MovementReference.Run(suite.Mover, suite.Objects[c.State], c.Walk);
            Assert.Equal(c.Expected.Count, frames.Count);
            for (var i = 0; i < frames.Count; i++)
            {
                Assert.Equal(c.Expected[i].Position, frames[i].Position);
                Assert.Equal(c.Expected[i].Valid, frames[i].Valid);
                Assert.Equal(c.Expected[i].Contact, frames[i].Contact);
            }
            Assert.Equal(c.Outcome.Class, MovementOutcome.Of(c.Walk, frames, c.Gate).Class);
        }
    }

    [Fact]
    public void The_file_is_the_same_bytes_with_one_worker_and_written_short_where_frames_change_nothing()
    {
        using var one = new TempDir();
        Assert.Equal(ExitCodes.Ok, CliRun.Of("move", "--setup", "0x020019FF", "--jobs", "1", "--out", one.Path).ExitCode);
        var bytes = File.ReadAllBytes(_door.FilePath);
        Assert.Equal(bytes, File.ReadAllBytes(Path.Combine(one.Path, "movement", "0x020019FF.movement.json")));
        var text = System.Text.Encoding.UTF8.GetString(bytes);
        // An open-door walk only moves: every frame but its first and last is {"f", "valid", "end"}.
        Assert.Contains("{\"f\": 1, \"valid\": true, \"end\": [", text);
    }

    [Fact]
    public void Another_object_is_walked_from_16_headings_in_its_one_pose()
    {
        // The sample's three-part static: 16 compass headings × 7 lateral offsets × walk and run, no door states.
        using var dir = new TempDir();
        Assert.Equal(ExitCodes.Ok, CliRun.Of("move", "--setup", "0x02003000", "--out", dir.Path).ExitCode);
        var suite = MovementFileReader.Read(File.ReadAllText(Path.Combine(dir.Path, "movement", "0x02003000.movement.json")),
            id => BspFileReader.Read(File.ReadAllText(Path.Combine(dir.Path, FileFormats.Bsp.PathFor(id)))));
        Assert.Equal(["default"], suite.Objects.Keys);
        Assert.Equal(16 * 7 * 2, suite.Cases.Count);
        // Aimed at its centre, a head-on walk never reaches the far side: the static is solid.
        Assert.All(suite.Cases.Where(c => c.Id.Contains("/lat+0.000/", StringComparison.Ordinal)), c => Assert.NotEqual(MovementOutcome.Reached, c.Outcome.Class));
    }

    [Theory]
    [InlineData(ExitCodes.Usage, "--state", "ajar")]
    [InlineData(ExitCodes.NotInDat, "--mover", "0x0200FFF0")]
    public void Bad_input_is_one_line_and_writes_nothing(int code, string option, string value)
    {
        using var dir = new TempDir();
        var run = CliRun.Of("move", "--setup", "0x020019FF", option, value, "--out", dir.Path);
        Assert.Equal(code, run.ExitCode);
        Assert.Single(run.ErrorLines, l => l.StartsWith("acshadow: ", StringComparison.Ordinal) && l.Contains(option));
        Assert.Empty(dir.Files());
    }

    [Fact]
    public void A_real_dat_has_no_default_mover()
    {
        using var dat = SampleDat.WriteToTempFolder();
        using var dir = new TempDir();
        var run = CliRun.Of("move", "--setup", "0x020019FF", "--dat", dat.Path, "--out", dir.Path);
        Assert.Equal(ExitCodes.Usage, run.ExitCode);
        Assert.Contains("--mover", run.Error);
        Assert.Equal(ExitCodes.Ok, CliRun.Of("move", "--setup", "0x020019FF", "--dat", dat.Path, "--mover", "0x02001100", "--state", "closed", "--out", dir.Path).ExitCode);
    }

    [Fact]
    public void Batch_adds_the_cases_to_index_json_and_verify_names_a_changed_case_by_its_id()
    {
        using var dir = new TempDir();
        Assert.Equal(ExitCodes.Ok, CliRun.Of("batch", "--doors", "--movement", "0x020019FF", "--out", dir.Path, "--quiet").ExitCode);
        var index = File.ReadAllText(Path.Combine(dir.Path, "index.json"));
        Assert.Contains("\"path\": \"movement/0x020019FF.movement.json\"", index);
        Assert.Contains("\"movement\": {\"setups\": [\"0x020019FF\"], \"mover\": \"0x02001100\"}", index);
        // The batch's movement file is the one move writes.
        Assert.Equal(File.ReadAllBytes(_door.FilePath), File.ReadAllBytes(Path.Combine(dir.Path, "movement", "0x020019FF.movement.json")));
        Assert.Equal(ExitCodes.Ok, CliRun.Of("verify", "--fixtures", dir.Path).ExitCode);

        var path = Path.Combine(dir.Path, "movement", "0x020019FF.movement.json");
        var text = File.ReadAllText(path);
        var at = text.IndexOf("\"class\": \"blocked\"", StringComparison.Ordinal);
        File.WriteAllText(path, text[..at] + "\"class\": \"slid\"" + text[(at + "\"class\": \"blocked\"".Length)..]);
        var run = CliRun.Of("verify", "--fixtures", dir.Path);
        Assert.Equal(ExitCodes.Drift, run.ExitCode);
        Assert.Contains("$.cases[id=closed/out-in/lat+0.000/hdg+00/walk].expected.outcome.class: \"slid\" → \"blocked\"", run.Out);
    }

    [Fact]
    public void Batch_movement_needs_ids_and_a_mover_in_the_dat()
    {
        using var dir = new TempDir();
        Assert.Equal(ExitCodes.Usage, CliRun.Of("batch", "--doors", "--movement", "door", "--out", dir.Path).ExitCode);
        Assert.Equal(ExitCodes.Usage, CliRun.Of("batch", "--doors", "--mover", "0x02001100", "--out", dir.Path).ExitCode);
        Assert.Equal(ExitCodes.NotInDat, CliRun.Of("batch", "--doors", "--movement", "0x020019FF", "--mover", "0x0200FFF0", "--out", dir.Path).ExitCode);
        Assert.Empty(dir.Files());
    }

    private static float Side(Plane gate, Vector3 p) => gate.Normal.X * p.X + gate.Normal.Y * p.Y + gate.Normal.Z * p.Z + gate.D;
}
