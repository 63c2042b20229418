using System.Numerics;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;

namespace AcShadow.Tests.Cells;

/// <summary>
/// EnvCell (cell dat) and Environment / CellStruct (portal dat) against bytes laid out by hand from
/// DatReaderWriter's dats.xml (EnvCell, Environment, CellStruct, CellPortal; the Cell/Physics/Drawing BSP
/// node readers) and ACE's DatLoader (EnvCell.Unpack, CellStruct.Unpack, BSPNode/BSPLeaf/BSPPortal with
/// their tree type), which agree on every field used here.
/// </summary>
public class CellLayoutTests
{
    /// <summary>
    /// EnvCell 0xA9B40105: flags SeenOutside | HasStaticObjs | HasRestrictionObj (0xB), the id again,
    /// 2 surfaces (byte), 1 portal (byte), 3 visible cells (ushort), surfaces 0x0032 0x0033, environment
    /// 0x0123, cell structure 4, frame (1, 2, 3) with W X Y Z = (0.5, 0.5, 0.5, 0.5), the portal (flags
    /// 3, polygon 7, other cell 0xFFFF, other portal 2), visible cells 0x0100 0x0101 0x0106, one stab
    /// (0x02003300 at (4, 5, 6), identity), restriction 0xBEEF. No padding: the stab count sits at offset 66,
    /// not a multiple of 4, and both readers read it there.
    /// </summary>
    private static byte[] EnvCellBytes() => new HandBytes()
        .U32(0xA9B40105).U32(0xB).U32(0xA9B40105)
        .U8(2).U8(1).U16(3)
        .U16(0x32).U16(0x33)
        .U16(0x123).U16(4)
        .Floats(1, 2, 3).Floats(0.5f, 0.5f, 0.5f, 0.5f)
        .U16(3).U16(7).U16(0xFFFF).U16(2)
        .U16(0x100).U16(0x101).U16(0x106)
        .U32(1).U32(0x02003300).Floats(4, 5, 6).Floats(1, 0, 0, 0)
        .U32(0xBEEF)
        .ToArray();

    [Fact]
    public void An_EnvCell_reads_field_by_field_as_laid_out()
    {
        var bytes = EnvCellBytes();
        Assert.Equal(4 * 3 + 4 + 4 + 4 + 28 + 8 + 6 + 4 + 32 + 4, bytes.Length);
        var cell = EnvCell.Read(new DatBinaryReader(bytes));
        Assert.Equal(0xA9B40105u, cell.Id);
        Assert.Equal(EnvCellFlags.SeenOutside | EnvCellFlags.HasStaticObjs | EnvCellFlags.HasRestrictionObj, cell.Flags);
        Assert.Equal([(ushort)0x32, (ushort)0x33], cell.Surfaces);
        Assert.Equal(0x0D000123u, cell.EnvironmentFileId);
        Assert.Equal(4, cell.CellStructure);
        Assert.Equal(new Vector3(1, 2, 3), cell.Position.Position);
        Assert.Equal(new Quaternion(0.5f, 0.5f, 0.5f, 0.5f), cell.Position.Rotation);
        var portal = Assert.Single(cell.Portals);
        Assert.Equal(new CellPortal(PortalFlags.ExactMatch | PortalFlags.PortalSide, 7, 0xFFFF, 2), portal);
        Assert.True(portal.LeadsOutside);
        Assert.Equal([(ushort)0x100, (ushort)0x101, (ushort)0x106], cell.VisibleCells);
        Assert.Equal(0xA9B40106u, cell.Sibling(cell.VisibleCells[2]));
        var stab = Assert.Single(cell.StaticObjects);
        Assert.Equal(0x02003300u, stab.Id);
        Assert.Equal(new Vector3(4, 5, 6), stab.Frame.Position);
        Assert.Equal(0xBEEFu, cell.RestrictionObj);
    }

    [Fact]
    public void The_EnvCell_writer_puts_down_the_same_bytes()
    {
        var bytes = EnvCellBytes();
        var w = new DatBinaryWriter();
        EnvCell.Read(new DatBinaryReader(bytes)).Write(w);
        Assert.Equal(bytes, w.ToArray());
    }

