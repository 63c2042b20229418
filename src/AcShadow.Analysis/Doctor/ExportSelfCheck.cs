using System.Diagnostics;
using System.Security.Cryptography;
using AcShadow.Core.Batch;
using AcShadow.Core.Dat;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Doctor;

/// <summary>
/// The tool on the user's dat: `batch --all` run twice in memory (every file hashed, none written), each
/// run's index.json (which lists every file with its SHA-256) digested, and the two digests compared. Equal
/// digests mean the export is deterministic on this machine; the time of each run and the process's peak
/// memory are measured.
/// </summary>
public static class ExportSelfCheck
{
    /// <summary>What one check run found.</summary>
    public sealed record Outcome(int Setups, int Files, int Skipped, string FirstDigest, string SecondDigest, double FirstSeconds, double SecondSeconds)
    {
        public bool Identical => FirstDigest == SecondDigest;
    }

    /// <param name="archive">The portal dat's archive; each run reads it through a database of its own with a bounded cache, as batch does.</param>
    public static Outcome Run(DatArchive archive, int jobs, CancellationToken cancellation = default)
    {
        var (first, files, setups, skipped, firstSeconds) = Once(archive, jobs, cancellation);
        var (second, _, _, _, secondSeconds) = Once(archive, jobs, cancellation);
        return new Outcome(setups, files, skipped, first, second, firstSeconds, secondSeconds);
    }

    private static (string Digest, int Files, int Setups, int Skipped, double Seconds) Once(DatArchive archive, int jobs, CancellationToken cancellation)
    {
        var clock = Stopwatch.StartNew();
        // Decoded objects are kept only while in use, as in batch: memory does not grow with the dat.
        var source = new DatDatabase(archive, cacheCapacity: 256);
        var selection = new BatchSelection(false, true, null, null);
        var plan = BatchPlanner.Plan(selection, source, null, []);
        var options = new ShapeBuildOptions(ShapePolicy.Retail);
        var inputs = new BatchInputs(source.Info, null, options.Policy, options.EntityScale, selection);
        var summary = BatchRunner.Stream(source, options, plan, inputs, jobs, static _ => { }, null, null, cancellation);
        using var sha = SHA256.Create();
        using (var hashing = new CryptoStream(Stream.Null, sha, CryptoStreamMode.Write, leaveOpen: true))
            summary.WriteIndex(hashing);
        return (Convert.ToHexStringLower(sha.Hash!), summary.Files.Count, summary.SetupsWritten, summary.Skipped.Count, clock.Elapsed.TotalSeconds);
    }
}
