using System.Diagnostics;
using AcShadow.Core.Dat;
using AcShadow.Files;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// An open portal dat (and cell dat when one was asked for, or found beside the portal dat: that one is opened
/// when a command first needs it), with how to name it to the user.
/// </summary>
public sealed class OpenedDat(DatDatabase portal, DatDatabase? cell, string description, bool isSample, IReadOnlyList<DatFileWatch>? watches = null,
    (string File, Func<DatDatabase> Open)? foundCell = null) : IDisposable
{
    private readonly Lazy<DatDatabase?> _cell = new(() => cell ?? foundCell?.Open());

    public DatDatabase Portal { get; } = portal;
    public DatDatabase? Cell => _cell.Value;
    public string Description { get; } = description;
    public bool IsSample { get; } = isSample;

    /// <summary>
    /// Fails (exit 3) when a dat file changed since it was opened: whatever was read after the change
    /// cannot be trusted, so the run ends with one line instead of skipping objects that "do not decode".
    /// </summary>
    public void RequireUnchanged()
    {
        foreach (var watch in watches ?? [])
            if (watch.Change() is { } change)
                throw new CliException(ExitCodes.DatUnreadable,
                    $"the dat changed while this run read it: {change}; nothing read after the change can be trusted: run again once the dat is complete");
    }

    /// <summary>How often <see cref="RequireUnchangedNowAndThen"/> looks.</summary>
    public static readonly TimeSpan ChangeCheckInterval = TimeSpan.FromMilliseconds(50);

    private long _lastCheck = Stopwatch.GetTimestamp();

    /// <summary>
    /// <see cref="RequireUnchanged"/> at most once per <see cref="ChangeCheckInterval"/>, for a run that asks after
    /// every object. Each look is several calls into the kernel for each file: after every Setup of a batch they were
    /// about 30,000 calls on the 3,000-Setup scale dat, each taking 2-3 times as long with two jobs as with one
    /// under strace (docs/performance.md). The run's end still looks once more, unthrottled.
    /// </summary>
    public void RequireUnchangedNowAndThen()
    {
        var now = Stopwatch.GetTimestamp();
        var last = Interlocked.Read(ref _lastCheck);
        if (Stopwatch.GetElapsedTime(last, now) < ChangeCheckInterval || Interlocked.CompareExchange(ref _lastCheck, now, last) != last) return;
        RequireUnchanged();
    }

    /// <summary>Whether <paramref name="path"/> names (through any link) a dat file this run reads.</summary>
    public bool Reads(string path) => FileKinds.Identity(path) is { } identity && IsOneOf(identity, ReadIdentities());

    /// <summary>The device and inode numbers of each dat file this run reads (a cell dat found beside the portal dat too, opened or not).</summary>
    public IReadOnlyList<byte[]> ReadIdentities() =>
        [.. (watches ?? []).Select(w => w.Identity).OfType<byte[]>(), .. foundCell is { File: var found } && FileKinds.Identity(found) is { } cell ? [cell] : Array.Empty<byte[]>()];

    /// <summary>Whether <paramref name="identity"/> is one of <paramref name="identities"/> (<see cref="ReadIdentities"/>).</summary>
    public static bool IsOneOf(byte[] identity, IReadOnlyList<byte[]> identities) => identities.Any(i => i.AsSpan().SequenceEqual(identity));

    /// <summary>
    /// A dat's identity with its content's SHA-256 (the whole file read once more): what batch records in
    /// index.json and verify compares, so a copy under another name is the same dat and a dat rewritten in
    /// place is not.
    /// </summary>
    public static DatSourceInfo Hashed(DatDatabase dat) => dat.Info with { Sha256 = dat.Archive.ContentSha256() };

    /// <summary>
    /// A second view over the portal archive that keeps at most <paramref name="objects"/> decoded objects
    /// (oldest dropped first), for a run over many objects: <see cref="Portal"/> keeps every object it decodes.
    /// This dat still owns and disposes the archive.
    /// </summary>
    public DatDatabase PortalWorkingSet(int objects) => new(Portal.Archive, objects);

    public void Dispose()
    {
        Portal.Dispose();
        if (_cell.IsValueCreated) _cell.Value?.Dispose();
    }
}
