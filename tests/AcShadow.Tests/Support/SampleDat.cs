using AcShadow.Core.Dat;
using AcShadow.Forging;

namespace AcShadow.Tests.Support;

/// <summary>The forged built-in sample, read back through the real dat reader.</summary>
public static class SampleDat
{
    private static readonly Lazy<(byte[] Portal, byte[]? Cell)> Bytes = new(SampleDats.Build);

    public static byte[] PortalBytes => Bytes.Value.Portal;
    public static byte[]? CellBytes => Bytes.Value.Cell;

    /// <summary>A fresh reader over the sample portal dat (each caller owns and disposes it).</summary>
    public static DatDatabase OpenPortal() => DatDatabase.Open(new MemoryStream(PortalBytes, writable: false), "client_portal.dat");

    /// <summary>Writes the sample dats into a new temporary folder, as a user's dat folder would look.</summary>
    public static TempDir WriteToTempFolder()
    {
        var dir = new TempDir();
        File.WriteAllBytes(Path.Combine(dir.Path, "client_portal.dat"), PortalBytes);
        if (CellBytes is not null) File.WriteAllBytes(Path.Combine(dir.Path, "client_cell_1.dat"), CellBytes);
        return dir;
    }
}
