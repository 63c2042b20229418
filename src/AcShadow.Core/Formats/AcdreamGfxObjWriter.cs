using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Fixtures.Batch;
using AcShadow.Fixtures.Formats;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Json;

namespace AcShadow.Core.Formats;

/// <summary>
/// Writes a <see cref="BspDump"/> in acdream's GfxObj fixture shape: GfxObjId (a number),
/// BoundingSphereOrigin {X,Y,Z}, BoundingSphereRadius, and ResolvedPolygons, each with Id, NumPoints,
/// SidesType (a number), Plane {Normal {X,Y,Z}, D} and its Vertices in the polygon's own order. The BSP
/// tree, the stippling and the vertex ids are not in that shape. Degenerate polygons (no plane) are left
/// out: the shape has no way to say "no plane", and the collision reference never tests them either.
/// Numbers and layout follow the canonical writer, so the bytes are as deterministic as the canonical files.
/// </summary>
public static class AcdreamGfxObjWriter
{
    public static byte[] Write(BspDump dump) => CanonicalJsonWriter.WriteUtf8(ToJson(dump));

    /// <summary>The acdream file beside a canonical BSP dump, named by the same GfxObj id.</summary>
    public static OutputFile File(uint gfxObjId, BspDump dump) =>
        new(FileFormats.AcdreamGfxObj.PathFor(gfxObjId), FixtureKind.AcdreamGfxObj, gfxObjId, Write(dump), 0, PolygonCount(dump));

    /// <summary>How many polygons the file carries (those with a plane).</summary>
    private static int PolygonCount(BspDump dump) => dump.Polygons.Count(p => p.Plane is not null);

    private static JsonObj ToJson(BspDump dump)
    {
        var positions = dump.Vertices.ToDictionary(v => v.Id, v => v.Position);
        return new JsonObj()
            .Add("GfxObjId", JsonNum.Of((long)dump.GfxObjId))
            .Add("BoundingSphereOrigin", Xyz(dump.BoundingSphere.Center))
            .Add("BoundingSphereRadius", dump.BoundingSphere.Radius)
            .Add("ResolvedPolygons", JsonArr.Of(dump.Polygons.Where(p => p.Plane is not null), p => new JsonObj()
                .Add("Id", p.Id)
                .Add("NumPoints", p.VertexIds.Count)
                .Add("SidesType", (int)p.SidesType)
                .Add("Plane", new JsonObj().Add("Normal", Xyz(p.Plane!.Value.Normal)).Add("D", p.Plane.Value.D))
                .Add("Vertices", JsonArr.Of(p.VertexIds, id => Xyz(Position(positions, id, dump.GfxObjId, p.Id))))));
    }

    private static Vector3 Position(Dictionary<int, Vector3> positions, int id, uint gfxObjId, int polygon) =>
        positions.TryGetValue(id, out var v) ? v
            : throw new InvalidOperationException($"GfxObj {JsonIds.Format(gfxObjId)} polygon {polygon} uses vertex {id}, which the dump does not have");

    private static JsonObj Xyz(Vector3 v) => new JsonObj().Add("X", v.X).Add("Y", v.Y).Add("Z", v.Z);
}
