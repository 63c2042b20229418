using System.Numerics;
using System.Text.Json;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Export;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;
using AcShadow.Tests.Errors;
using AcShadow.Tests.Forge;
using AcShadow.Tests.Support;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Tests.Bsp;

/// <summary>
/// Retail's solid query follows both children of every internal node unchecked, so a physics BSP with a
/// one-child node is something retail cannot traverse: read, reported on the GfxObj, its missing side
/// treated as empty space by the reference (our choice); the forge never writes one.
/// </summary>
public class OneChildNodeTests
{
    private const uint Gfx = BrokenDats.HealthyGfxObj + 0x10;
    private const uint SetupId = BrokenDats.HealthySetup + 0x10;

    /// <summary>The healthy box's solid leaf below a splitting plane z = 2, the side above it as given.</summary>
    private static PhysicsBspNode Split(PhysicsBspNode? above)
    {
        var leaf = Records.BoxGfxObj(Gfx).PhysicsBsp!;
        return new PhysicsBspNode(BspNodeTypes.ForChildren(above is not null, true), new Plane(Vector3.UnitZ, -2f), above, leaf,
            new Sphere(Vector3.Zero, 1f), 0, 0, []);
    }

    private static readonly PhysicsBspNode EmptyLeaf =
        new(BspNodeType.Leaf, default, null, null, new Sphere(Vector3.Zero, 0f), 1, 0, []);

    [Fact]
    public void A_node_without_its_positive_child_is_a_diagnostic_naming_the_node()
    {
        var dump = BspExtractor.Extract(BrokenDats.Box(Gfx, bsp: Split(null)))!;

        Assert.Equal(
            [$"GfxObj 0x{Gfx:X8} BSP node 0 has no positive child: retail's solid query would fail here; acshadow treats the missing side as empty space"],
            dump.Diagnostics);
        Assert.Null(dump.Nodes[0].Pos);
    }

    [Fact]
    public void A_node_without_its_negative_child_is_named_too_and_both_children_are_not()
    {
        var leaf = Records.BoxGfxObj(Gfx).PhysicsBsp!;
        var posOnly = new PhysicsBspNode(BspNodeType.BPIn, new Plane(-Vector3.UnitZ, 2f), leaf, null, new Sphere(Vector3.Zero, 1f), 0, 0, []);

        Assert.Equal([$"GfxObj 0x{Gfx:X8} BSP node 0 has no negative child: retail's solid query would fail here; acshadow treats the missing side as empty space"],
            BspExtractor.Extract(BrokenDats.Box(Gfx, bsp: posOnly))!.Diagnostics);
        Assert.Empty(BspExtractor.Extract(BrokenDats.Box(Gfx, bsp: Split(EmptyLeaf)))!.Diagnostics);
    }

    [Fact]
    public void Dumping_a_dat_with_a_one_child_node_reports_it_in_bsp_json_and_on_stderr()
    {
        var portal = BrokenDats.Portal(BrokenDats.Bytes(BrokenDats.Box(Gfx, bsp: Split(null))), BrokenDats.Bytes(BrokenDats.SetupOf(SetupId, Gfx)));
        using var dats = BrokenDats.Folder(portal);
        using var output = new TempDir();

        var run = CliRun.Of("dump", "--setup", $"0x{SetupId:X8}", "--dat", dats.Path, "--out", output.Path);

        Assert.Equal(0, run.ExitCode);
        Assert.Contains(run.ErrorLines, l => l.StartsWith($"warning: 0x{SetupId:X8}: {ExportDiagnosticCodes.BspGeometry}: ", StringComparison.Ordinal) && l.Contains("BSP node 0 has no positive child"));
        using var bsp = JsonDocument.Parse(File.ReadAllText(Path.Combine(output.Path, $"gfxobjs/0x{Gfx:X8}.bsp.json")));
        var diagnostics = bsp.RootElement.GetProperty("diagnostics").EnumerateArray().Select(d => d.GetString()).ToArray();
        Assert.Contains(diagnostics, d => d!.Contains("BSP node 0 has no positive child: retail's solid query would fail here"));
        Assert.Equal(JsonValueKind.Null, bsp.RootElement.GetProperty("nodes")[0].GetProperty("pos").ValueKind);
    }

    [Fact]
    public void The_reference_answers_the_missing_side_as_an_empty_leaf_there_would()
    {
        var oneChild = new BspSphereQuery(CompiledBsp.Compile(BspExtractor.Extract(BrokenDats.Box(Gfx, bsp: Split(null)))!));
        var bothChildren = new BspSphereQuery(CompiledBsp.Compile(BspExtractor.Extract(BrokenDats.Box(Gfx, bsp: Split(EmptyLeaf)))!));

        for (var z = -1f; z <= 3f; z += 0.25f)
            for (var x = -1f; x <= 1f; x += 0.5f)
            {
                var centre = new Vector3(x, 0.1f, z);
                Assert.Equal(bothChildren.Overlaps(centre, 0.3f), oneChild.Overlaps(centre, 0.3f));
            }
        Assert.True(oneChild.Overlaps(new Vector3(0, 0, 0.1f), 0.3f));
        Assert.False(oneChild.Overlaps(new Vector3(0, 0, 2.5f), 0.3f));
    }

    [Fact]
    public void Every_forged_physics_BSP_gives_every_internal_node_both_children()
    {
        using var sample = SampleDat.OpenPortal();
        var checkedAny = false;
        foreach (var id in sample.ListIds(AcShadow.Core.Dat.DatObjectKind.GfxObj))
        {
            if (sample.ReadGfxObj(id) is not { PhysicsBsp: { } root }) continue;
            checkedAny = true;
            Assert.All(Internal(root), n => Assert.True(n.Pos is not null && n.Neg is not null, $"GfxObj 0x{id:X8}: a {n.Type.Tag()} node has one child"));
            Assert.DoesNotContain(BspExtractor.Extract(sample.ReadGfxObj(id)!)!.Diagnostics, d => d.Contains("child"));
            var leaves = BspInvariants.Leaves(root).ToArray();
            Assert.Equal(Enumerable.Range(0, leaves.Length), leaves.Select(l => l.LeafIndex).Order());
            Assert.All(leaves.Where(l => l.Polygons.Count == 0), l => Assert.Equal(0, l.Solid));
        }
        Assert.True(checkedAny);
    }

    private static IEnumerable<PhysicsBspNode> Internal(PhysicsBspNode node) =>
        node.IsLeaf ? [] : new[] { node }.Concat(node.Pos is null ? [] : Internal(node.Pos)).Concat(node.Neg is null ? [] : Internal(node.Neg));
}
