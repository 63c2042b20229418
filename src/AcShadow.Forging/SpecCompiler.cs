using System.Numerics;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Forging.Bsp;
using AcShadow.Forging.Spec;

namespace AcShadow.Forging;

/// <summary>The forged files: the portal dat always, the cell dat only when the spec has landblocks.</summary>
public sealed record ForgedDats(byte[] Portal, byte[]? Cell, int GfxObjCount, int SetupCount, int LandblockCount)
{
    public int EnvironmentCount { get; init; }
    public int EnvCellCount { get; init; }
}

/// <summary>
/// Turns a spec into dat bytes with the Core records' own writers and <see cref="DatArchiveWriter"/>.
/// Same spec, same bytes: the date field is fixed and nothing depends on the clock or thread timing.
/// </summary>
public static class SpecCompiler
{
    /// <summary>Retail block sizes.</summary>
    public const int PortalBlockSize = 1024, CellBlockSize = 256;
    /// <summary>A fixed directory date keeps the bytes reproducible.</summary>
    public const uint RawDate = 0;

    public static ForgedDats Compile(ForgeSpec spec, BranchFill fill = BranchFill.Zero) => Compile(SpecValidator.Validate(spec), fill);

    /// <param name="fill">The directory's unused branch slots: retail's zeros, or DatReaderWriter's 0xCDCDCDCD.</param>
    public static ForgedDats Compile(ValidSpec spec, BranchFill fill = BranchFill.Zero)
    {
        var gfxBytes = new byte[spec.GfxObjs.Count][];
        // BSP building dominates; each GfxObj is independent, and results land by index, so order is fixed.
        Parallel.For(0, spec.GfxObjs.Count, i => gfxBytes[i] = Serialize(ToGfxObj(spec.GfxObjs[i]).Write));

        var portal = new Dictionary<uint, byte[]>();
        for (var i = 0; i < gfxBytes.Length; i++) portal[spec.GfxObjs[i].Id] = gfxBytes[i];
        foreach (var setup in spec.Setups) portal[setup.Id] = Serialize(setup.Write);
        foreach (var table in spec.MotionTables) portal[table.Id] = Serialize(table.Write);
        foreach (var animation in spec.Animations) portal[animation.Id] = Serialize(animation.Write);
        foreach (var environment in spec.Environments) portal[environment.Id] = Serialize(ToEnvironment(environment).Write);
        // Real dats carry an Iteration record beside the header; it gives the same figure as the directory.
        var iteration = Serialize(IterationRecord.Single(spec.Iteration).Write);
        portal[IterationRecord.Id] = iteration;
        var portalDat = DatArchiveWriter.Write(portal, new DatArchiveWriter.Options(DatFileKind.Portal, PortalBlockSize, spec.Iteration, RawDate, Fill: fill));

        byte[]? cellDat = null;
        if (spec.Landblocks.Count > 0)
        {
            var cell = spec.Landblocks.ToDictionary(l => l.Id, l => Serialize(l.Write));
            foreach (var envCell in spec.Cells) cell[envCell.Id] = Serialize(envCell.Write);
            cell[IterationRecord.Id] = iteration;
            cellDat = DatArchiveWriter.Write(cell, new DatArchiveWriter.Options(DatFileKind.Cell, CellBlockSize, spec.Iteration, RawDate, Fill: fill));
        }
        return new ForgedDats(portalDat, cellDat, spec.GfxObjs.Count, spec.Setups.Count, spec.Landblocks.Count) { EnvironmentCount = spec.Environments.Count, EnvCellCount = spec.Cells.Count };
    }

    public static GfxObj ToGfxObj(ForgeGfxObj g)
    {
        var flags = (g.Physics ? GfxObjFlags.HasPhysics : 0) | (g.Drawing ? GfxObjFlags.HasDrawing : 0);
        var vertices = new Dictionary<ushort, Vector3>(g.Vertices.Count);
        for (var i = 0; i < g.Vertices.Count; i++) vertices[(ushort)i] = g.Vertices[i];
        var keyed = g.Polygons.Select((p, i) => new KeyValuePair<ushort, Polygon>((ushort)i, p)).ToArray();
        var bsp = g.Physics ? PhysicsBspBuilder.Build(g.Vertices, g.Polygons.Select(p => p.VertexIds).ToArray()) : null;
        return new GfxObj(g.Id, flags, [], vertices, g.Physics ? keyed : [], bsp, SortCenter(g.Vertices), g.Drawing ? keyed : []);
    }

    /// <summary>
    /// Cell shapes as real ones are stored: the walls are both physics and drawing polygons, the portal
    /// polygons drawing polygons after them, the PhysicsBSP built like a GfxObj's (a room is an open
    /// mesh, so its leaves are not solid), a one-leaf cell BSP and a one-leaf drawing BSP.
    /// </summary>
    public static CellEnvironment ToEnvironment(ForgeEnvironment e) => new(e.Id, e.CellStructs.Select((c, i) =>
    {
        var vertices = new Dictionary<ushort, Vector3>(c.Vertices.Count);
        for (var v = 0; v < c.Vertices.Count; v++) vertices[(ushort)v] = c.Vertices[v];
        var physics = c.Polygons.Select((p, k) => new KeyValuePair<ushort, Polygon>((ushort)k, p)).ToArray();
        var portals = c.Portals.Select((p, k) => new KeyValuePair<ushort, Polygon>((ushort)(c.Polygons.Count + k), p)).ToArray();
        var bsp = PhysicsBspBuilder.Build(c.Vertices, c.Polygons.Select(p => p.VertexIds).ToArray());
        var cellBsp = new CellBspNode(BspNodeType.Leaf, default, null, null, 0);
        return new KeyValuePair<uint, CellStruct>((uint)i, new CellStruct(vertices, [.. physics, .. portals], portals.Select(p => p.Key).ToArray(), cellBsp, physics, bsp, true));
    }).ToArray());

    /// <summary>The centre of the vertices' bounding box (drawing only; collision never reads it).</summary>
    private static Vector3 SortCenter(IReadOnlyList<Vector3> vertices)
    {
        if (vertices.Count == 0) return Vector3.Zero;
        var min = new Vector3(float.MaxValue);
        var max = new Vector3(float.MinValue);
        foreach (var v in vertices) { min = Vector3.Min(min, v); max = Vector3.Max(max, v); }
        return (min + max) * 0.5f;
    }

    private static byte[] Serialize(Action<DatBinaryWriter> write)
    {
        var w = new DatBinaryWriter();
        write(w);
        return w.ToArray();
    }
}
