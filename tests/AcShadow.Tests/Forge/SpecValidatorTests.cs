using AcShadow.Forging;
using AcShadow.Forging.Spec;

namespace AcShadow.Tests.Forge;

/// <summary>Every bad spec is refused with one line that names the item and the fix.</summary>
public sealed class SpecValidatorTests
{
    private const string Box = """
        { "id": "0x01000001", "physics": true,
          "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]],
          "polygons": [ { "vertices": [0,1,2,3] } ] }
        """;

    private static string Error(string json)
    {
        var e = Assert.Throws<SpecException>(() => SpecCompiler.Compile(SpecJson.Parse(json)));
        Assert.DoesNotContain('\n', e.Message);
        return e.Message;
    }

    private static string WithSetup(string setup) => $$"""{ "gfxObjs": [ {{Box}} ], "setups": [ {{setup}} ] }""";

    [Fact]
    public void Unknown_part_id_names_the_setup_and_both_fixes()
    {
        var message = Error($$"""{ "gfxObjs": [ {{Box}} ], "setups": [ { "id": "0x02000001", "parts": ["0x01000001"] }, { "id": "0x02000002", "parts": ["0x01000001"] }, { "id": "0x02000010", "parts": ["0x01000001", "0x0100ABCD"] } ] }""");
        Assert.Equal("setups[2] (0x02000010): part 0x0100ABCD is not a gfxObj in this spec (declare it, or list it in missingParts)", message);
    }

    [Fact]
    public void Missing_parts_are_allowed_when_listed()
    {
        var dats = SpecCompiler.Compile(SpecJson.Parse(WithSetup("""{ "id": "0x02000010", "parts": ["0x0100ABCD"], "missingParts": ["0x0100ABCD"] }""")));
        Assert.NotEmpty(dats.Portal);
    }

    [Fact]
    public void Polygon_with_fewer_than_three_vertices()
    {
        var message = Error("""{ "gfxObjs": [ { "id": "0x01000001", "drawing": true, "vertices": [[0,0,0],[1,0,0]], "polygons": [ { "vertices": [0,1] } ] } ] }""");
        Assert.Equal("gfxObjs[0] (0x01000001) polygons[0]: has 2 vertex id(s); a polygon needs at least 3", message);
    }

    [Fact]
    public void Vertex_id_out_of_range_gives_the_valid_range()
    {
        var message = Error("""{ "gfxObjs": [ { "id": "0x01000001", "physics": true, "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]], "polygons": [ { "vertices": [0,1,2] }, { "vertices": [0,2,4] } ] } ] }""");
        Assert.Equal("gfxObjs[0] (0x01000001) polygons[1]: vertex id 4 is out of range; valid ids are 0-3", message);
    }

    [Fact]
    public void Placement_frame_count_must_equal_part_count()
    {
        // The dat stores a placement frame as NumParts frames, so fewer frames than parts cannot be forged.
        var message = Error(WithSetup("""{ "id": "0x02000010", "parts": ["0x01000001", "0x01000001", "0x01000001"], "placements": { "Resting": [ {}, {} ] } }"""));
        Assert.Equal("setups[0] (0x02000010): placement \"Resting\" has 2 frame(s) but the setup has 3 part(s); the dat stores exactly one frame per part, so give 3", message);
    }

    [Fact]
    public void Default_scale_count_must_equal_part_count()
    {
        var message = Error(WithSetup("""{ "id": "0x02000010", "parts": ["0x01000001", "0x01000001"], "defaultScale": [[1,1,1]] }"""));
        Assert.Contains("defaultScale has 1 entries but the setup has 2 part(s)", message);
    }

    [Fact]
    public void Duplicate_ids_are_refused()
    {
        Assert.Equal("gfxObjs[1] (0x01000001): duplicate id, already declared by gfxObjs[0]; give each gfxObj its own id",
            Error($$"""{ "gfxObjs": [ {{Box}}, {{Box}} ] }"""));
        Assert.StartsWith("setups[1] (0x02000010): duplicate id",
            Error($$"""{ "gfxObjs": [ {{Box}} ], "setups": [ { "id": "0x02000010", "parts": ["0x01000001"] }, { "id": "0x02000010", "parts": ["0x01000001"] } ] }"""));
    }

    [Theory]
    [InlineData("""{ "gfxObjs": [ { "id": "0x02000001" } ] }""", "gfxObjs[0]: id 0x02000001 is outside the GfxObj range 0x01000000-0x0100FFFF")]
    [InlineData("""{ "gfxObjs": [ { "id": "0x01010000" } ] }""", "gfxObjs[0]: id 0x01010000 is outside the GfxObj range 0x01000000-0x0100FFFF")]
    [InlineData("""{ "setups": [ { "id": "0x01000001", "parts": [] } ] }""", "setups[0]: id 0x01000001 is outside the Setup range 0x02000000-0x0200FFFF")]
    [InlineData("""{ "landblocks": [ { "id": "0xA9B4FFFF" } ] }""", "landblocks[0]: id 0xA9B4FFFF is outside the LandBlockInfo range 0xXXYYFFFE")]
    [InlineData("""{ "gfxObjs": [ { "id": "10044B5" } ] }""", "gfxObjs[0]: id \"10044B5\" is not a hex id like \"0x010044B5\"")]
    public void Ids_must_be_hex_and_inside_their_type_range(string json, string expected) => Assert.Equal(expected, Error(json));

