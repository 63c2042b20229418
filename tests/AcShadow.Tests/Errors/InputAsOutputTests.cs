using System.Security.Cryptography;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Errors;

/// <summary>
/// docs/errors.md, "output": a report's --out that names a dat the run reads (by its path, another spelling
/// of it, a link to it, the cell dat, or the dat $ACSHADOW_DAT names) is refused with exit 6 and the dat is
/// left byte for byte as it was: a proprietary dat overwritten by a report cannot be had back.
/// </summary>
public class InputAsOutputTests
{
    public static TheoryData<string, string, string> Targets => new()
    {
        { "doctor", "portal", "doctor.json" },
        { "doctor", "cell", "doctor.json" },
        { "doctor", "link", "doctor.json" },
        { "doctor", "dotted", "doctor.json" },
        { "audit", "portal", "audit.csv" },
        { "audit", "link", "audit.csv" },
    };

    private static string Digest(string path) => Convert.ToHexString(SHA256.HashData(File.ReadAllBytes(path)));

    [Theory]
    [MemberData(nameof(Targets))]
    public void A_report_is_never_written_over_a_dat_the_run_reads(string command, string target, string example)
    {
        using var dats = SampleDat.WriteToTempFolder();
        var portal = Path.Combine(dats.Path, "client_portal.dat");
        var cell = Path.Combine(dats.Path, "client_cell_1.dat");
        var link = Path.Combine(dats.Path, "report.json");
        File.CreateSymbolicLink(link, portal);
        var before = Digest(portal) + Digest(cell);
        var outPath = target switch
        {
            "portal" => portal,
            "cell" => cell,
            "link" => link,
            _ => Path.Combine(dats.Path, ".", "client_portal.dat"),
        };

        var run = CliRun.Of(command, "--dat", portal, "--cell-dat", cell, "--out", outPath);

        Assert.Equal(6, run.ExitCode);
        Assert.Contains($"--out: {outPath} is a dat this run reads: acshadow never writes over its input; pass another file name, e.g. {example}", run.Error);
        Assert.Equal(before, Digest(portal) + Digest(cell));
        Assert.True(File.Exists(link) && new FileInfo(link).LinkTarget == portal, "the link is left as it was");
        Assert.DoesNotContain("   at ", run.Error);
    }

    [Fact]
    public void The_dat_named_by_ACSHADOW_DAT_is_refused_as_out_too()
    {
        using var dats = SampleDat.WriteToTempFolder();
        var portal = Path.Combine(dats.Path, "client_portal.dat");
        var size = new FileInfo(portal).Length;
        var run = CliRun.With(name => name == "ACSHADOW_DAT" ? dats.Path : null, "doctor", "--out", portal);
        Assert.Equal(6, run.ExitCode);
        Assert.Equal(size, new FileInfo(portal).Length);
    }

    [Fact]
    public void Another_file_beside_the_dat_is_written_as_before()
    {
        using var dats = SampleDat.WriteToTempFolder();
        var report = Path.Combine(dats.Path, "doctor.json");
        var run = CliRun.Of("doctor", "--dat", dats.Path, "--out", report);
        Assert.Equal(0, run.ExitCode);
        Assert.StartsWith("{", File.ReadAllText(report));
    }
}
