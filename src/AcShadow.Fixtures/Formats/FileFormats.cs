namespace AcShadow.Fixtures.Formats;

/// <summary>
/// Every file format acshadow writes, each described once: the version this library reads and the tool
/// writes, where its files go, its schema. docs/formats.md describes the fields; `acshadow formats` prints
/// this list.
/// </summary>
internal static class FileFormats
{
    public static FileFormat Shadow { get; } = new("shadow", "acshadow.shadow/2", "setups/0x%08X.shadow.json",
        "one Setup's collision shapes (the seed's ShadowShape fields), the pose its parts are in and the Setup facts behind them");

    public static FileFormat Bsp { get; } = new("bsp", "acshadow.bsp/1", "gfxobjs/0x%08X.bsp.json",
        "one GfxObj's physics polygons, planes and PhysicsBSP tree");

    /// <summary>
    /// One run describes at most one landblock, as it writes one index.json. The file sits at the root beside
    /// setups/ and gfxobjs/, so the output-relative paths of the files it names are also relative to it.
    /// </summary>
    public static FileFormat Scene { get; } = new("scene", "acshadow.scene/1", "scene.json",
        "a landblock's placed objects and buildings with world frames");

    public static FileFormat CompiledScene { get; } = new("compiled-scene", "acshadow.compiled-scene/1", "compiled-scene.json",
        "a landblock compiled by `acshadow scene`: each object's cheapest exact model, its shapes and the evidence");

    public static FileFormat Cell { get; } = new("cell", "acshadow.cell/1", "cells/0x%08X.cell.json",
        "one indoor cell (EnvCell): its frames, physics polygons with planes, PhysicsBSP, portals and the objects inside");

    /// <summary>One object Setup's golden movement suite (every case of every state it was generated in).</summary>
    public static FileFormat Movement { get; } = new("movement", "acshadow.movement-case/1", "movement/0x%08X.movement.json",
        "one object Setup's golden movement cases: the object per state, the mover, walks and the reference's frames and outcomes");

    public static FileFormat Index { get; } = new("index", "acshadow.index/1", "index.json",
        "a batch's inputs and every file it wrote, with SHA-256");

    public static FileFormat Audit { get; } = new("audit", "acshadow.audit/1", "(audit --format json --out FILE)",
        "the audit report: one row per Setup, a summary by category, what was skipped");

    public static FileFormat Doctor { get; } = new("doctor", "acshadow.doctor/1", "(doctor --out FILE)",
        "the doctor report: a verdict, counts and example ids per check of acshadow's assumptions on a dat; no dat content");

    /// <summary>
    /// acdream's GfxObj fixture shape carries no format field (acdream fixes its fields); the format here is
    /// the schema's title. The files sit beside the canonical dumps.
    /// </summary>
    public static FileFormat AcdreamGfxObj { get; } = new("acdream", "acdream.gfxobj", "gfxobjs/0x%08X.gfxobj.json",
        "acdream's GfxObj fixture shape (--format acdream): polygons with planes and vertices, no BSP tree");

    /// <summary>acdream's EnvCell fixture shape (its CellDump record), no format field; acdream's readers look for 0x%08X.json.</summary>
    public static FileFormat AcdreamCell { get; } = new("acdream-cell", "acdream.cell", "cells/0x%08X.json",
        "acdream's EnvCell fixture shape (--format acdream): transforms, polygons, portal polygons, portals, visible cells");

    /// <summary>In the order <c>acshadow formats</c> lists them.</summary>
    public static IReadOnlyList<FileFormat> All { get; } =
        [Shadow, Bsp, Scene, CompiledScene, Cell, Movement, Index, Audit, Doctor, AcdreamGfxObj, AcdreamCell];
}
