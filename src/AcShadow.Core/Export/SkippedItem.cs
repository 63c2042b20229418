using AcShadow.Core.Json;
using AcShadow.Fixtures.Json;

namespace AcShadow.Core.Export;

/// <summary>An id the selection asked for that the run could not export, and why. Reported, never fatal.</summary>
public sealed record SkippedItem(uint Id, string Reason, SelectionSource From)
{
    public const string NotInDat = "not in the dat";

    public override string ToString() => $"{JsonIds.Format(Id)}: {Reason} (from {string.Join(", ", From.Names())})";
}
