using AcShadow.Forge;
using System.Text.Json;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Forging;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Dat;

/// <summary>
/// The Iteration object (0xFFFF0001) real dats carry. Its bytes below are worked out by hand from the public
/// layout (ACE's and DatReaderWriter's Iteration): int current, then (int -count, int first) runs until the
/// counts use up the current figure; no id.
/// </summary>
public class IterationRecordTests
{
    private static byte[] Hex(string hex) => Convert.FromHexString(hex.Replace(" ", ""));

    private static byte[] Bytes(Action<DatBinaryWriter> write)
    {
        var w = new DatBinaryWriter();
        write(w);
        return w.ToArray();
    }

    [Fact]
    public void One_run_from_iteration_1_is_what_DatReaderWriter_writes()
    {
        var bytes = Hex("05000000 FBFFFFFF 01000000"); // 5, -5, 1

        var record = IterationRecord.Read(new DatBinaryReader(bytes));

        Assert.Equal(5, record.Current);
        Assert.Equal([new IterationRun(1, 5)], record.Runs);
        Assert.Equal(bytes, Bytes(IterationRecord.Single(5).Write));
    }

    [Fact]
    public void Several_runs_are_read_until_their_counts_make_up_the_current_figure()
    {
        var bytes = Hex("0A000000 FDFFFFFF 01000000 F9FFFFFF 05000000"); // 10: 3 from 1, 7 from 5

        var record = IterationRecord.Read(new DatBinaryReader(bytes));

        Assert.Equal(10, record.Current);
        Assert.Equal([new IterationRun(1, 3), new IterationRun(5, 7)], record.Runs);
        Assert.Equal(bytes, Bytes(record.Write));
    }

    [Theory]
    [InlineData("05000000 05000000 01000000")]             // a positive count never ends the list
    [InlineData("05000000 F9FFFFFF 01000000")]             // the runs cover 7 of 5
    [InlineData("05000000 FEFFFFFF 01000000")]             // cut short: 2 of 5, then nothing
    public void A_record_that_cannot_be_read_to_its_end_is_refused(string hex) =>
        Assert.Throws<DatFormatException>(() => IterationRecord.Read(new DatBinaryReader(Hex(hex))));

    private static DatDatabase Dat(int entryIteration, byte[]? record)
    {
        var objects = new Dictionary<uint, byte[]> { [0x01000001] = [1, 2, 3] };
        if (record is not null) objects[IterationRecord.Id] = record;
        return DatDatabase.Open(new MemoryStream(DatArchiveWriter.Write(objects, new DatArchiveWriter.Options(DatFileKind.Portal, Iteration: entryIteration))), "client_portal.dat");
    }

    [Fact]
    public void The_record_gives_the_dat_its_iteration_when_present()
    {
        using var dat = Dat(1, Hex("09000000 F7FFFFFF 01000000"));
        Assert.Equal(9, dat.Info.Iteration);
        Assert.Equal(DatIterationSource.Record, dat.Info.IterationSource);
    }

    [Fact]
    public void Without_a_record_the_largest_directory_iteration_stands()
    {
        using var dat = Dat(3, null);
        Assert.Equal(3, dat.Info.Iteration);
        Assert.Equal(DatIterationSource.Directory, dat.Info.IterationSource);
    }

    [Fact]
    public void An_unreadable_record_falls_back_to_the_directory_and_says_so()
    {
        using var dat = Dat(4, Hex("0500"));
        Assert.Equal(4, dat.Info.Iteration);
        Assert.Equal(DatIterationSource.UnreadableRecord, dat.Info.IterationSource);
    }

    [Fact]
    public void The_forge_writes_the_record_in_both_dats()
    {
        var spec = SampleSpecAuthor.Create() with { Iteration = 6 };
        var dats = SpecCompiler.Compile(spec);
        foreach (var bytes in new[] { dats.Portal, dats.Cell! })
        {
            using var dat = DatDatabase.Open(new MemoryStream(bytes), "forged.dat");
            Assert.Equal(Hex("06000000 FAFFFFFF 01000000"), dat.Archive.ReadObjectBytes(IterationRecord.Id));
            Assert.Equal(6, dat.Info.Iteration);
            Assert.Equal(DatIterationSource.Record, dat.Info.IterationSource);
        }
    }

    [Fact]
    public void Index_json_and_the_audit_say_where_the_iteration_came_from()
    {
        using var output = new TempDir();
        Assert.Equal(0, CliRun.Of("batch", "--doors", "--out", output.Path, "--quiet").ExitCode);
        using var index = JsonDocument.Parse(File.ReadAllText(Path.Combine(output.Path, "index.json")));
        var dat = index.RootElement.GetProperty("inputs").GetProperty("dat");
        Assert.Equal(1, dat.GetProperty("iteration").GetInt32());
        Assert.Equal("record", dat.GetProperty("iterationSource").GetString());

        var audit = CliRun.Of("audit", "--doors", "--format", "md");
        Assert.Equal(0, audit.ExitCode);
        Assert.Contains("iteration 1 from the iteration record 0xFFFF0001", audit.Out);
    }
}
