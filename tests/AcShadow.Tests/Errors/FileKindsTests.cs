using System.Net.Sockets;
using AcShadow.Files;

namespace AcShadow.Tests.Errors;

/// <summary>What kind of file a path names and which file it is, asked of the kernel (statx), never by opening it.</summary>
public class FileKindsTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("acshadow-kinds-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private string At(string name) => Path.Combine(_dir, name);

    private static void MakeHardLink(string target, string link)
    {
        using var ln = System.Diagnostics.Process.Start("ln", [target, link])!;
        ln.WaitForExit();
        Assert.Equal(0, ln.ExitCode);
    }

    [Fact]
    public void Each_kind_is_told_without_following_a_final_link_unless_asked()
    {
        File.WriteAllText(At("file"), "x");
        Directory.CreateDirectory(At("folder"));
        File.CreateSymbolicLink(At("link"), At("file"));
        File.CreateSymbolicLink(At("dangling"), At("nothing"));
        using var socket = new Socket(AddressFamily.Unix, SocketType.Stream, ProtocolType.Unspecified);
        socket.Bind(new UnixDomainSocketEndPoint(At("socket")));

        Assert.Equal(FileKind.Regular, FileKinds.Of(At("file")));
        Assert.Equal(FileKind.Folder, FileKinds.Of(At("folder")));
        Assert.Equal(FileKind.SymbolicLink, FileKinds.Of(At("link")));
        Assert.Equal(FileKind.Regular, FileKinds.Of(At("link"), followLinks: true));
        Assert.Equal(FileKind.SymbolicLink, FileKinds.Of(At("dangling")));
        Assert.Equal(FileKind.Missing, FileKinds.Of(At("dangling"), followLinks: true));
        Assert.Equal(FileKind.Missing, FileKinds.Of(At("nothing")));
        Assert.Equal(FileKind.Missing, FileKinds.Of(Path.Combine(At("file"), "below-a-file")));
        Assert.Equal(FileKind.Socket, FileKinds.Of(At("socket")));
        Assert.Equal(FileKind.CharacterDevice, FileKinds.Of("/dev/null"));
    }

    [Fact]
    public void Identity_is_the_same_for_one_file_however_reached_and_differs_between_files()
    {
        File.WriteAllText(At("a"), "same bytes");
        File.WriteAllText(At("b"), "same bytes");
        File.CreateSymbolicLink(At("link-to-a"), At("a"));
        MakeHardLink(At("a"), At("hard-a"));

        var a = FileKinds.Identity(At("a"));
        Assert.NotNull(a);
        Assert.Equal(a, FileKinds.Identity(At("link-to-a")));
        Assert.Equal(a, FileKinds.Identity(At("hard-a")));
        Assert.NotEqual(a, FileKinds.Identity(At("b")));
        using (var open = File.OpenHandle(At("a")))
            Assert.Equal(a, FileKinds.Identity(open));
        Assert.Null(FileKinds.Identity(At("nothing")));

        // A file replaced by rename under the same name is another file.
        File.Move(At("b"), At("a"), overwrite: true);
        Assert.NotEqual(a, FileKinds.Identity(At("a")));
    }
}
