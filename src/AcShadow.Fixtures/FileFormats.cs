using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures;

/// <summary>One kind of file acshadow writes: its <c>format</c> value, where it goes, its schema.</summary>
public sealed record FileFormat(string Name, string Format, string PathPattern, string? SchemaId, string Description);

/// <summary>
/// Every file format acshadow writes, with the version this library reads. docs/formats.md describes them;
/// `acshadow formats` prints this list.
/// </summary>
public static class FileFormats
{
    public const string Shadow = "acshadow.shadow/2";
    public const string Bsp = "acshadow.bsp/1";
    public const string Index = "acshadow.index/1";
    public const string Scene = "acshadow.scene/1";
    public const string Audit = "acshadow.audit/1";
    public const string CompiledScene = "acshadow.compiled-scene/1";
    public const string Cell = "acshadow.cell/1";
    public const string Doctor = "acshadow.doctor/1";

    /// <summary>
    /// acdream's GfxObj fixture shape carries no format field (its field set is fixed by acdream); the
    /// name here is the one index.json lists the files under and the schema's title.
    /// </summary>
    public const string AcdreamGfxObj = "acdream.gfxobj";

    /// <summary>acdream's EnvCell fixture shape (its CellDump record); like its GfxObj shape, no format field.</summary>
    public const string AcdreamCell = "acdream.cell";

    public static IReadOnlyList<FileFormat> All { get; } =
    [
        new("shadow", Shadow, "setups/0x%08X.shadow.json", "urn:acshadow:schema:acshadow.shadow-2",
            "one Setup's collision shapes (the seed's ShadowShape fields), the pose its parts are in and the Setup facts behind them"),
        new("bsp", Bsp, "gfxobjs/0x%08X.bsp.json", "urn:acshadow:schema:acshadow.bsp-1",
            "one GfxObj's physics polygons, planes and PhysicsBSP tree"),
        new("scene", Scene, "scene.json", "urn:acshadow:schema:acshadow.scene-1",
            "a landblock's placed objects and buildings with world frames"),
        new("compiled-scene", CompiledScene, "compiled-scene.json", "urn:acshadow:schema:acshadow.compiled-scene-1",
            "a landblock compiled by `acshadow scene`: each object's cheapest exact model, its shapes and the evidence"),
        new("cell", Cell, "cells/0x%08X.cell.json", "urn:acshadow:schema:acshadow.cell-1",
            "one indoor cell (EnvCell): its frames, physics polygons with planes, PhysicsBSP, portals and the objects inside"),
        new("index", Index, "index.json", "urn:acshadow:schema:acshadow.index-1",
            "a batch's inputs and every file it wrote, with SHA-256"),
        new("audit", Audit, "(audit --format json --out FILE)", "urn:acshadow:schema:acshadow.audit-1",
            "the audit report: one row per Setup, a summary by category, what was skipped"),
        new("doctor", Doctor, "(doctor --out FILE)", "urn:acshadow:schema:acshadow.doctor-1",
            "the doctor report: a verdict, counts and example ids per check of acshadow's assumptions on a dat; no dat content"),
        new("acdream", AcdreamGfxObj, "gfxobjs/0x%08X.gfxobj.json", "urn:acshadow:schema:acdream.gfxobj",
            "acdream's GfxObj fixture shape (--format acdream): polygons with planes and vertices, no BSP tree"),
        new("acdream-cell", AcdreamCell, "cells/0x%08X.json", "urn:acshadow:schema:acdream.cell",
            "acdream's EnvCell fixture shape (--format acdream): transforms, polygons, portal polygons, portals, visible cells"),
    ];
}
