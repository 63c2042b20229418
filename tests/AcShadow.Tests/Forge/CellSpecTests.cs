using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;
using AcShadow.Forging;
using AcShadow.Forging.Spec;

namespace AcShadow.Tests.Forge;

/// <summary>The forge's environments and cells: what a spec says lands in the dats, and bad cells are one clear line.</summary>
public sealed class CellSpecTests
{
    private const string Environment = """
        { "id": "0x0D000001", "cellStructs": [ {
            "vertices": [[0,0,0],[2,0,0],[2,2,0],[0,2,0],[0,0,2],[2,0,2]],
            "polygons": [ { "vertices": [0,1,2,3] } ],
            "portals": [ { "vertices": [0,1,5,4] } ] } ] }
        """;

    private static string Spec(string cells, string numCells = "") => $$"""
        { "environments": [ {{Environment}} ],
          "landblocks": [ { "id": "0x0102FFFE"{{numCells}}, "cells": [ {{cells}} ] } ] }
        """;

    private const string Cell = """{ "environment": "0x0D000001", "origin": [10, 20, 3], "portals": [ { "polygon": 0, "otherCell": "outside", "flags": "PortalSide" } ] }""";

    private static string Error(string json)
    {
        var e = Assert.Throws<SpecException>(() => SpecCompiler.Compile(SpecJson.Parse(json)));
        Assert.DoesNotContain('\n', e.Message);
        return e.Message;
    }

    [Fact]
    public void Cells_and_their_environment_land_in_the_cell_and_portal_dats()
    {
        var dats = SpecCompiler.Compile(SpecJson.Parse(Spec($"{Cell}, {Cell.Replace("\"outside\"", "\"0x0100\"")}")));
        Assert.Equal(1, dats.EnvironmentCount);
        Assert.Equal(2, dats.EnvCellCount);
        using var portal = DatDatabase.Open(new MemoryStream(dats.Portal), "client_portal.dat");
        using var cell = DatDatabase.Open(new MemoryStream(dats.Cell!), "client_cell_1.dat");
        Assert.Equal(2u, cell.ReadLandBlockInfo(0x0102FFFE)!.NumCells);
        var first = cell.ReadEnvCell(0x01020100)!;
        Assert.Equal(new System.Numerics.Vector3(10, 20, 3), first.Position.Position);
        // The portal polygon follows the structure's one wall: drawing polygon id 1.
        Assert.Equal(new CellPortal(PortalFlags.PortalSide, 1, CellPortal.Outside, 0), Assert.Single(first.Portals));
        Assert.Equal((ushort)0x0100, Assert.Single(cell.ReadEnvCell(0x01020101)!.Portals).OtherCellId);
        var shape = portal.ReadEnvironment(0x0D000001)!.Cell(0)!;
        Assert.Equal([(ushort)1], shape.Portals);
        Assert.Equal([(ushort)0], shape.PhysicsPolygons.Select(p => p.Key));
        Assert.Equal([(ushort)0, (ushort)1], shape.Polygons.Select(p => p.Key));
    }

    [Theory]
    [InlineData("""{ "environment": "0x0D000002" }""", "landblocks[0] (0x0102FFFE) cells[0] (0x01020100): environment 0x0D000002 is not in this spec's environments; declare it")]
    [InlineData("""{ "environment": "0x0D000001", "cellStruct": 1 }""", "landblocks[0] (0x0102FFFE) cells[0] (0x01020100): cellStruct 1 is out of range; environment 0x0D000001 has 1 (0-0)")]
    [InlineData("""{ "environment": "0x0D000001", "portals": [ { "polygon": 1, "otherCell": "outside" } ] }""", "landblocks[0] (0x0102FFFE) cells[0] (0x01020100) portals[0]: polygon 1 is out of range; the cell structure has 1 portal polygon(s)")]
    [InlineData("""{ "environment": "0x0D000001", "portals": [ { "polygon": 0, "otherCell": "0x0100" } ] }""", "landblocks[0] (0x0102FFFE) cells[0] (0x01020100) portals[0] otherCell: 0x0100 is not another cell of this landblock (0x0100-0x0100, not itself) or \"outside\"")]
    [InlineData("""{ "environment": "0x0D000001", "visibleCells": ["0x0105"] }""", "landblocks[0] (0x0102FFFE) cells[0] (0x01020100) visibleCells[0]: 0x0105 is not another cell of this landblock (0x0100-0x0100, not itself)")]
    [InlineData("""{ "environment": "0x0D000001", "portals": [ { "polygon": 0, "otherCell": "outside", "flags": "Sideways" } ] }""", "landblocks[0] (0x0102FFFE) cells[0] (0x01020100) portals[0] flags: \"Sideways\" is not one of None, ExactMatch, PortalSide")]
    public void A_bad_cell_is_one_line_naming_it(string cell, string expected) => Assert.Equal(expected, Error(Spec(cell)));

    [Fact]
    public void A_cell_count_that_disagrees_and_an_environment_without_shapes_are_refused()
    {
        Assert.Equal("landblocks[0] (0x0102FFFE): numCells 3 but 1 cell(s) are given; leave numCells out (it is the number of cells)",
            Error(Spec(Cell, ", \"numCells\": 3")));
        Assert.Equal("environments[0] (0x0D000001): has no cellStructs; an environment needs at least one cell structure",
            Error("""{ "environments": [ { "id": "0x0D000001" } ] }"""));
        Assert.Equal("environments[0]: id 0x0E000001 is outside the Environment range 0x0D000000-0x0D00FFFF",
            Error("""{ "environments": [ { "id": "0x0E000001" } ] }"""));
    }
}
