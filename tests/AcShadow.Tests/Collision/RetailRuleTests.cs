using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;
using AcShadow.Forging.Bsp;

namespace AcShadow.Tests.Collision;

/// <summary>The retail rules one at a time, on a 1 × 1 × 1 m box standing on z = 0.</summary>
public class RetailRuleTests
{
    private const float Eps = PhysicsEpsilon.Value;
    private static readonly TestMesh Box = TestMesh.Box(new(0, 0, 0.5f), new(0.5f, 0.5f, 0.5f));
    private static readonly BspDump TestTree = TestGfx.Dump(0x01007600, Box);
    private static readonly BspDump ForgeTree = TestGfx.Dump(0x01007601, Box, PhysicsBspBuilder.Build(Box.Vertices, Box.Polygons.Select(p => (IReadOnlyList<short>)p).ToArray()));

    public static TheoryData<string> Trees => new() { "test", "forge" };

    private static BspSphereQuery Query(string tree) => BspSphereQuery.From(tree == "test" ? TestTree : ForgeTree);

    [Theory, MemberData(nameof(Trees))]
    public void A_face_blocks_within_r_minus_epsilon_and_not_beyond(string tree)
    {
        var q = Query(tree);
        const float r = 0.5f;
        Assert.True(q.Overlaps(new Vector3(0.5f + r - Eps - 1e-4f, 0.1f, 0.5f), r));
        Assert.False(q.Overlaps(new Vector3(0.5f + r - Eps + 1e-4f, 0.1f, 0.5f), r));
        Assert.False(q.Overlaps(new Vector3(0.5f + r - 1e-4f, 0.1f, 0.5f), r)); // grazing within ε is clear
    }

    [Theory, MemberData(nameof(Trees))]
    public void Edges_and_vertices_block_along_the_diagonal(string tree)
    {
        var q = Query(tree);
        const float r = 0.3f;
        var edgeDir = Vector3.Normalize(new Vector3(1, 1, 0));
        var edge = new Vector3(0.5f, 0.5f, 0.5f);
        Assert.True(q.Overlaps(edge + edgeDir * (r - Eps - 1e-4f), r));
        Assert.False(q.Overlaps(edge + edgeDir * (r - Eps + 1e-4f), r));
        var cornerDir = Vector3.Normalize(new Vector3(1, 1, 1));
        var corner = new Vector3(0.5f, 0.5f, 1f);
        Assert.True(q.Overlaps(corner + cornerDir * (r - Eps - 1e-4f), r));
        Assert.False(q.Overlaps(corner + cornerDir * (r - Eps + 1e-4f), r));
    }

    [Theory, MemberData(nameof(Trees))]
    public void A_centre_in_a_solid_leaf_holding_polygons_blocks_without_touching_any(string tree)
    {
        // BSPLEAF::sphere_intersects_solid: centre check on and solid → blocked, before any polygon test.
        Assert.True(Query(tree).Overlaps(new Vector3(0, 0, 0.5f), 0.05f));
        Assert.True(Query(tree).Overlaps(new Vector3(0.1f, -0.2f, 0.3f), 0f));
    }

    [Fact]
    public void Without_a_solid_leaf_holding_polygons_a_small_sphere_deep_inside_is_clear()
    {
        // The forge's box tree with its Solid flags cleared: only polygon contact blocks.
        var bsp = CompiledBsp.Compile(TestGfx.Dump(0x01007603, Box, WithoutSolid(PhysicsBspBuilder.Build(Box.Vertices, Box.Polygons.Select(p => (IReadOnlyList<short>)p).ToArray()))));
        Assert.DoesNotContain(bsp.Nodes, n => n.IsLeaf && n.Solid);
        Assert.False(new BspSphereQuery(bsp).Overlaps(new Vector3(0, 0, 0.5f), 0.05f));
        Assert.True(new BspSphereQuery(bsp).Overlaps(new Vector3(0, 0, 0.5f), 0.51f));
    }

    private static PhysicsBspNode WithoutSolid(PhysicsBspNode n) =>
        n with { Solid = 0, Pos = n.Pos is null ? null : WithoutSolid(n.Pos), Neg = n.Neg is null ? null : WithoutSolid(n.Neg) };

    [Fact]
    public void A_part_pose_moves_turns_and_scales_the_query_into_part_space()
    {
        var bsp = CompiledBsp.Compile(TestTree);
        var turn = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2);
        var shape = new ShadowShape(ShapeSource.Part, 0, bsp.GfxObjId, CollisionType.Bsp, new Vector3(10, 0, 0), turn, 2f, 1f, 0f, null);
        var query = ObjectOverlapQuery.Create([shape], id => id == bsp.GfxObjId ? bsp : null);
        // Scaled ×2 the box spans x 9..11, y −1..1 (turned 90° it is still square), z 0..2.
        Assert.True(query.Overlaps(new Vector3(11.3f, 0, 1), 0.35f));
        Assert.False(query.Overlaps(new Vector3(11.4f, 0, 1), 0.35f));
        Assert.True(query.Overlaps(new Vector3(10, 0, 2.3f), 0.35f));
        Assert.False(query.Overlaps(new Vector3(10, 0, 2.4f), 0.35f));
    }

    [Fact]
    public void Dat_and_json_give_the_same_answers()
    {
        var db = TestGfx.RoundTrip([TestGfx.Make(0x01007602, Box)]);
        var fromDat = BspExtractor.Extract(db.ReadGfxObj(0x01007602)!)!;
        var json = System.Text.Encoding.UTF8.GetString(BspFileWriter.Write(fromDat));
        var fromJson = BspFileReader.Read(json);
        var a = BspSphereQuery.From(fromDat);
        var b = BspSphereQuery.From(fromJson);
        foreach (var (c, r, _) in StressProbes.For(a.Bsp, 5000, 5))
            Assert.Equal(a.Overlaps(c, r), b.Overlaps(c, r));
    }

    [Fact]
    public void A_cylinder_is_a_box_in_profile_with_epsilon()
    {
        // CCylSphere::collides_with_sphere: horizontal reach R − ε + r, vertical r − ε + h/2 from the middle.
        var b = new Vector3(0, 0, 0);
        Assert.True(CylinderSphereTest.Touches(b, 0.5f, 2f, new Vector3(0.5f + 0.3f - Eps - 1e-4f, 0, 1), 0.3f));
        Assert.False(CylinderSphereTest.Touches(b, 0.5f, 2f, new Vector3(0.5f + 0.3f - Eps + 1e-4f, 0, 1), 0.3f));
        Assert.True(CylinderSphereTest.Touches(b, 0.5f, 2f, new Vector3(0, 0, 2 + 0.3f - Eps - 1e-4f), 0.3f));
        Assert.False(CylinderSphereTest.Touches(b, 0.5f, 2f, new Vector3(0, 0, 2 + 0.3f - Eps + 1e-4f), 0.3f));
        // No rounding at the rim: the corner of the profile still blocks.
        Assert.True(CylinderSphereTest.Touches(b, 0.5f, 2f, new Vector3(0.75f, 0, 2.25f), 0.3f));
    }

    [Fact]
    public void A_sphere_blocks_within_the_radius_sum_less_epsilon()
    {
        Assert.True(SphereSphereTest.Touches(Vector3.Zero, 0.1f, new Vector3(0.6f - Eps - 1e-4f, 0, 0), 0.5f));
        Assert.False(SphereSphereTest.Touches(Vector3.Zero, 0.1f, new Vector3(0.6f - Eps + 1e-4f, 0, 0), 0.5f));
    }
}
