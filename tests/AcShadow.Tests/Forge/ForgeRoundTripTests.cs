using AcShadow.Forge;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;
using AcShadow.Forging;
using AcShadow.Forging.Spec;

namespace AcShadow.Tests.Forge;

/// <summary>
/// Every object kind the forge writes (GfxObj, Setup with hooked placement frames, LandBlockInfo, the
/// Iteration record), written into real dats and read back, compared field by field with what was written.
/// The per-field bytes are pinned elsewhere by hand-worked layouts (AnimationHookTests, IterationRecordTests);
/// this catches a field the reader drops or a writer that stops agreeing with it.
/// </summary>
public sealed class ForgeRoundTripTests
{
    private static readonly ValidSpec Spec = SpecValidator.Validate(SampleSpecAuthor.Create() with { Iteration = 3 });
    private static readonly ForgedDats Dats = SpecCompiler.Compile(Spec);

    private static DatDatabase Open(byte[] bytes) => DatDatabase.Open(new MemoryStream(bytes, writable: false), "round-trip.dat");

    [Fact]
    public void Every_GfxObj_reads_back_field_by_field()
    {
        using var dat = Open(Dats.Portal);
        Assert.NotEmpty(Spec.GfxObjs);
        foreach (var forged in Spec.GfxObjs)
        {
            var written = SpecCompiler.ToGfxObj(forged);
            var read = dat.ReadGfxObj(written.Id)!;
            var at = $"GfxObj 0x{written.Id:X8}";
            Assert.Equal(written.Id, read.Id);
            Assert.Equal(written.Flags, read.Flags);
            Assert.Equal(written.Surfaces, read.Surfaces);
            Assert.Equal(written.Vertices.OrderBy(v => v.Key), read.Vertices.OrderBy(v => v.Key));
            Assert.Equal(written.PhysicsPolygons.Count, read.PhysicsPolygons.Count);
            for (var i = 0; i < written.PhysicsPolygons.Count; i++)
            {
                var (w, r) = (written.PhysicsPolygons[i], read.PhysicsPolygons[i]);
                Assert.Equal(w.Key, r.Key);
                AssertPolygon(w.Value, r.Value, $"{at} polygon {w.Key}");
            }
            AssertBsp(written.PhysicsBsp, read.PhysicsBsp, $"{at} BSP root");
            Assert.Equal(written.SortCenter, read.SortCenter);
            // Drawing polygons are written (drawing-only parts) but not read: collision never uses them.
            Assert.Empty(read.DrawingPolygons);
        }
    }

    private static void AssertPolygon(Polygon w, Polygon r, string at)
    {
        Assert.True(w.Stippling == r.Stippling && w.SidesType == r.SidesType && w.PosSurface == r.PosSurface && w.NegSurface == r.NegSurface, at);
        Assert.Equal(w.VertexIds, r.VertexIds);
        // UV indices (one byte a vertex, zeros when the writer has none) are drawing only: stepped over, not kept. That
        // the step is the right length shows in every field read after them.
        Assert.Empty(r.PosUVIndices);
        Assert.Empty(r.NegUVIndices);
    }

    private static void AssertBsp(PhysicsBspNode? w, PhysicsBspNode? r, string at)
    {
        if (w is null) { Assert.Null(r); return; }
        Assert.NotNull(r);
        Assert.True(w.Type == r.Type, $"{at}: type {w.Type.Tag()} read as {r.Type.Tag()}");
        Assert.Equal(w.BoundingSphere, r.BoundingSphere);
        if (w.IsLeaf)
        {
            Assert.Equal((w.LeafIndex, w.Solid), (r.LeafIndex, r.Solid));
            Assert.Equal(w.Polygons, r.Polygons);
            return;
        }
        Assert.Equal(w.SplittingPlane, r.SplittingPlane);
        AssertBsp(w.Pos, r.Pos, $"{at}.pos");
        AssertBsp(w.Neg, r.Neg, $"{at}.neg");
    }

    [Fact]
    public void Every_Setup_reads_back_field_by_field_hooks_included()
    {
        using var dat = Open(Dats.Portal);
        Assert.Contains(Spec.Setups, s => s.PlacementFrames.Any(p => p.Hooks.Count > 0));
        foreach (var w in Spec.Setups)
        {
            var r = dat.ReadSetup(w.Id)!;
            Assert.Equal(w.Id, r.Id);
            Assert.Equal(w.Flags, r.Flags);
            Assert.Equal(w.Parts, r.Parts);
            Assert.Equal(w.ParentIndex, r.ParentIndex);
            Assert.Equal(w.DefaultScale, r.DefaultScale);
            Assert.Equal(w.PlacementFrames.Count, r.PlacementFrames.Count);
            for (var p = 0; p < w.PlacementFrames.Count; p++)
            {
                Assert.Equal(w.PlacementFrames[p].Placement, r.PlacementFrames[p].Placement);
                Assert.Equal(w.PlacementFrames[p].Frames, r.PlacementFrames[p].Frames);
                Assert.Equal(w.PlacementFrames[p].Hooks, r.PlacementFrames[p].Hooks);
                Assert.Equal(w.PlacementFrames[p].Hooks.Select(h => h.FieldText()), r.PlacementFrames[p].Hooks.Select(h => h.FieldText()));
            }
            Assert.Equal(w.CylSpheres, r.CylSpheres);
            Assert.Equal(w.Spheres, r.Spheres);
            Assert.Equal((w.Height, w.Radius, w.StepUpHeight, w.StepDownHeight), (r.Height, r.Radius, r.StepUpHeight, r.StepDownHeight));
            Assert.Equal(w.SortingSphere, r.SortingSphere);
            Assert.Equal(w.SelectionSphere, r.SelectionSphere);
        }
    }

    [Fact]
    public void Every_LandBlockInfo_reads_back_field_by_field()
    {
        using var dat = Open(Dats.Cell!);
        Assert.NotEmpty(Spec.Landblocks);
        foreach (var w in Spec.Landblocks)
        {
            var r = dat.ReadLandBlockInfo(w.Id)!;
            Assert.Equal((w.Id, w.NumCells), (r.Id, r.NumCells));
            Assert.Equal(w.Objects, r.Objects);
            Assert.Equal(w.Buildings.Count, r.Buildings.Count);
            for (var b = 0; b < w.Buildings.Count; b++)
            {
                Assert.Equal((w.Buildings[b].ModelId, w.Buildings[b].Frame, w.Buildings[b].NumLeaves), (r.Buildings[b].ModelId, r.Buildings[b].Frame, r.Buildings[b].NumLeaves));
                Assert.Equal(w.Buildings[b].Portals, r.Buildings[b].Portals);
            }
            Assert.Equal(w.RestrictionTable, r.RestrictionTable);
        }
    }

    [Fact]
    public void The_iteration_record_reads_back_in_both_dats()
    {
        foreach (var (bytes, objects) in new[] { (Dats.Portal, Spec.GfxObjs.Count + Spec.Setups.Count + Spec.MotionTables.Count + Spec.Animations.Count + Spec.Environments.Count), (Dats.Cell!, Spec.Landblocks.Count + Spec.Cells.Count) })
        {
            using var dat = Open(bytes);
            var record = IterationRecord.Read(new DatBinaryReader(dat.Archive.ReadObjectBytes(IterationRecord.Id)!));
            Assert.Equal(3, record.Current);
            Assert.Equal([new IterationRun(1, 3)], record.Runs);
            Assert.Equal(objects + 1, dat.Archive.Entries.Count);
        }
    }
}
