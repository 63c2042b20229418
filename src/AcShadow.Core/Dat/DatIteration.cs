using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;

namespace AcShadow.Core.Dat;

/// <summary>
/// A dat's iteration: its Iteration record's current figure when it has one (real dats do), else the
/// largest iteration any directory entry carries. A record that cannot be read does not stop the dat from
/// being used (nothing acshadow computes depends on it): the directory's figure stands, and the source says so.
/// </summary>
public static class DatIteration
{
    public static (int Iteration, DatIterationSource Source) Of(DatArchive archive)
    {
        var damaged = false;
        try
        {
            if (archive.ReadObjectBytes(IterationRecord.Id) is { } bytes)
                return (IterationRecord.Read(new DatBinaryReader(bytes)).Current, DatIterationSource.Record);
        }
        catch (DatFormatException)
        {
            damaged = true;
        }
        return (archive.MaxIteration, damaged ? DatIterationSource.UnreadableRecord : DatIterationSource.Directory);
    }
}
