using AcShadow.Files;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Errors;

/// <summary>
/// docs/errors.md, "links and special files": what is not a regular file of ours is never replaced; links
/// to a dat are followed; a loop is named; a FIFO where an output or fixture belongs is refused unopened;
/// --setups is read within a bound.
/// </summary>
public class SpecialFileTests
{
    internal static void MakeFifo(string path)
    {
        var (code, _, error) = BuiltCli.RunShell([], $"mkfifo '{path}'");
        Assert.True(code == 0, error);
        Assert.Equal(FileKind.Fifo, FileKinds.Of(path));
    }

    [Fact]
    public void A_FIFO_or_a_link_where_an_output_file_belongs_is_refused_unopened_and_left_in_place()
    {
        using var dir = new TempDir();
        using var elsewhere = new TempDir();
        Directory.CreateDirectory(Path.Combine(dir.Path, "setups"));
        var shadow = Path.Combine(dir.Path, "setups", "0x020019FF.shadow.json");
        MakeFifo(shadow);
        var bsp = Path.Combine(dir.Path, "gfxobjs", "0x010044B5.bsp.json");
        Directory.CreateDirectory(Path.GetDirectoryName(bsp)!);
        var linkedTo = Path.Combine(elsewhere.Path, "mine.json");
        File.WriteAllText(linkedTo, "{\n  \"format\": \"acshadow.bsp/1\",\n}\n");
        File.CreateSymbolicLink(bsp, linkedTo);

        // A real process: were the FIFO opened, the run would hang (BuiltCli fails the test after 2 minutes).
        var (code, _, error) = BuiltCli.Run([], "dump", "--setup", "0x020019FF", "--out", dir.Path);

        Assert.Equal(6, code);
        var line = Assert.Single(error.Split('\n', StringSplitOptions.RemoveEmptyEntries), l => !l.Contains("SYNTHETIC") && !l.StartsWith("warning:", StringComparison.Ordinal));
        Assert.Contains("and 1 more would be replaced but are not acshadow output", line);
        Assert.Contains("nothing was written", line);
        Assert.Equal(FileKind.Fifo, FileKinds.Of(shadow));
        Assert.Equal(FileKind.SymbolicLink, FileKinds.Of(bsp));
        Assert.Contains("acshadow.bsp/1", File.ReadAllText(linkedTo));
    }

    [Theory]
    [InlineData("cells/0xA9B40100.cell.json", "dump", "--cell", "0xA9B40100")]
    [InlineData("0x020019FF.glb", "view", "--setup", "0x020019FF")]
    public void A_FIFO_where_a_cell_file_or_a_view_model_belongs_is_refused_unopened(string relative, params string[] command)
    {
        using var dir = new TempDir();
        var fifo = Path.Combine(dir.Path, relative);
        Directory.CreateDirectory(Path.GetDirectoryName(fifo)!);
        MakeFifo(fifo);

        // A real process: were the FIFO opened, the run would hang (BuiltCli fails the test after 2 minutes).
        var (code, _, error) = BuiltCli.Run([], [.. command, "--out", dir.Path]);

        Assert.Equal(6, code);
        var line = Assert.Single(error.Split('\n', StringSplitOptions.RemoveEmptyEntries), l => !l.Contains("SYNTHETIC") && !l.StartsWith("warning:", StringComparison.Ordinal));
        Assert.Contains("(a FIFO (named pipe)) would be replaced but is not acshadow output", line);
        Assert.Equal(FileKind.Fifo, FileKinds.Of(fifo));
    }

    [Fact]
    public void Doctor_out_through_a_link_writes_the_file_it_leads_to_and_keeps_the_link()
    {
        using var dir = new TempDir();
        var target = Path.Combine(dir.Path, "report.json");
        File.WriteAllText(target, "an older report");
        var link = Path.Combine(dir.Path, "link.json");
        File.CreateSymbolicLink(link, target);

        var run = CliRun.Of("doctor", "--out", link);

        Assert.Equal(0, run.ExitCode);
        Assert.Equal(FileKind.SymbolicLink, FileKinds.Of(link));
        Assert.Contains("\"format\": \"acshadow.doctor/1\"", File.ReadAllText(target));
    }

    [Fact]
    public void The_atomic_writer_never_replaces_a_device_a_FIFO_or_a_link()
    {
        using var dir = new TempDir();
        var fifo = Path.Combine(dir.Path, "pipe.json");
        MakeFifo(fifo);
        var link = Path.Combine(dir.Path, "link.json");
        File.CreateSymbolicLink(link, "/dev/null");

        Assert.Throws<NotARegularFileException>(() => AtomicFile.Write(fifo, "x"u8, Durability.Renamed));
        Assert.Throws<NotARegularFileException>(() => AtomicFile.Write(link, "x"u8, Durability.Renamed));
        Assert.Throws<NotARegularFileException>(() => AtomicFile.Write("/dev/null", "x"u8, Durability.Renamed));

        Assert.Equal(FileKind.Fifo, FileKinds.Of(fifo));
        Assert.Equal(FileKind.SymbolicLink, FileKinds.Of(link));
        Assert.Equal(FileKind.CharacterDevice, FileKinds.Of("/dev/null"));
        Assert.Equal(["link.json", "pipe.json"], Directory.GetFileSystemEntries(dir.Path).Select(p => Path.GetFileName(p)).Order().ToArray());
    }

