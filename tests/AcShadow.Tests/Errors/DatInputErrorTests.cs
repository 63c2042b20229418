using System.Diagnostics;
using AcShadow.Core.Dat;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Errors;

/// <summary>docs/errors.md, "the dat": every way --dat or --cell-dat can be wrong, through every command.</summary>
public class DatInputErrorTests
{
    public static TheoryData<string> Commands => new() { "dump", "batch", "audit", "verify", "chart" };

    /// <summary>A valid invocation of the command, but for the dat options given.</summary>
    private static CliRun Run(string command, string outDir, params string[] datOptions)
    {
        string[] rest = command switch
        {
            "dump" => ["--setup", "0x020019FF", "--out", outDir],
            "batch" => ["--all", "--out", outDir],
            "audit" => [],
            "verify" => ["--fixtures", Fixtures.CommittedFixturesTests.RepositoryFixtures()],
            "chart" => ["--setup", "0x020019FF", "--out", outDir],
            _ => throw new ArgumentOutOfRangeException(nameof(command)),
        };
        return CliRun.Of([command, .. rest, .. datOptions]);
    }

    /// <summary>Exit 3, one line holding <paramref name="message"/>, no stack trace, nothing written.</summary>
    private static void AssertDatError(CliRun run, TempDir output, string message)
    {
        Assert.Equal(3, run.ExitCode);
        var line = Assert.Single(run.ErrorLines, l => !l.Contains("SYNTHETIC"));
        Assert.Contains(message, line);
        Assert.Empty(output.Files());
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public void A_dat_path_naming_nothing_is_exit_3(string command)
    {
        using var output = new TempDir();
        var run = Run(command, output.Path, "--dat", "/nonexistent/client_portal.dat");
        AssertDatError(run, output, "--dat: /nonexistent/client_portal.dat does not exist: pass the path of your client_portal.dat");
    }

    [Fact]
    public void ACSHADOW_DAT_naming_nothing_is_named_as_the_source()
    {
        using var output = new TempDir();
        var run = CliRun.With(name => name == "ACSHADOW_DAT" ? "/nonexistent/dats" : null, "dump", "--setup", "0x020019FF", "--out", output.Path);
        AssertDatError(run, output, "ACSHADOW_DAT: /nonexistent/dats does not exist");
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public void A_folder_without_client_portal_dat_is_exit_3(string command)
    {
        using var output = new TempDir();
        using var empty = new TempDir();
        var run = Run(command, output.Path, "--dat", empty.Path);
        AssertDatError(run, output, $"--dat: folder {empty.Path} has no client_portal.dat");
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public void A_file_that_is_not_a_dat_is_exit_3(string command)
    {
        using var output = new TempDir();
        using var dir = new TempDir();
        var file = Path.Combine(dir.Path, "client_portal.dat");
        File.WriteAllText(file, new string('x', 4000));
        var run = Run(command, output.Path, "--dat", file);
        AssertDatError(run, output, "is not a readable dat: not an Asheron's Call dat file");
    }

    [Fact]
    public void A_file_shorter_than_a_header_is_exit_3_with_its_size()
    {
        using var output = new TempDir();
        using var dir = new TempDir();
        var file = Path.Combine(dir.Path, "client_portal.dat");
        File.WriteAllText(file, "hello\n");
        var run = Run("dump", output.Path, "--dat", file);
        AssertDatError(run, output, "is 6 bytes, too short for a dat");
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public void A_cell_dat_where_the_portal_dat_belongs_is_exit_3(string command)
    {
        using var output = new TempDir();
        using var dats = SampleDat.WriteToTempFolder();
        var run = Run(command, output.Path, "--dat", Path.Combine(dats.Path, "client_cell_1.dat"));
        AssertDatError(run, output, "is a cell dat, not a portal dat (its header says so): pass client_portal.dat there");
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public void A_language_dat_where_the_portal_dat_belongs_is_exit_3(string command)
    {
        using var output = new TempDir();
        using var dir = new TempDir();
        var file = Path.Combine(dir.Path, "client_local_English.dat");
        File.WriteAllBytes(file, BrokenDats.Archive(DatFileKind.Local));
        var run = Run(command, output.Path, "--dat", file);
        AssertDatError(run, output, "is a language (client_local_English) dat, not a portal dat");
    }

    [Theory]
    [InlineData("batch", "--landblock", "0xA9B4", "--out")]
    [InlineData("audit", "--landblock", "0xA9B4", "--out")]
    [InlineData("chart", "--landblock", "0xA9B4", "--out")]
    [InlineData("verify", "--fixtures")]
    public void A_portal_dat_given_as_the_cell_dat_is_exit_3(string command, params string[] options)
    {
        using var output = new TempDir();
        using var dats = SampleDat.WriteToTempFolder();
        var portal = Path.Combine(dats.Path, "client_portal.dat");
        var last = command switch
        {
            "verify" => Fixtures.CommittedFixturesTests.RepositoryFixtures(),
            "audit" => Path.Combine(output.Path, "audit.csv"),
            _ => output.Path,
        };
        var run = CliRun.Of([command, .. options, last, "--dat", portal, "--cell-dat", portal]);
        AssertDatError(run, output, "--cell-dat: " + portal + " is a portal dat, not a cell dat (its header says so): pass client_cell_1.dat there");
    }

    [Fact]
    public void A_header_naming_an_unknown_data_set_is_not_a_readable_dat()
    {
        using var output = new TempDir();
        using var dir = new TempDir();
        var file = Path.Combine(dir.Path, "client_portal.dat");
        File.WriteAllBytes(file, BrokenDats.Archive((DatFileKind)2560));
        var run = Run("dump", output.Path, "--dat", file);
        AssertDatError(run, output, "is not a readable dat: its header names data set 2560, which is no dat acshadow knows");
    }

    [Fact]
    public void A_folder_named_client_portal_dat_is_exit_3()
    {
        using var output = new TempDir();
        using var dir = new TempDir();
        Directory.CreateDirectory(Path.Combine(dir.Path, "client_portal.dat"));
        var run = Run("dump", output.Path, "--dat", dir.Path);
        AssertDatError(run, output, "client_portal.dat is a folder, not a file");
    }

    [Fact]
    public async Task A_FIFO_is_refused_without_being_opened()
    {
        using var output = new TempDir();
        using var dir = new TempDir();
        var fifo = Path.Combine(dir.Path, "client_portal.dat");
        using (var mkfifo = Process.Start("mkfifo", [fifo])) mkfifo.WaitForExit();
        Assert.True(File.Exists(fifo));
        // Opening a FIFO for reading waits for a writer: a regression would hang here, not fail.
        var run = Task.Run(() => Run("dump", output.Path, "--dat", fifo));
        Assert.True(await Task.WhenAny(run, Task.Delay(TimeSpan.FromSeconds(60))) == run, "acshadow opened the FIFO and waited for a writer");
        AssertDatError(await run, output, "is a FIFO (named pipe), not a regular file");
    }

    [Fact]
    public void An_unreadable_dat_is_exit_3_naming_the_file()
    {
        using var dir = new TempDir();
        BuiltCli.OpenToEveryone(dir.Path);
        var file = Path.Combine(dir.Path, "client_portal.dat");
        File.WriteAllBytes(file, SampleDat.PortalBytes);
        BuiltCli.SetMode(file, UnixFileMode.None);
        var outDir = Path.Combine(dir.Path, "out");

        var (code, stdout, stderr) = BuiltCli.Run(BuiltCli.AsUnprivilegedUser(), "dump", "--setup", "0x020019FF", "--dat", file, "--out", outDir);

        Assert.Equal(3, code);
        var line = Assert.Single(stderr.Split('\n', StringSplitOptions.RemoveEmptyEntries));
        Assert.Contains($"--dat: cannot open {file}: Access to the path", line);
        Assert.Equal("", stdout);
        Assert.False(Directory.Exists(outDir));
    }
}
