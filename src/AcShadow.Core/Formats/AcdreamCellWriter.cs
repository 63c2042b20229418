using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Batch;
using AcShadow.Fixtures.Formats;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Cells;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Core.Formats;

/// <summary>
/// Writes an EnvCell in acdream's EnvCell fixture shape (its CellDump record): CellId (a
/// number), WorldTransform and InverseWorldTransform as {M11 … M44} (System.Numerics' row-vector
/// convention, <see cref="CellMatrices"/>; the frame is the landblock-relative one, as acdream's own
/// captured cells are), ResolvedPolygons (physics polygons with a plane, cell frame), PortalPolygons (each
/// portal polygon once, by id), Portals {OtherCellId, PolygonId, Flags} with the dat's 16-bit ids (0xFFFF:
/// outside) and VisibleCellIds as full cell ids. The BSP tree, the objects inside and degenerate polygons
/// are not in that shape.
/// </summary>
public static class AcdreamCellWriter
{
    /// <summary>The acdream file beside a cell file, from the records the cell file was written from.</summary>
    /// <param name="landblockFrame">The cell's frame in its landblock.</param>
    /// <param name="physics">The cell structure's physics polygons, in the cell's frame.</param>
    /// <param name="portals">The portals as the cell file lists them (other cells as full ids).</param>
    /// <param name="visibleCells">Full cell ids.</param>
    public static OutputFile File(uint cellId, Frame landblockFrame, BspDump physics, IReadOnlyList<CellPortalRecord> portals, IReadOnlyList<uint> visibleCells) =>
        new(FileFormats.AcdreamCell.PathFor(cellId), FixtureKind.AcdreamCell, cellId,
            CanonicalJsonWriter.WriteUtf8(ToJson(cellId, landblockFrame, physics, portals, visibleCells)), 0, physics.Polygons.Count(p => p.Plane is not null));

    private static JsonObj ToJson(uint cellId, Frame frame, BspDump physics, IReadOnlyList<CellPortalRecord> portals, IReadOnlyList<uint> visibleCells)
    {
        var positions = physics.Vertices.ToDictionary(v => v.Id, v => v.Position);
        var portalPolygons = portals.Where(p => p.Plane is not null).DistinctBy(p => p.PolygonId).OrderBy(p => p.PolygonId);
        return new JsonObj()
            .Add("CellId", JsonNum.Of((long)cellId))
            .Add("WorldTransform", Matrix(CellMatrices.World(frame)))
            .Add("InverseWorldTransform", Matrix(CellMatrices.Inverse(frame)))
            .Add("ResolvedPolygons", JsonArr.Of(physics.Polygons.Where(p => p.Plane is not null), p =>
                Polygon(p.Id, p.VertexIds.Count, (int)p.SidesType, p.Plane!.Value, p.VertexIds.Select(id => positions[id]))))
            .Add("PortalPolygons", JsonArr.Of(portalPolygons, p =>
                Polygon(p.PolygonId, p.Vertices.Count, (int)SidesType.Landblock, p.Plane!.Value, p.Vertices)))
            .Add("Portals", JsonArr.Of(portals, p => new JsonObj()
                .Add("OtherCellId", (int)(p.OtherCellId & 0xFFFF))
                .Add("PolygonId", p.PolygonId)
                .Add("Flags", p.Flags)))
            .Add("VisibleCellIds", JsonArr.Of(visibleCells, v => JsonNum.Of((long)v)));
    }

    private static JsonObj Polygon(int id, int points, int sidesType, Plane plane, IEnumerable<Vector3> vertices) => new JsonObj()
        .Add("Id", id)
        .Add("NumPoints", points)
        .Add("SidesType", sidesType)
        .Add("Plane", new JsonObj().Add("Normal", Xyz(plane.Normal)).Add("D", plane.D))
        .Add("Vertices", JsonArr.Of(vertices, v => Xyz(v)));

    private static JsonObj Matrix(Matrix4x4 m) => new JsonObj()
        .Add("M11", m.M11).Add("M12", m.M12).Add("M13", m.M13).Add("M14", m.M14)
        .Add("M21", m.M21).Add("M22", m.M22).Add("M23", m.M23).Add("M24", m.M24)
        .Add("M31", m.M31).Add("M32", m.M32).Add("M33", m.M33).Add("M34", m.M34)
        .Add("M41", m.M41).Add("M42", m.M42).Add("M43", m.M43).Add("M44", m.M44);

    private static JsonObj Xyz(Vector3 v) => new JsonObj().Add("X", v.X).Add("Y", v.Y).Add("Z", v.Z);
}