    [Fact]
    public void Audit_out_dev_stdout_writes_the_report_there_and_a_link_is_written_through_not_replaced()
    {
        using var dir = new TempDir();
        var (code, stdout, _) = BuiltCli.Run([], "audit", "--doors", "--format", "csv", "--out", "/dev/stdout");
        Assert.Equal(0, code);
        Assert.StartsWith("id,", stdout);
        Assert.Equal(FileKind.CharacterDevice, FileKinds.Of("/dev/null"));

        var real = Path.Combine(dir.Path, "real.csv");
        File.WriteAllText(real, "old");
        var link = Path.Combine(dir.Path, "report.csv");
        File.CreateSymbolicLink(link, real);
        Assert.Equal(0, CliRun.Of("audit", "--doors", "--out", link).ExitCode);
        Assert.Equal(FileKind.SymbolicLink, FileKinds.Of(link));
        Assert.StartsWith("id,", File.ReadAllText(real));
    }

    [Fact]
    public void Links_to_a_dat_are_followed_everywhere_a_dat_is_named()
    {
        using var dats = SampleDat.WriteToTempFolder();
        using var links = new TempDir();
        using var output = new TempDir();
        var portalLink = Path.Combine(links.Path, "portal.dat");
        File.CreateSymbolicLink(portalLink, Path.Combine(dats.Path, "client_portal.dat"));
        var cellLink = Path.Combine(links.Path, "cell.dat");
        File.CreateSymbolicLink(cellLink, Path.Combine(dats.Path, "client_cell_1.dat"));
        var folder = Path.Combine(links.Path, "folder");
        Directory.CreateDirectory(folder);
        File.CreateSymbolicLink(Path.Combine(folder, "client_portal.dat"), portalLink);

        Assert.Equal(0, CliRun.Of("dump", "--setup", "0x020019FF", "--dat", portalLink, "--out", output.Path).ExitCode);
        Assert.Equal(0, CliRun.Of("dump", "--setup", "0x020019FF", "--dat", folder, "--out", output.Path).ExitCode);
        Assert.Equal(0, CliRun.With(name => name == "ACSHADOW_DAT" ? portalLink : null, "dump", "--setup", "0x020019FF", "--out", output.Path).ExitCode);
        Assert.Equal(0, CliRun.Of("batch", "--landblock", "0xA9B4", "--dat", portalLink, "--cell-dat", cellLink, "--out", output.Path, "--quiet").ExitCode);
    }

    [Fact]
    public void A_link_loop_and_a_dangling_link_are_named_as_such()
    {
        using var dir = new TempDir();
        using var output = new TempDir();
        var a = Path.Combine(dir.Path, "a.dat");
        var b = Path.Combine(dir.Path, "b.dat");
        File.CreateSymbolicLink(a, b);
        File.CreateSymbolicLink(b, a);
        var dangling = Path.Combine(dir.Path, "gone.dat");
        File.CreateSymbolicLink(dangling, Path.Combine(dir.Path, "nothing-here.dat"));

        var loop = CliRun.Of("dump", "--setup", "0x020019FF", "--dat", a, "--out", output.Path);
        Assert.Equal(3, loop.ExitCode);
        Assert.Contains($"--dat: {a} is a symbolic link loop", Assert.Single(loop.ErrorLines));

        var gone = CliRun.Of("dump", "--setup", "0x020019FF", "--dat", dangling, "--out", output.Path);
        Assert.Equal(3, gone.ExitCode);
        Assert.Contains($"is a symbolic link to {Path.Combine(dir.Path, "nothing-here.dat")}, which does not exist", Assert.Single(gone.ErrorLines));
        Assert.Empty(output.Files());
    }

    [Fact]
    public void A_FIFO_in_a_fixtures_folder_is_refused_without_hanging_verify()
    {
        using var dir = new TempDir();
        Assert.Equal(0, CliRun.Of("batch", "--doors", "--out", dir.Path, "--quiet").ExitCode);
        var shadow = Directory.GetFiles(Path.Combine(dir.Path, "setups"))[0];
        File.Delete(shadow);
        MakeFifo(shadow);

        var (code, _, error) = BuiltCli.Run([], "verify", "--fixtures", dir.Path);

        Assert.Equal(2, code);
        Assert.Contains($"--fixtures: {shadow} is a FIFO (named pipe), not a regular file", error);
    }

    [Fact]
    public void An_endless_setups_file_is_refused_at_its_bound()
    {
        using var output = new TempDir();
        var (code, _, error) = BuiltCli.Run([], "batch", "--setups", "/dev/zero", "--out", output.Path, "--quiet");
        Assert.Equal(2, code);
        Assert.Contains("--setups: /dev/zero holds more than 16 MiB", error);
        Assert.Empty(output.Files());
    }
}
