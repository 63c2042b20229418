using AcShadow.Files;
using AcShadow.Tests.Errors;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Files;

/// <summary>
/// <see cref="AtomicFile.WriteNew"/>: a file where nothing is expected goes in whole without a look at its path
/// first, and whatever is at the path after all (a file, a link, a FIFO) is left exactly as it was, with no
/// temporary file left beside it.
/// </summary>
public class AtomicNewFileTests
{
    private static readonly byte[] Content = [.. Enumerable.Range(0, 70_000).Select(i => (byte)(i * 7))];

    private static string[] Entries(string folder) =>
        [.. Directory.GetFileSystemEntries(folder).Select(p => Path.GetFileName(p)!).Order(StringComparer.Ordinal)];

    [Fact]
    public void A_missing_file_is_written_whole_and_no_temporary_is_left()
    {
        using var dir = new TempDir();
        var path = Path.Combine(dir.Path, "0x01000001.bsp.json");

        Assert.Equal(Content.Length, AtomicFile.WriteNew(path, Content, Durability.Renamed));

        Assert.Equal(Content, File.ReadAllBytes(path));
        Assert.Equal(["0x01000001.bsp.json"], Entries(dir.Path));
    }

    [Fact]
    public void Its_folder_is_made_when_missing_as_for_any_write()
    {
        using var dir = new TempDir();
        var path = Path.Combine(dir.Path, "gfxobjs", "0x01000001.bsp.json");

        Assert.Equal(Content.Length, AtomicFile.WriteNew(path, Content, Durability.Flushed));

        Assert.Equal(Content, File.ReadAllBytes(path));
        Assert.Equal(["0x01000001.bsp.json"], Entries(Path.Combine(dir.Path, "gfxobjs")));
    }

    [Fact]
    public void A_file_already_at_the_path_is_left_as_it_was()
    {
        using var dir = new TempDir();
        var path = Path.Combine(dir.Path, "index.json");
        File.WriteAllText(path, "someone else's");

        Assert.Null(AtomicFile.WriteNew(path, Content, Durability.Renamed));

        Assert.Equal("someone else's", File.ReadAllText(path));
        Assert.Equal(["index.json"], Entries(dir.Path));
    }

    [Fact]
    public void A_FIFO_or_a_link_at_the_path_is_neither_opened_nor_replaced()
    {
        using var dir = new TempDir();
        using var elsewhere = new TempDir();
        var fifo = Path.Combine(dir.Path, "pipe.json");
        SpecialFileTests.MakeFifo(fifo);
        var linkedTo = Path.Combine(elsewhere.Path, "mine.json");
        File.WriteAllText(linkedTo, "mine");
        var link = Path.Combine(dir.Path, "link.json");
        File.CreateSymbolicLink(link, linkedTo);

        // Opening the FIFO would wait for a writer for ever; the test returning says it was not opened.
        Assert.Null(AtomicFile.WriteNew(fifo, Content, Durability.Renamed));
        Assert.Null(AtomicFile.WriteNew(link, Content, Durability.Renamed));

        Assert.Equal(FileKind.Fifo, FileKinds.Of(fifo));
        Assert.Equal(FileKind.SymbolicLink, FileKinds.Of(link));
        Assert.Equal("mine", File.ReadAllText(linkedTo));
        Assert.Equal(["link.json", "pipe.json"], Entries(dir.Path));
    }

    [Fact]
    public void A_write_that_fails_leaves_neither_the_file_nor_a_temporary()
    {
        using var dir = new TempDir();
        // The folder above the file's folder is gone: an error, not something to recreate (as for any write).
        var path = Path.Combine(dir.Path, "gone", "gfxobjs", "0x01000001.bsp.json");

        Assert.Throws<DirectoryNotFoundException>(() => AtomicFile.WriteNew(path, Content, Durability.Renamed));

        Assert.Empty(Entries(dir.Path));
    }

    [Fact]
    public void Writers_side_by_side_in_one_folder_each_get_their_files_whole_and_one_path_goes_to_one_of_them()
    {
        using var dir = new TempDir();
        var contents = Enumerable.Range(0, 8).Select(w => Content.Select(b => (byte)(b ^ w)).ToArray()).ToArray();
        var shared = Path.Combine(dir.Path, "shared.json");
        var sharedResults = new long?[contents.Length];

        Parallel.For(0, contents.Length, new ParallelOptions { MaxDegreeOfParallelism = 4 }, w =>
        {
            for (var i = 0; i < 50; i++)
                Assert.Equal(Content.Length, AtomicFile.WriteNew(Path.Combine(dir.Path, $"w{w}-{i:00}.json"), contents[w], Durability.Renamed));
            sharedResults[w] = AtomicFile.WriteNew(shared, contents[w], Durability.Renamed);
        });

        for (var w = 0; w < contents.Length; w++)
            for (var i = 0; i < 50; i++)
                Assert.Equal(contents[w], File.ReadAllBytes(Path.Combine(dir.Path, $"w{w}-{i:00}.json")));
        var winner = Assert.Single(Enumerable.Range(0, contents.Length), w => sharedResults[w] is not null);
        Assert.Equal(contents[winner], File.ReadAllBytes(shared));
        Assert.Equal(contents.Length * 50 + 1, Entries(dir.Path).Length);
        Assert.DoesNotContain(Entries(dir.Path), name => name.EndsWith(AtomicFile.TemporarySuffix, StringComparison.Ordinal));
    }
}
