using System.Security.Cryptography;
using System.Text;
using AcShadow.Core.Batch;
using AcShadow.Core.Formats;
using AcShadow.Fixtures.Batch;

namespace AcShadow.Tests.Batch;

/// <summary>
/// incremental.json's bytes, worked out from docs/batch.md's layout (canonical JSON, `sha256` last: the SHA-256
/// of the file's canonical bytes without that member), and which files are trusted when read back.
/// </summary>
public sealed class IncrementalStateFileTests
{
    private static readonly IncrementalState State = new("tool-key/retail/1/canonical/retail/closed/",
    [
        new IncrementalSetup(0x0200024F, "04e94e18f1bbe25cd156a57e1e80cc6c", [0x01000110], 2,
        [
            new FileEntry("setups/0x0200024F.shadow.json", FixtureKind.Shadow, 0x0200024F, 3, 0, 2266, new string('a', 64)),
            new FileEntry("gfxobjs/0x01000110.bsp.json", FixtureKind.Bsp, 0x01000110, 0, 6, 4192, new string('c', 64)),
        ]),
    ]);

    /// <summary>The state above without its checksum, as docs/batch.md lays it out.</summary>
    private const string Body = """
        {
          "format": "acshadow.incremental/1",
          "tool": "tool-key/retail/1/canonical/retail/closed/",
          "setups": [
            {
              "id": "0x0200024F",
              "fingerprint": "04e94e18f1bbe25cd156a57e1e80cc6c",
              "parts": ["0x01000110"],
              "diagnostics": 2,
              "files": [
                {
                  "path": "setups/0x0200024F.shadow.json",
                  "kind": "shadow",
                  "id": "0x0200024F",
                  "shapes": 3,
                  "polygons": 0,
                  "bytes": 2266,
                  "sha256": "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa"
                },
                {
                  "path": "gfxobjs/0x01000110.bsp.json",
                  "kind": "bsp",
                  "id": "0x01000110",
                  "shapes": 0,
                  "polygons": 6,
                  "bytes": 4192,
                  "sha256": "cccccccccccccccccccccccccccccccccccccccccccccccccccccccccccccccc"
                }
              ]
            }
          ]
        }

        """;

    private static string Expected()
    {
        var sum = Convert.ToHexStringLower(SHA256.HashData(Encoding.UTF8.GetBytes(Body)));
        return Body[..^3] + $",\n  \"sha256\": \"{sum}\"\n}}\n";
    }

    [Fact]
    public void The_state_is_written_as_its_canonical_body_with_the_checksum_of_that_body_last()
    {
        Assert.Equal(Expected(), Encoding.UTF8.GetString(IncrementalStateFile.Write(State)));
    }

    [Fact]
    public void A_state_read_back_is_the_state_written()
    {
        var read = IncrementalStateFile.TryRead(Encoding.UTF8.GetBytes(Expected()));
        Assert.NotNull(read);
        Assert.Equal(State.Tool, read.Tool);
        var setup = Assert.Single(read.Setups);
        Assert.Equal((0x0200024Fu, "04e94e18f1bbe25cd156a57e1e80cc6c", 2), (setup.Id, setup.Fingerprint, setup.Diagnostics));
        Assert.Equal([0x01000110u], setup.Parts);
        Assert.Equal(State.Setups[0].Files, setup.Files);
    }

    [Theory]
    [InlineData("\"diagnostics\": 2", "\"diagnostics\": 3")]
    [InlineData("\"bytes\": 2266", "\"bytes\": 2267")]
    [InlineData("\"polygons\": 6", "\"polygons\": 7")]
    [InlineData("setups/0x0200024F.shadow.json", "setups/0x0200024E.shadow.json")]
    public void A_same_length_edit_of_a_count_or_path_is_not_trusted(string from, string to)
    {
        var edited = Expected().Replace(from, to, StringComparison.Ordinal);
        Assert.NotEqual(Expected(), edited);
        Assert.Null(IncrementalStateFile.TryRead(Encoding.UTF8.GetBytes(edited)));
    }

    [Fact]
    public void An_edited_checksum_is_not_trusted()
    {
        var file = Expected();
        var at = file.LastIndexOf("\"sha256\": \"", StringComparison.Ordinal) + "\"sha256\": \"".Length;
        var edited = file[..at] + (file[at] == '0' ? '1' : '0') + file[(at + 1)..];
        Assert.Null(IncrementalStateFile.TryRead(Encoding.UTF8.GetBytes(edited)));
    }

    [Fact]
    public void The_same_state_laid_out_otherwise_is_still_read_by_its_checksum()
    {
        // Two-space indents turned into tabs: not the bytes written, but the same JSON with a checksum that holds for it.
        var relaid = Expected().Replace("  ", "\t", StringComparison.Ordinal);
        Assert.NotNull(IncrementalStateFile.TryRead(Encoding.UTF8.GetBytes(relaid)));
    }

    [Fact]
    public void A_state_with_no_setups_sits_on_one_line_and_is_read_back()
    {
        var empty = new IncrementalState("k", []);
        var body = "{\"format\": \"acshadow.incremental/1\", \"tool\": \"k\", \"setups\": []}\n";
        var sum = Convert.ToHexStringLower(SHA256.HashData(Encoding.UTF8.GetBytes(body)));
        var written = IncrementalStateFile.Write(empty);
        Assert.Equal(body[..^2] + $", \"sha256\": \"{sum}\"}}\n", Encoding.UTF8.GetString(written));
        Assert.Equal("k", IncrementalStateFile.TryRead(written)?.Tool);
    }

    [Fact]
    public void A_state_listing_one_setup_twice_is_not_a_state_even_with_a_checksum_that_holds()
    {
        // Written by hand with a fresh checksum: reuse keys records by Setup, so a second record for one is refused
        // when read (read as no state: everything exported), never met later as an exception.
        var twice = new IncrementalState(State.Tool, [State.Setups[0], State.Setups[0] with { Fingerprint = new string('f', 32) }]);
        var written = IncrementalStateFile.Write(twice);
        Assert.Null(IncrementalStateFile.TryRead(written));
        Assert.NotNull(IncrementalStateFile.TryRead(IncrementalStateFile.Write(State)));
    }
}
