using System.Text;
using Microsoft.Win32.SafeHandles;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// stderr written with nothing but CoreLib, for when Console.Error cannot be. The runtime keeps a descriptor
/// open for every assembly it loads, so with a low `ulimit -n` the assemblies Console needs to format and
/// write a line may fail to load, and the error that says so would go unsaid. A FileStream on descriptor 2
/// needs no new descriptor and no assembly beyond CoreLib; it is opened per line, so it writes at the
/// descriptor's current offset (stdout and stderr may share one file).
/// </summary>
public static class RawStandardError
{
    /// <summary>Best effort: with descriptor 2 closed too, only the exit code is left to tell.</summary>
    public static void WriteLine(string line)
    {
        try
        {
            var bytes = Encoding.UTF8.GetBytes(line + "\n");
            using var stderr = new FileStream(new SafeFileHandle(2, ownsHandle: false), FileAccess.Write, bufferSize: 0);
            stderr.Write(bytes, 0, bytes.Length);
        }
        catch (Exception)
        {
        }
    }
}
