using System.Numerics;
using System.Text.Json;
using AcShadow.Analysis.Audit;
using AcShadow.Core.Batch;
using AcShadow.Core.Catalog;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;
using AcShadow.Tests.Batch;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Audit;

public class AuditTests
{
    private static AuditReport SampleReport(AuditQuery? query = null)
    {
        using var portal = SampleDat.OpenPortal();
        var plan = BatchPlanner.Plan(new BatchSelection(false, true, null, null), portal, null, DoorCatalog.SetupIds);
        return AuditRunner.Run(portal, plan, query ?? new AuditQuery(), 2);
    }

    [Fact]
    public void Every_sample_setup_has_a_row_with_the_right_counts()
    {
        var report = SampleReport();
        Assert.Equal(BatchCommandTests.SampleSetups, report.Rows.Select(r => $"0x{r.SetupId:X8}"));
        var door = report.Rows.Single(r => r.SetupId == 0x020019FF);
        Assert.Equal((3, 3, 0, 0, 1), (door.Parts, door.BspParts, door.MissingParts, door.CylSpheres, door.Spheres));
        Assert.Equal((0.141f, 0.2f), (door.Radius, door.Height));
        Assert.Equal((3, 4), (door.RetailShapes, door.UnionShapes));
        Assert.Equal(("Resting", AuditCategory.Bsp, false), (door.Placement, door.Category, door.FlagMismatch));

        var creature = report.Rows.Single(r => r.SetupId == 0x02001000);
        Assert.Equal((AuditCategory.Cylinders, 0, 2, 2), (creature.Category, creature.BspParts, creature.CylSpheres, creature.RetailShapes));
        Assert.Null(creature.Coverage);

        var flagOnly = report.Rows.Single(r => r.SetupId == 0x02003100);
        Assert.True(flagOnly.FlagHasPhysicsBsp);
        Assert.False(flagOnly.PartsHavePhysicsBsp);
        Assert.Equal(AuditCategory.Spheres, flagOnly.Category);

        var staticMulti = report.Rows.Single(r => r.SetupId == 0x02003000);
        Assert.True(staticMulti.FlagMismatch);
        Assert.Contains("non-uniform-scale", staticMulti.DiagnosticCodes);

        var otherPlacement = report.Rows.Single(r => r.SetupId == 0x02003200);
        Assert.Equal(("None", "Other", 0), (otherPlacement.Placement, otherPlacement.UnionPlacement, otherPlacement.RetailShapes));
        Assert.Equal(1, report.Rows.Single(r => r.SetupId == 0x02003400).MissingParts);
        Assert.True(report.Rows.Single(r => r.SetupId == 0x02005000).PhysicsPolygons >= 200);
    }

    [Fact]
    public void Summary_counts_match_the_sample()
    {
        var s = SampleReport().Summary;
        // 15 Setups and the four pose-rule Setups of issue 27 (0x02000311, 0x02003700-0x02003900), each with BSP parts.
        Assert.Equal(19, s["setups"]);
        Assert.Equal(15, s["bsp"]);
        Assert.Equal(1, s["cylinders"]);
        Assert.Equal(3, s["spheres"]);
        Assert.Equal(0, s["none"]);
        Assert.Equal(2, s["flagMismatch"]);
        Assert.Equal(1, s["missingParts"]);
        Assert.Equal(1, s["noPose"]);
        Assert.Equal(1, s["coverageUnknown"]);
        Assert.Equal(s["bsp"], s["coverageBelow10"] + s["coverage10To50"] + s["coverageAtLeast50"] + s["coverageUnknown"]);
        Assert.Equal(0, s["skipped"]);
    }

    [Fact]
    public void The_doors_soda_can_covers_little_of_the_door()
    {
        var report = SampleReport();
        foreach (var id in new uint[] { 0x020019FF, 0x0200024F, 0x02000281 })
        {
            var door = report.Rows.Single(r => r.SetupId == id);
            Assert.InRange(door.Coverage!.Value, 0.0, 0.15);
            Assert.InRange(door.HeightCoverage!.Value, 0.0, 0.1); // 0.2 m of a 2.3 m door
            Assert.InRange(door.FootprintArea!.Value, 0.5, 0.8);
            Assert.InRange(door.VolumeCoverage!.Value, 0.0, 0.02); // near zero: the soda can fills ~1% of the door
            Assert.Equal(Math.Round(door.Coverage.Value * door.HeightCoverage.Value, 4, MidpointRounding.AwayFromZero), door.VolumeCoverage.Value);
        }
        // A radius as big as the object covers all of it.
        Assert.Equal(1d, report.Rows.Single(r => r.SetupId == 0x02005000).Coverage);
    }

