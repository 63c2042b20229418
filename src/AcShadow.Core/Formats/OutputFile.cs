using System.Text;
using AcShadow.Fixtures.Batch;

namespace AcShadow.Core.Formats;

/// <summary>
/// One output file in memory: where it goes (relative to the output folder, '/' separated) and its bytes.
/// Every command's files are these: an export's (shadow, BSP, cell, scene files) also carry what index.json
/// lists of them (<see cref="Listing"/>); chart's, scene's and view's carry none. A file handed to a
/// streaming batch's writer may lend its bytes (<see cref="Json.Utf8JsonText.Lend"/>): they are valid only
/// during that call, so a writer that keeps files keeps a copy.
/// </summary>
public sealed record OutputFile(string RelativePath, ReadOnlyMemory<byte> Content)
{
    /// <summary>An export's file, listed in index.json as <paramref name="kind"/> of object <paramref name="id"/>.</summary>
    public OutputFile(string relativePath, FixtureKind kind, uint id, ReadOnlyMemory<byte> content, int shapeCount, int polygonCount)
        : this(relativePath, content) => Listing = new OutputFileListing(kind, id, shapeCount, polygonCount);

    /// <summary>A text file, written as UTF-8 without a byte-order mark (as every acshadow text file is).</summary>
    public static OutputFile Text(string relativePath, string text) => new(relativePath, Utf8.GetBytes(text));

    private static readonly UTF8Encoding Utf8 = new(false);

    /// <summary>What index.json lists of an export's file; null for a file no index lists.</summary>
    public OutputFileListing? Listing { get; init; }

    /// <summary>
    /// Makes the same content as acdream's fixture file, from the records this file was written from (null: the
    /// format has no acdream shape). Made only when the run asks for acdream's format.
    /// </summary>
    public Func<OutputFile>? Acdream { get; init; }
}
