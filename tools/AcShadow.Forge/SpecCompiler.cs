using System.Numerics;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;
using AcShadow.Forge.Bsp;
using AcShadow.Forge.Spec;

namespace AcShadow.Forge;

/// <summary>The forged files: the portal dat always, the cell dat only when the spec has landblocks.</summary>
public sealed record ForgedDats(byte[] Portal, byte[]? Cell, int GfxObjCount, int SetupCount, int LandblockCount);

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

    public static ForgedDats Compile(ForgeSpec spec) => Compile(SpecValidator.Validate(spec));

    public static ForgedDats Compile(ValidSpec spec)
    {
        var gfxBytes = new byte[spec.GfxObjs.Count][];
        // BSP building dominates; each GfxObj is independent, and results land by index, so order is fixed.
        Parallel.For(0, spec.GfxObjs.Count, i => gfxBytes[i] = Serialize(ToGfxObj(spec.GfxObjs[i]).Write));

        var portal = new Dictionary<uint, byte[]>();
        for (var i = 0; i < gfxBytes.Length; i++) portal[spec.GfxObjs[i].Id] = gfxBytes[i];
        foreach (var setup in spec.Setups) portal[setup.Id] = Serialize(setup.Write);
        foreach (var table in spec.MotionTables) portal[table.Id] = Serialize(table.Write);
        foreach (var animation in spec.Animations) portal[animation.Id] = Serialize(animation.Write);
        var portalDat = DatArchiveWriter.Write(portal, new DatArchiveWriter.Options(DatFileKind.Portal, PortalBlockSize, spec.Iteration, RawDate));

        byte[]? cellDat = null;
        if (spec.Landblocks.Count > 0)
        {
            var cell = spec.Landblocks.ToDictionary(l => l.Id, l => Serialize(l.Write));
            cellDat = DatArchiveWriter.Write(cell, new DatArchiveWriter.Options(DatFileKind.Cell, CellBlockSize, spec.Iteration, RawDate));
        }
        return new ForgedDats(portalDat, cellDat, spec.GfxObjs.Count, spec.Setups.Count, spec.Landblocks.Count);
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