    [Fact]
    public void Without_flags_an_EnvCell_ends_after_its_visible_cells()
    {
        var bytes = new HandBytes().U32(0x01020100).U32(0).U32(0x01020100).U8(0).U8(0).U16(0).U16(1).U16(0)
            .Floats(0, 0, 0).Floats(1, 0, 0, 0).ToArray();
        var cell = EnvCell.Read(new DatBinaryReader(bytes));
        Assert.Empty(cell.StaticObjects);
        Assert.Equal(0x0D000001u, cell.EnvironmentFileId);
        Assert.Equal(4 * 3 + 4 + 4 + 28, bytes.Length);
    }

    [Fact]
    public void A_truncated_EnvCell_or_a_second_id_that_disagrees_is_refused()
    {
        var bytes = EnvCellBytes();
        Assert.Throws<DatFormatException>(() => EnvCell.Read(new DatBinaryReader(bytes.AsMemory(0, bytes.Length - 2))));
        var other = (byte[])bytes.Clone();
        other[8] = 0x06;
        Assert.Contains("stored twice", Assert.Throws<DatFormatException>(() => EnvCell.Read(new DatBinaryReader(other))).Message);
        var hugeStabs = (byte[])bytes.Clone();
        hugeStabs[66] = 0xFF; hugeStabs[67] = 0xFF; hugeStabs[68] = 0xFF;
        Assert.Contains("static object count", Assert.Throws<DatFormatException>(() => EnvCell.Read(new DatBinaryReader(hugeStabs))).Message);
    }

    /// <summary>
    /// Environment 0x0D000123 with one cell structure (key 2): 2 drawing polygons, 1 physics polygon, 1
    /// portal; 3 vertices (the first with one UV, which is stepped over); drawing polygon 0 a triangle with
    /// stippling NoPos (no UV indices), polygon 1 the portal triangle with stippling None and sides 0 (3
    /// positive UV indices); the portal list [1] (2 bytes, at offset 163, then 3 bytes of padding to a
    /// multiple of 4 counted from the object's start); a cell BSP of one BPIn node (plane, positive leaf 5); the physics polygon
    /// 0; a physics leaf (index 0, solid 1, sphere, 1 polygon); the drawing-BSP flag (a uint, 1); a drawing
    /// PORT node (plane, two leaves, sphere, 1 polygon, 1 portal reference); padding to 4.
    /// </summary>
    private static byte[] EnvironmentBytes()
    {
        var b = new HandBytes().U32(0x0D000123).U32(1).U32(2);
        b.U32(2).U32(1).U32(1);
        b.I32(1).U32(3);
        b.U16(0).U16(1).Floats(0, 0, 0).Floats(0, 0, 1).Floats(0.25f, 0.75f);
        b.U16(1).U16(0).Floats(1, 0, 0).Floats(0, 0, 1);
        b.U16(2).U16(0).Floats(0, 1, 0).Floats(0, 0, 1);
        b.U16(0).U8(3).U8(0x04).I32(0).I16(0).I16(0).I16(0).I16(1).I16(2);
        b.U16(1).U8(3).U8(0x00).I32(0).I16(0).I16(0).I16(0).I16(2).I16(1).U8(0).U8(1).U8(2);
        b.U16(1);
        while (b.Length % 4 != 0) b.U8(0);
        b.Tag("BPIn").Floats(0, 0, 1, -0.5f).Tag("LEAF").I32(5);
        b.U16(0).U8(3).U8(0x04).I32(1).I16(0).I16(0).I16(0).I16(1).I16(2);
        b.Tag("LEAF").I32(0).I32(1).Floats(0.5f, 0.5f, 0, 0.75f).U32(1).U16(0);
        b.U32(1);
        b.Tag("PORT").Floats(1, 0, 0, 0).Tag("LEAF").I32(0).Tag("LEAF").I32(1).Floats(0, 0, 0, 2).U32(1).U32(1).U16(0).I16(1).I16(0);
        while (b.Length % 4 != 0) b.U8(0);
        return b.ToArray();
    }

