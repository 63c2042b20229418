using System.Globalization;
using AcShadow.Fixtures.Cells;

namespace AcShadow.Fuzz;

/// <summary>
/// Saved reproducers: one folder per failure holding client_portal.dat, client_cell_1.dat and case.txt
/// (the Setup dump is asked for, the landblock batch exports, the policy and format, the signature and the
/// mutation), read back by the regression tests.
/// </summary>
public static class ReproducerStore
{
    public const string PortalFile = "client_portal.dat";
    public const string CellFile = "client_cell_1.dat";
    public const string CaseFile = "case.txt";

    public static string Save(string root, string name, FuzzInput input, CaseFailure failure)
    {
        var folder = Path.Combine(root, name);
        Directory.CreateDirectory(folder);
        File.WriteAllBytes(Path.Combine(folder, PortalFile), input.Portal);
        File.WriteAllBytes(Path.Combine(folder, CellFile), input.Cell);
        File.WriteAllText(Path.Combine(folder, CaseFile),
            $"dump-setup: 0x{input.DumpSetup:X8}\nlandblock: 0x{input.Landblock:X4}\npolicy: {input.Policy}\nformat: {input.Format}\nsignature: {OneLine(failure.Signature)}\nmutation: {OneLine(input.Description)}\n");
        return folder;
    }

    public static FuzzInput Load(string folder)
    {
        var fields = File.ReadAllLines(Path.Combine(folder, CaseFile))
            .Select(l => l.Split(": ", 2))
            .Where(p => p.Length == 2)
            .ToDictionary(p => p[0], p => p[1]);
        return new FuzzInput(
            File.ReadAllBytes(Path.Combine(folder, PortalFile)),
            File.ReadAllBytes(Path.Combine(folder, CellFile)),
            ParseHex(fields["dump-setup"]),
            ParseHex(fields["landblock"]),
            fields.GetValueOrDefault("mutation", Path.GetFileName(folder)))
        {
            Policy = fields.GetValueOrDefault("policy", "retail"),
            Format = fields.GetValueOrDefault("format", "canonical"),
        };
    }

    private static uint ParseHex(string text) => uint.Parse(text.AsSpan(2), NumberStyles.HexNumber, CultureInfo.InvariantCulture);

    private static string OneLine(string text) => text.Split('\n')[0].Trim();
}
