using System.Globalization;
using AcShadow.Core.Dat;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Json;

namespace AcShadow.Core.Batch;

/// <summary>
/// The ids of a `--setups FILE`: one Setup id a line ("0x020019FF" or "020019FF"), blank lines and
/// '#' comments (whole-line or trailing) ignored. <see cref="Name"/> is the file's name, for messages and
/// index.json; the ids themselves are recorded too, so verify does not need the file.
/// </summary>
public sealed record SetupList(string Name, IReadOnlyList<uint> Ids)
{
    /// <summary>Parses the file's text; a line that is not a Setup id is a <see cref="FormatException"/> naming the line.</summary>
    public static SetupList Parse(string name, string text)
    {
        var ids = new List<uint>();
        var lineNumber = 0;
        foreach (var raw in text.Split('\n'))
        {
            lineNumber++;
            var hash = raw.IndexOf('#');
            var line = (hash >= 0 ? raw[..hash] : raw).Trim();
            if (line.Length == 0) continue;
            if (!JsonIds.TryParse(line, out var id))
                throw new FormatException($"{name} line {lineNumber.ToString(CultureInfo.InvariantCulture)}: '{line}' is not a Setup id (write one hex id a line, e.g. 0x020019FF)");
            if (!DatObjectKind.Setup.Contains(id))
                throw new FormatException($"{name} line {lineNumber.ToString(CultureInfo.InvariantCulture)}: {JsonIds.Format(id)} is outside the Setup range {DatObjectKind.Setup.RangeText()}");
            ids.Add(id);
        }
        return new SetupList(name, ids.Distinct().Order().ToArray());
    }
}
