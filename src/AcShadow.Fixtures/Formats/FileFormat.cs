using AcShadow.Fixtures.Json;

namespace AcShadow.Fixtures.Formats;

/// <summary>
/// One kind of file acshadow writes: its short name, its <c>format</c> value (name and version), where it
/// goes in an output folder and what it holds. Its JSON Schema's <c>$id</c> follows from <see cref="Format"/>.
/// </summary>
/// <param name="Name">The short name: index.json's <c>kind</c> for the files a batch lists.</param>
/// <param name="Format">The file's <c>format</c> value: name, slash, version.</param>
/// <param name="PathPattern">
/// Relative to the output folder; <c>0x%08X</c> stands for the dat id a file is named by. A report written
/// wherever <c>--out</c> says has its option in parentheses instead.
/// </param>
/// <param name="Description">What one file holds, in a line.</param>
internal sealed record FileFormat(string Name, string Format, string PathPattern, string Description)
{
    private const string IdPlaceholder = "0x%08X";

    /// <summary>The schema's <c>$id</c>: the format with its version after a dash (urn:acshadow:schema:acshadow.bsp-1).</summary>
    public string SchemaId => "urn:acshadow:schema:" + Format.Replace('/', '-');

    /// <summary>The file of a dat id, relative to the output folder: setups/0x020019FF.shadow.json.</summary>
    /// <exception cref="InvalidOperationException">The format's files are not named by an id.</exception>
    public string PathFor(uint id) => PathPattern.Contains(IdPlaceholder, StringComparison.Ordinal)
        ? PathPattern.Replace(IdPlaceholder, JsonIds.Format(id), StringComparison.Ordinal)
        : throw new InvalidOperationException($"{Name} files are not named by an id (\"{PathPattern}\")");

    /// <summary>The one file of a format written once per folder (index.json, scene.json, compiled-scene.json).</summary>
    /// <exception cref="InvalidOperationException">The format has a file per id, or no fixed place.</exception>
    public string Path => PathPattern.Contains(IdPlaceholder, StringComparison.Ordinal) || PathPattern.StartsWith('(')
        ? throw new InvalidOperationException($"{Name} files have no one fixed path (\"{PathPattern}\")")
        : PathPattern;
}