    [Fact]
    public void An_Environment_and_its_cell_structure_read_as_laid_out()
    {
        var bytes = EnvironmentBytes();
        Assert.Equal(320, bytes.Length);
        var r = new DatBinaryReader(bytes);
        var environment = CellEnvironment.Read(r);
        Assert.Equal(0, r.Remaining);
        Assert.Equal(0x0D000123u, environment.Id);
        var (key, cell) = Assert.Single(environment.Cells);
        Assert.Equal(2u, key);
        Assert.Same(cell, environment.Cell(2));
        Assert.Null(environment.Cell(0));
        Assert.Equal(new[] { new Vector3(0, 0, 0), new Vector3(1, 0, 0), new Vector3(0, 1, 0) }, cell.Vertices.OrderBy(v => v.Key).Select(v => v.Value));
        Assert.Equal([(ushort)0, (ushort)1], cell.Polygons.Select(p => p.Key));
        Assert.Equal([(short)0, (short)2, (short)1], cell.Polygons[1].Value.VertexIds);
        Assert.Equal([(ushort)1], cell.Portals);
        Assert.Equal(BspNodeType.BPIn, cell.CellBsp.Type);
        Assert.Equal(new Plane(0, 0, 1, -0.5f), cell.CellBsp.SplittingPlane);
        Assert.Equal(5, cell.CellBsp.Pos!.LeafIndex);
        Assert.Null(cell.CellBsp.Neg);
        var (physicsKey, physics) = Assert.Single(cell.PhysicsPolygons);
        Assert.Equal(0, physicsKey);
        Assert.Equal(SidesType.None, physics.SidesType);
        Assert.True(cell.PhysicsBsp.IsLeaf);
        Assert.Equal(1, cell.PhysicsBsp.Solid);
        Assert.Equal([(ushort)0], cell.PhysicsBsp.Polygons);
        Assert.True(cell.HasDrawingBsp);
    }

    [Fact]
    public void A_cell_structure_the_forge_writes_reads_back_the_same()
    {
        var environment = CellEnvironment.Read(new DatBinaryReader(EnvironmentBytes()));
        var w = new DatBinaryWriter();
        environment.Write(w);
        var again = CellEnvironment.Read(new DatBinaryReader(w.ToArray()));
        var (a, b) = (environment.Cells[0].Value, again.Cells[0].Value);
        Assert.Equal(a.Vertices.OrderBy(v => v.Key), b.Vertices.OrderBy(v => v.Key));
        Assert.Equal(a.Portals, b.Portals);
        Assert.Equal(a.PhysicsBsp.Polygons, b.PhysicsBsp.Polygons);
        Assert.Equal(a.CellBsp.Pos!.LeafIndex, b.CellBsp.Pos!.LeafIndex);
        Assert.Equal(0, w.ToArray().Length % 4);
    }

    [Theory]
    [InlineData(13)]
    [InlineData(60)]
    [InlineData(120)]
    public void A_truncated_Environment_is_refused(int cut)
    {
        var bytes = EnvironmentBytes();
        Assert.Throws<DatFormatException>(() => CellEnvironment.Read(new DatBinaryReader(bytes.AsMemory(0, bytes.Length - cut))));
    }

    [Fact]
    public void A_node_tag_that_is_no_tag_is_refused_in_every_tree()
    {
        var bytes = EnvironmentBytes();
        var cellBspAt = IndexOfTag(bytes, "BPIn");
        bytes[cellBspAt] = (byte)'x';
        Assert.Contains("cell BSP node tag", Assert.Throws<DatFormatException>(() => CellEnvironment.Read(new DatBinaryReader(bytes))).Message);
        bytes = EnvironmentBytes();
        bytes[IndexOfTag(bytes, "PORT")] = (byte)'x';
        Assert.Contains("drawing BSP node tag", Assert.Throws<DatFormatException>(() => CellEnvironment.Read(new DatBinaryReader(bytes))).Message);
    }

    [Fact]
    public void Cell_and_Environment_ids_have_their_own_ranges()
    {
        Assert.True(DatObjectKind.EnvCell.Contains(0xA9B40100));
        Assert.True(DatObjectKind.EnvCell.Contains(0xA9B4FFFD));
        Assert.False(DatObjectKind.EnvCell.Contains(0xA9B40040));
        Assert.False(DatObjectKind.EnvCell.Contains(0xA9B4FFFE));
        Assert.True(DatObjectKind.Environment.Contains(0x0D00FFFF));
        Assert.False(DatObjectKind.Environment.Contains(0x0E000000));
    }

    private static int IndexOfTag(byte[] bytes, string tag)
    {
        var stored = System.Text.Encoding.ASCII.GetBytes(tag).Reverse().ToArray();
        for (var i = 0; i + 4 <= bytes.Length; i++)
            if (bytes.AsSpan(i, 4).SequenceEqual(stored)) return i;
        throw new InvalidOperationException(tag);
    }
}
