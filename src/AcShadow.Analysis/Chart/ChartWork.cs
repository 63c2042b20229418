using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;

namespace AcShadow.Analysis.Chart;

/// <summary>
/// A rough size for charting each object, read from the dat's directory without decoding any GfxObj: the
/// stored bytes of the GfxObjs a Setup flagged HasPhysicsBSP is made of (vertices, polygons and BSP nodes
/// are most of them, and they are what the grid, the stability probes and every model's answers grow
/// with); 0 for other Setups, whose cost is the fixed one every object has. Only for an ETA: on the scale
/// dat a Setup has from 0 to 7,844 physics polygons and the BSP-bearing half comes first by id, so
/// counting objects misleads. Reading the 7,000 Setups for it took 65 ms.
/// </summary>
public static class ChartWork
{
    // A damaged directory can claim gigabytes for one object; no real GfxObj comes near this.
    private const long MaxBytesPerPart = 16L << 20;

    /// <summary>Per object, in chart order: the Setups, then the bare GfxObjs. An object that cannot be read weighs 0.</summary>
    public static double[] Of(IDatSource dat, IReadOnlyList<uint> setupIds, IReadOnlyList<uint> bareGfxObjIds)
    {
        var work = new double[setupIds.Count + bareGfxObjIds.Count];
        for (var i = 0; i < setupIds.Count; i++)
        {
            try
            {
                // A Setup without the HasPhysicsBSP flag (creatures, items) has parts that carry drawing meshes
                // only: their bytes say nothing of its chart, which costs what any object's does.
                if (dat.ReadSetup(setupIds[i]) is { } setup && setup.Flags.HasFlag(SetupFlags.HasPhysicsBsp))
                    foreach (var part in setup.Parts) work[i] += Bytes(dat, part);
            }
            catch (DatFormatException)
            {
                // Charting skips it too, with its reason.
            }
        }
        for (var i = 0; i < bareGfxObjIds.Count; i++) work[setupIds.Count + i] = Bytes(dat, bareGfxObjIds[i]);
        return work;
    }

    private static double Bytes(IDatSource dat, uint id)
    {
        try
        {
            return Math.Min(dat.StoredSize(id) ?? 0, MaxBytesPerPart);
        }
        catch (DatFormatException)
        {
            return 0;
        }
    }
}