    [Theory]
    [InlineData("\"NaN\"")]
    [InlineData("\"Infinity\"")]
    [InlineData("1e40")]
    public void Non_finite_numbers_are_refused(string value)
    {
        var message = Error($$"""{ "gfxObjs": [ { "id": "0x01000001", "drawing": true, "vertices": [[0,0,0],[1,{{value}},0],[0,1,0]], "polygons": [ { "vertices": [0,1,2] } ] } ] }""");
        Assert.StartsWith("gfxObjs[0] (0x01000001) vertices[1] y: ", message);
        Assert.EndsWith("is not a finite float32 number", message);
    }

    [Fact]
    public void Malformed_json_reports_line_and_position()
    {
        var message = Error("{\n  \"gfxObjs\": [\n    { \"id\": \"0x01000001\",, }\n  ]\n}");
        Assert.StartsWith("spec: malformed JSON at line 3, position ", message);
    }

    [Fact]
    public void A_misspelt_property_is_an_error_not_silently_ignored()
    {
        var message = Error(WithSetup("""{ "id": "0x02000010", "parts": ["0x01000001"], "radiuss": 1 }"""));
        Assert.Contains("malformed JSON", message);
        Assert.Contains("radiuss", message);
    }

    [Fact]
    public void Unknown_placement_name()
    {
        var message = Error(WithSetup("""{ "id": "0x02000010", "parts": ["0x01000001"], "placements": { "Restin": [ {} ] } }"""));
        Assert.Equal("setups[0] (0x02000010): unknown placement name \"Restin\" (use a retail name such as Resting, Default, Other, or Placement0xNN)", message);
    }

    [Theory]
    [InlineData("""{ "id": "0x02000010", "parts": ["0x01000001"], "flags": ["HasDefaultScale"] }""", "flag HasDefaultScale is derived")]
    [InlineData("""{ "id": "0x02000010", "parts": ["0x01000001"], "flags": ["Shiny"] }""", "unknown flag \"Shiny\" (use AllowFreeHeading, HasPhysicsBsp)")]
    [InlineData("""{ "id": "0x02000010", "parts": [] }""", "has no parts")]
    [InlineData("""{ "id": "0x02000010", "parts": ["0x01000001"], "missingParts": ["0x01000001"] }""", "missingParts lists 0x01000001, but gfxObjs declares it")]
    [InlineData("""{ "id": "0x02000010", "parts": ["0x01000001"], "placements": { "Resting": [ { "orientation": { "w": 2, "x": 0, "y": 0, "z": 0 } } ] } }""", "quaternion length is 2, not 1; normalize it")]
    [InlineData("""{ "id": "0x02000010", "parts": ["0x01000001"], "radius": -1 }""", "radius: -1 is negative")]
    [InlineData("""{ "id": "0x02000010", "parts": ["0x01000001"], "placements": { "Resting": [ {} ], "resting": [ {} ] } }""", "placement \"resting\" is given twice")]
    public void Setup_mistakes_are_named(string setup, string expected) => Assert.Contains(expected, Error(WithSetup(setup)));

    [Theory]
    [InlineData("""{ "id": "0x01000002", "physics": true, "vertices": [], "polygons": [] }""", "physics is true but there are no polygons")]
    [InlineData("""{ "id": "0x01000002", "vertices": [[0,0,0],[1,0,0],[0,1,0]], "polygons": [ { "vertices": [0,1,2] } ] }""", "neither physics nor drawing is true")]
    [InlineData("""{ "id": "0x01000002", "drawing": true, "vertices": [[0,0,0],[1,0,0],[0,1,0]], "polygons": [ { "vertices": [0,1,2], "sidesType": "Both" } ] }""", "\"Both\" is not one of Landblock, None, Clockwise, CounterClockwise")]
    [InlineData("""{ "id": "0x01000002", "drawing": true, "vertices": [[0,0,0],[1,0],[0,1,0]] }""", "vertices[1]: expected [x, y, z], got 2 number(s)")]
    public void GfxObj_mistakes_are_named(string gfx, string expected) => Assert.Contains(expected, Error($$"""{ "gfxObjs": [ {{gfx}} ] }"""));

    [Fact]
    public void Landblock_objects_must_be_declared()
    {
        var message = Error($$"""{ "gfxObjs": [ {{Box}} ], "landblocks": [ { "id": "0xA9B4FFFE", "objects": [ { "id": "0x02000099" } ] } ] }""");
        Assert.Equal("landblocks[0] (0xA9B4FFFE) objects[0]: 0x02000099 is neither a gfxObj nor a setup in this spec; declare it or place another id", message);
    }
}
