using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;
using AcShadow.Forging.Spec;
using AcShadow.Forge;
using AcShadow.Forging;

namespace AcShadow.Tests.Forge;

/// <summary>Each object type survives spec → forge → file on disk → DatDatabase unchanged.</summary>
public sealed class SpecRoundTripTests
{
    private const string Spec = """
    {
      "iteration": 7,
      "gfxObjs": [
        { "id": "0x01000010", "physics": true, "drawing": true,
          "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 1.25]],
          "polygons": [
            { "vertices": [0, 3, 2, 1] },
            { "vertices": [0, 1, 4], "sidesType": "None" },
            { "vertices": [1, 2, 4], "sidesType": "Clockwise", "stippling": "NoPos, NoNeg" },
            { "vertices": [2, 3, 4], "sidesType": "CounterClockwise", "stippling": "Positive" },
            { "vertices": [3, 0, 4] }
          ] },
        { "id": "0x01000011", "drawing": true,
          "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "polygons": [ { "vertices": [0, 1, 2] } ] }
      ],
      "setups": [
        { "id": "0x02000010", "parts": ["0x01000010", "0x01000011"],
          "placements": {
            "Resting": [ { "origin": [1, 2, 3], "orientation": { "w": 0, "x": 0, "y": 0, "z": 1 } }, {} ],
            "Placement0x11": [ {}, { "origin": [0, 0, -0.5] } ]
          },
          "cylSpheres": [ { "origin": [0, 0, 0.1], "radius": 0.4, "height": 1.7 } ],
          "spheres": [ { "center": [0, 0, 0.5], "radius": 0.6 } ],
          "radius": 1.5, "height": 2.5, "stepUpHeight": 0.4, "stepDownHeight": 0.3,
          "sortingSphere": { "center": [0, 0, 1], "radius": 2 },
          "selectionSphere": { "center": [0, 0, 1.1], "radius": 2.1 },
          "defaultScale": [[1, 1, 1.5], [0.5, 2, 1]],
          "flags": ["AllowFreeHeading", "HasPhysicsBsp"] }
      ],
      "landblocks": [
        { "id": "0x1234FFFE", "numCells": 3,
          "objects": [ { "id": "0x02000010", "origin": [10, 20, 30], "orientation": { "w": 0.5, "x": 0.5, "y": 0.5, "z": 0.5 } },
                       { "id": "0x01000010", "origin": [1, 2, 3] } ],
          "buildings": [ { "modelId": "0x01000010", "origin": [96, 96, 5], "numLeaves": 2 } ] }
      ]
    }
    """;

    private static ForgedFiles Forge() => ForgedFiles.Write(SpecCompiler.Compile(SpecJson.Parse(Spec)));

    [Fact]
    public void GfxObj_round_trips_vertices_polygons_flags_and_a_bsp()
    {
        using var files = Forge();
        var gfx = files.Portal.ReadGfxObj(0x01000010)!;
        Assert.Equal(GfxObjFlags.HasPhysics | GfxObjFlags.HasDrawing, gfx.Flags);
        Assert.Equal(new Vector3(0.5f, 0.5f, 1.25f), gfx.Vertices[4]);
        Assert.Equal(5, gfx.Vertices.Count);
        Assert.Equal([0, 1, 2, 3, 4], gfx.PhysicsPolygons.Select(p => (int)p.Key));
        Assert.Equal([0, 3, 2, 1], gfx.PhysicsPolygons[0].Value.VertexIds.Select(v => (int)v));
        Assert.Equal([SidesType.Landblock, SidesType.None, SidesType.Clockwise, SidesType.CounterClockwise, SidesType.Landblock],
            gfx.PhysicsPolygons.Select(p => p.Value.SidesType));
        Assert.Equal(Stippling.NoPos | Stippling.NoNeg, gfx.PhysicsPolygons[2].Value.Stippling);
        Assert.Equal(Stippling.Positive, gfx.PhysicsPolygons[3].Value.Stippling);
        Assert.Empty(BspInvariants.Check(gfx));
        Assert.Equal(7, files.Portal.Info.Iteration);

        var drawing = files.Portal.ReadGfxObj(0x01000011)!;
        Assert.Equal(GfxObjFlags.HasDrawing, drawing.Flags);
        Assert.False(drawing.HasPhysics);
        Assert.Equal(3, drawing.Vertices.Count);
    }

