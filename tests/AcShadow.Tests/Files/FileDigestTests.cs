using AcShadow.Files;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Files;

/// <summary>FileDigest.Holds: the recorded length and SHA-256, nothing less, and never through a link.</summary>
public sealed class FileDigestTests
{
    // SHA-256 of the ASCII bytes "abc" (FIPS 180-2, appendix B.1).
    private const string Abc = "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad";

    [Theory]
    [InlineData("abc", 3, true)]
    [InlineData("abc", 4, false)]
    [InlineData("abd", 3, false)]
    public void A_file_holds_only_the_bytes_whose_length_and_hash_were_recorded(string content, long bytes, bool holds)
    {
        using var dir = new TempDir();
        var path = Path.Combine(dir.Path, "f.json");
        File.WriteAllText(path, content);
        Assert.Equal(holds, FileDigest.Holds(path, bytes, Abc));
    }

    [Fact]
    public void A_link_to_a_file_that_holds_them_and_a_missing_file_do_not()
    {
        using var dir = new TempDir();
        var real = Path.Combine(dir.Path, "real.json");
        File.WriteAllText(real, "abc");
        Assert.True(FileDigest.Holds(real, 3, Abc));
        Assert.False(FileDigest.Holds(File.CreateSymbolicLink(Path.Combine(dir.Path, "link.json"), real).FullName, 3, Abc));
        Assert.False(FileDigest.Holds(Path.Combine(dir.Path, "missing.json"), 3, Abc));
    }
}