    [Fact]
    public void Coverage_is_the_share_of_the_footprint_inside_the_circle()
    {
        var square = Square(1f); // one horizontal 2 × 2 quad about the origin
        var at = new FootprintCoverage.PosedPart(square, Vector3.Zero, Quaternion.Identity, 1f);
        var (quarter, area) = FootprintCoverage.Measure([at], 1f)!.Value;
        Assert.Equal(4d, area, 3);
        Assert.Equal(Math.PI / 4, quarter, 2);
        Assert.Equal(1d, FootprintCoverage.Measure([at], 1.5f)!.Value.Coverage);
        Assert.Equal(0d, FootprintCoverage.Measure([at with { Position = new Vector3(10, 0, 0) }], 1f)!.Value.Coverage);
        // Rotation and scale move the footprint with the part.
        var turned = at with { Position = new Vector3(2, 0, 0), Rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 4), Scale = 0.5f };
        Assert.Equal(1d, FootprintCoverage.Measure([turned], 1f)!.Value.Area, 3);
    }

    [Fact]
    public void A_vertical_polygon_has_no_footprint()
    {
        var wall = OneQuad(new(0, 0, 0), new(1, 0, 0), new(1, 0, 1), new(0, 0, 1));
        Assert.Null(FootprintCoverage.Measure([new(wall, Vector3.Zero, Quaternion.Identity, 1f)], 1f));
    }

    private static GfxObj Square(float half) => OneQuad(new(-half, -half, 0), new(half, -half, 0), new(half, half, 0), new(-half, half, 0));

    private static GfxObj OneQuad(Vector3 a, Vector3 b, Vector3 c, Vector3 d) => new(0x01000002, GfxObjFlags.HasPhysics, [],
        new Dictionary<ushort, Vector3> { [0] = a, [1] = b, [2] = c, [3] = d },
        [new(0, new Polygon(Stippling.NoPos, SidesType.Clockwise, 0, 0, [0, 1, 2, 3], [], []))],
        new PhysicsBspNode(BspNodeType.Leaf, default, null, null, new Sphere(Vector3.Zero, 2), 0, 1, [0]), Vector3.Zero, []);

    [Fact]
    public void Filters_and_sorting()
    {
        var onlyBsp = SampleReport(new AuditQuery(OnlyBsp: true));
        Assert.Equal(15, onlyBsp.Rows.Count);
        Assert.Equal(19, onlyBsp.Audited);
        Assert.Equal([0x02003000u, 0x02003100u], SampleReport(new AuditQuery(FlagMismatch: true)).Rows.Select(r => r.SetupId));
        var low = SampleReport(new AuditQuery(MaxCoverage: 0.2));
        Assert.All(low.Rows, r => Assert.True(r.Coverage <= 0.2));
        Assert.Contains(low.Rows, r => r.SetupId == 0x020019FF);

        var byCoverage = SampleReport(new AuditQuery(OnlyBsp: true, Sort: "-coverage")).Rows;
        var known = byCoverage.Where(r => r.Coverage is not null).Select(r => r.Coverage!.Value).ToArray();
        Assert.Equal(known.OrderDescending(), known);
        Assert.Null(byCoverage[^1].Coverage); // unknown sorts last
        var byPolygons = SampleReport(new AuditQuery(Sort: "polygons")).Rows.Select(r => r.PhysicsPolygons).ToArray();
        Assert.Equal(byPolygons.Order(), byPolygons);
    }

    [Fact]
    public void Csv_json_and_markdown_carry_every_row_and_column()
    {
        using var dir = new TempDir();
        var csvPath = Path.Combine(dir.Path, "audit.csv");
        var csv = CliRun.Of("audit", "--out", csvPath);
        Assert.Equal(0, csv.ExitCode);
        var lines = File.ReadAllLines(csvPath);
        Assert.Equal(string.Join(',', AuditColumns.All.Select(c => c.Key)), lines[0]);
        Assert.Equal(20, lines.Length); // header and the sample's 19 Setups
        Assert.StartsWith("0x0200024F,bsp,1,1,0,", lines[1]);
        Assert.Contains("wrote", csv.Out);
        Assert.Contains("family bsp", csv.Out);

        var json = CliRun.Of("audit", "--format", "json", "--only-bsp");
        Assert.Equal(0, json.ExitCode);
        using var doc = JsonDocument.Parse(json.Out);
        Assert.Equal("acshadow.audit/1", doc.RootElement.GetProperty("format").GetString());
        var rows = doc.RootElement.GetProperty("rows").EnumerateArray().ToArray();
        Assert.Equal(15, rows.Length);
        Assert.Equal(AuditColumns.All.Select(c => c.Key), rows[0].EnumerateObject().Select(p => p.Name));
        Assert.Equal(15, doc.RootElement.GetProperty("summary").GetProperty("bsp").GetInt32());

        var md = CliRun.Of("audit", "--format", "md", "--setups", WriteIds(dir, "0x020019FF\n0x0200ABCD\n"));
        Assert.Equal(0, md.ExitCode);
        Assert.Contains("| 0x020019FF | bsp | 3 | 3 |", md.Out);
        Assert.Contains("- skipped, not in the dat: 0x0200ABCD", md.Out);

        var csvOut = CliRun.Of("audit", "--format", "csv");
        Assert.Equal(20, csvOut.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries).Length);
        Assert.Contains("Summary", csvOut.Error); // the summary stays out of the CSV
    }

    [Fact]
    public void Table_ends_with_the_summary_and_is_the_default()
    {
        var run = CliRun.Of("audit", "--doors");
        Assert.Equal(0, run.ExitCode);
        var lines = run.Out.Split('\n');
        Assert.StartsWith("Setup ", lines[0]);
        // The sample's 4 catalog doors: 0x0200024F, 0x02000281, 0x02000311, 0x020019FF.
        Assert.Equal(4, lines.Count(l => l.StartsWith("0x02")));
        Assert.Contains("Summary (4 of 4 audited Setup(s) shown)", run.Out);
        Assert.Contains($"{DoorCatalog.Entries.Count - 4}  skipped (not in the dat or unreadable)", run.Out);
    }

    [Fact]
    public void Chart_adds_the_exact_models_and_the_soda_can_is_not_one_of_them()
    {
        var run = CliRun.Of("audit", "--doors", "--chart", "--format", "json");
        Assert.Equal(0, run.ExitCode);
        using var doc = JsonDocument.Parse(run.Out);
        var rows = doc.RootElement.GetProperty("rows").EnumerateArray().ToArray();
        Assert.Equal(4, rows.Length);
        foreach (var row in rows)
        {
            var exact = row.GetProperty("exactModels").EnumerateArray().Select(e => e.GetString()).ToArray();
            Assert.Contains("retail", exact); // the reference agrees with itself
            Assert.DoesNotContain("fallback-cylinder", exact);
            Assert.Contains(row.GetProperty("cheapestExact").GetString(), exact);
        }
        Assert.DoesNotContain("exactModels", CliRun.Of("audit", "--doors", "--format", "csv").Out);
    }

    [Theory]
    [InlineData(2, "--format: 'xml'", "--format", "xml")]
    [InlineData(2, "--max-coverage: '2'", "--max-coverage", "2")]
    [InlineData(2, "--max-coverage: 'low'", "--max-coverage", "low")]
    [InlineData(2, "--sort: 'size'", "--sort", "size")]
    [InlineData(2, "--jobs: '-3'", "--jobs=-3")]
    [InlineData(4, "has no LandBlockInfo", "--landblock", "0x0101")]
    [InlineData(3, "does not exist", "--dat", "/nonexistent/client_portal.dat")]
    public void Bad_input_exits_with_its_code_one_line_and_no_file(int code, string message, params string[] args)
    {
        using var dir = new TempDir();
        var run = CliRun.Of(["audit", "--out", Path.Combine(dir.Path, "audit.csv"), .. args]);
        Assert.Equal(code, run.ExitCode);
        Assert.Contains(message, Assert.Single(run.ErrorLines, l => !l.Contains("SYNTHETIC")));
        Assert.Empty(dir.Files());
    }

    [Fact]
    public void Out_that_is_a_folder_fails_with_the_output_code()
    {
        using var dir = new TempDir();
        var run = CliRun.Of("audit", "--out", dir.Path);
        Assert.Equal(6, run.ExitCode);
        Assert.Contains("is a folder", Assert.Single(run.ErrorLines));
        Assert.Empty(dir.Files());
    }

    private static string WriteIds(TempDir dir, string text)
    {
        var path = Path.Combine(dir.Path, "ids.txt");
        File.WriteAllText(path, text);
        return path;
    }
}