    [Fact]
    public void Setup_round_trips_every_field()
    {
        using var files = Forge();
        var s = files.Portal.ReadSetup(0x02000010)!;
        Assert.Equal([0x01000010u, 0x01000011u], s.Parts);
        Assert.Equal(SetupFlags.AllowFreeHeading | SetupFlags.HasPhysicsBsp | SetupFlags.HasDefaultScale, s.Flags);
        Assert.Equal([new Vector3(1, 1, 1.5f), new Vector3(0.5f, 2, 1)], s.DefaultScale);
        Assert.Equal([Placement.Resting, 0x11u], s.PlacementFrames.Select(p => p.Placement));
        var resting = s.FindPlacement(Placement.Resting)!;
        Assert.Equal(new Frame(new Vector3(1, 2, 3), new Quaternion(0, 0, 1, 0)), resting.Frames[0]);
        Assert.Equal(Frame.Identity, resting.Frames[1]);
        Assert.Equal(new Vector3(0, 0, -0.5f), s.FindPlacement(0x11)!.Frames[1].Position);
        Assert.Equal(new CylSphere(new Vector3(0, 0, 0.1f), 0.4f, 1.7f), Assert.Single(s.CylSpheres));
        Assert.Equal(new Sphere(new Vector3(0, 0, 0.5f), 0.6f), Assert.Single(s.Spheres));
        Assert.Equal((1.5f, 2.5f, 0.4f, 0.3f), (s.Radius, s.Height, s.StepUpHeight, s.StepDownHeight));
        Assert.Equal(new Sphere(new Vector3(0, 0, 1), 2), s.SortingSphere);
        Assert.Equal(new Sphere(new Vector3(0, 0, 1.1f), 2.1f), s.SelectionSphere);
    }

    [Fact]
    public void LandBlockInfo_round_trips_into_the_cell_dat()
    {
        using var files = Forge();
        Assert.NotNull(files.Cell);
        Assert.Equal(Core.Dat.DatFileKind.Cell, files.Cell!.Info.Kind);
        Assert.Equal(256, files.Cell.Info.BlockSize);
        Assert.Equal(1024, files.Portal.Info.BlockSize);
        var info = files.Cell.ReadLandBlockInfo(0x1234FFFE)!;
        Assert.Equal(3u, info.NumCells);
        Assert.Equal(2, info.Objects.Count);
        Assert.Equal(new Stab(0x02000010, new Frame(new Vector3(10, 20, 30), new Quaternion(0.5f, 0.5f, 0.5f, 0.5f))), info.Objects[0]);
        Assert.Equal(new Frame(new Vector3(1, 2, 3), Quaternion.Identity), info.Objects[1].Frame);
        var building = Assert.Single(info.Buildings);
        Assert.Equal((0x01000010u, 2u), (building.ModelId, building.NumLeaves));
        Assert.Equal(new Vector3(96, 96, 5), building.Frame.Position);
    }

    [Fact]
    public void A_spec_without_landblocks_writes_no_cell_dat()
    {
        var spec = SpecJson.Parse("""{ "gfxObjs": [ { "id": "0x01000001", "physics": true, "vertices": [[0,0,0],[1,0,0],[0,1,0]], "polygons": [ { "vertices": [0,1,2] } ] } ] }""");
        var dats = SpecCompiler.Compile(spec);
        Assert.Null(dats.Cell);
        using var files = ForgedFiles.Write(dats);
        Assert.Null(files.Cell);
        Assert.False(File.Exists(Path.Combine(files.Directory, ForgeApp.CellFileName)));
    }

    [Fact]
    public void Spec_json_round_trips_through_serialize_and_parse()
    {
        var spec = SampleSpecAuthor.Create();
        var again = SpecJson.Parse(SpecJson.Serialize(spec));
        Assert.Equal(SpecJson.Serialize(spec), SpecJson.Serialize(again));
        Assert.Equal(SpecCompiler.Compile(spec).Portal, SpecCompiler.Compile(again).Portal);
    }
}
