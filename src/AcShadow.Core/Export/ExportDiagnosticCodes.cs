namespace AcShadow.Core.Export;

/// <summary>
/// The diagnostic codes the export adds to the builders' (<c>DiagnosticCodes</c>, <c>PoseDiagnosticCodes</c>):
/// stable, for consumers that filter on them. Scene compile (Analysis) reports the same faults with the same codes.
/// </summary>
public static class ExportDiagnosticCodes
{
    /// <summary>A placed object or an indoor cell that could not be turned into shapes (not in the dat, unreadable, another kind of id, a cell structure that is missing or a frame that is not finite).</summary>
    public const string Unresolved = "unresolved";
    /// <summary>A fault in a GfxObj's or cell structure's physics geometry found while extracting its BSP (NaN vertices, a one-child node, a subtree past the depth limit).</summary>
    public const string BspGeometry = "bsp-geometry";
    /// <summary>An indoor cell's portal that names a polygon the cell structure cannot give.</summary>
    public const string PortalPolygon = "portal-polygon";
}
