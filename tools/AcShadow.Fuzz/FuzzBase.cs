using AcShadow.Core.Dat;
using AcShadow.Forge;

namespace AcShadow.Fuzz;

/// <summary>
/// The intact dats every case starts from: the forge's built-in sample (portal and cell), their layouts,
/// the Setups `dump` may be asked for and the landblock `batch` exports.
/// </summary>
public sealed class FuzzBase
{
    public FuzzBase(byte[] portal, byte[] cell)
    {
        Portal = portal;
        Cell = cell;
        PortalLayout = new DatLayout(portal);
        CellLayout = new DatLayout(cell);
        SetupIds = PortalLayout.Objects.Select(o => o.Id).Where(id => DatObjectKind.Setup.Contains(id)).ToArray();
        Landblock = CellLayout.Objects.Select(o => o.Id).First(id => DatObjectKind.LandBlockInfo.Contains(id)) >> 16;
    }

    public static FuzzBase Sample()
    {
        var (portal, cell) = SampleDats.Build();
        return new FuzzBase(portal, cell);
    }

    public byte[] Portal { get; }
    public byte[] Cell { get; }
    public DatLayout PortalLayout { get; }
    public DatLayout CellLayout { get; }
    public IReadOnlyList<uint> SetupIds { get; }

    /// <summary>The landblock (0xXXYY) whose scene batch exports.</summary>
    public uint Landblock { get; }
}
