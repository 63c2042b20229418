using System.Text;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// stdout or stderr as a command writes to it, with a failure of the stream itself told apart from a
/// failure of the work: stdout that cannot take the output (a full disk behind `> file`, /dev/full, a
/// closed descriptor) is <see cref="StandardOutputException"/> (exit 6, not "reading the dat failed");
/// a line for stderr that Console cannot write (it may need an assembly that can no longer load) goes out
/// through <see cref="RawStandardError"/>; where that fails too, there is nowhere left to say anything, and
/// the exit code still tells.
/// </summary>
public sealed class StandardStreamWriter : TextWriter
{
    private readonly TextWriter? _inner;
    private readonly bool _isError;
    private string? _broken;

    /// <summary>Opened at once, while descriptors are free: a run that later uses them all up can still say so.</summary>
    public StandardStreamWriter(Func<TextWriter> open, bool isError)
    {
        _isError = isError;
        try
        {
            _inner = open();
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or NotSupportedException)
        {
            _broken = e.Message;
        }
    }

    public override Encoding Encoding => new UTF8Encoding(false);

    public override void Write(char value) => Guard(w => w.Write(value));
    public override void Write(string? value) => Guard(w => w.Write(value));
    public override void Write(char[] buffer, int index, int count) => Guard(w => w.Write(buffer, index, count));
    public override void WriteLine(string? value) => Guard(w => w.WriteLine(value), value);
    public override void WriteLine() => Guard(w => w.WriteLine());
    public override void Flush() => Guard(w => w.Flush());

    private void Guard(Action<TextWriter> write, string? line = null)
    {
        if (_broken is null)
        {
            try
            {
                write(_inner!);
                return;
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException or ObjectDisposedException or NotSupportedException)
            {
                _broken = e.Message;
            }
        }
        if (!_isError) throw new StandardOutputException(_broken);
        if (line is not null) RawStandardError.WriteLine(line);
    }
}

/// <summary>stdout could not be written: the output went nowhere.</summary>
public sealed class StandardOutputException(string message) : Exception(message);
