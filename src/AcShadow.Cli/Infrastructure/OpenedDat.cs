using AcShadow.Core.Dat;

namespace AcShadow.Cli.Infrastructure;

/// <summary>An open portal dat (and cell dat when one was asked for), with how to name it to the user.</summary>
public sealed class OpenedDat(DatDatabase portal, DatDatabase? cell, string description, bool isSample) : IDisposable
{
    public DatDatabase Portal { get; } = portal;
    public DatDatabase? Cell { get; } = cell;
    public string Description { get; } = description;
    public bool IsSample { get; } = isSample;

    public void Dispose()
    {
        Portal.Dispose();
        Cell?.Dispose();
    }
}
