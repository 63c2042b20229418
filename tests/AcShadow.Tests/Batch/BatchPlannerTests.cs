using AcShadow.Core.Batch;
using AcShadow.Core.Catalog;
using AcShadow.Core.Dat;
using AcShadow.Core.Export;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Batch;

public class BatchPlannerTests
{
    [Fact]
    public void Union_is_sorted_each_id_once_with_every_source_recorded()
    {
        using var portal = SampleDat.OpenPortal();
        var selection = new BatchSelection(true, true, new SetupList("ids.txt", [0x020019FF, 0x0200ABCD]), null);
        var plan = BatchPlanner.Plan(selection, portal, null, DoorCatalog.SetupIds);

        Assert.Equal(portal.ListIds(DatObjectKind.Setup).Order(), plan.Setups.Select(s => s.Id));
        Assert.Equal(SelectionSource.Doors | SelectionSource.All | SelectionSource.SetupsFile, plan.Setups.Single(s => s.Id == 0x020019FF).From);
        Assert.Equal(SelectionSource.All, plan.Setups.Single(s => s.Id == 0x02001000).From);
        Assert.Equal(plan.Skipped.Select(s => s.Id).Order(), plan.Skipped.Select(s => s.Id));
        var custom = Assert.Single(plan.Skipped, s => s.Id == 0x0200ABCD);
        Assert.Equal(SkippedItem.NotInDat, custom.Reason);
        Assert.Equal(SelectionSource.SetupsFile, custom.From);
        Assert.Null(plan.Scene);
    }

    [Fact]
    public void Landblock_adds_the_setups_its_scene_places()
    {
        using var portal = SampleDat.OpenPortal();
        using var cell = DatDatabase.Open(new MemoryStream(SampleDat.CellBytes!), "client_cell_1.dat");
        var plan = BatchPlanner.Plan(new BatchSelection(false, false, null, 0xA9B4FFFE), portal, cell, []);
        // The door and the static it places, and the Setup placed inside its ground-floor cell.
        Assert.Equal([0x020019FFu, 0x02003000u, 0x02003300u], plan.Setups.Select(s => s.Id));
        Assert.Equal([0xA9B40100u, 0xA9B40101u], plan.Scene!.Cells.Select(c => c.Id));
        Assert.Empty(plan.Scene.MissingCells);
        var objectsOnly = BatchPlanner.Plan(new BatchSelection(false, false, null, 0xA9B4FFFE) { Cells = false }, portal, cell, []);
        Assert.Equal([0x020019FFu, 0x02003000u], objectsOnly.Setups.Select(s => s.Id));
        Assert.Empty(objectsOnly.Scene!.Cells);
        Assert.All(plan.Setups, s => Assert.Equal(SelectionSource.Landblock, s.From));
        Assert.NotNull(plan.Scene);
        Assert.Equal(4, plan.Scene!.Objects.Count);
    }

    [Fact]
    public void Landblock_needs_a_cell_dat_and_must_be_in_it()
    {
        using var portal = SampleDat.OpenPortal();
        using var cell = DatDatabase.Open(new MemoryStream(SampleDat.CellBytes!), "client_cell_1.dat");
        var none = Assert.Throws<SelectionException>(() => BatchPlanner.Plan(new BatchSelection(false, false, null, 0xA9B4FFFE), portal, null, []));
        Assert.Equal(SelectionProblem.NeedsCellDat, none.Problem);
        var missing = Assert.Throws<SelectionException>(() => BatchPlanner.Plan(new BatchSelection(false, false, null, 0x0101FFFE), portal, cell, []));
        Assert.Equal(SelectionProblem.NotInDat, missing.Problem);
    }

    [Theory]
    [InlineData("0xA9B4", 0xA9B4FFFEu)]
    [InlineData("a9b4", 0xA9B4FFFEu)]
    [InlineData("0xA9B4FFFE", 0xA9B4FFFEu)]
    [InlineData("0x0101", 0x0101FFFEu)]
    public void Landblock_ids_parse(string text, uint expected)
    {
        Assert.True(LandblockIds.TryParse(text, out var id));
        Assert.Equal(expected, id);
        Assert.Equal("0x" + (expected >> 16).ToString("X4"), LandblockIds.Short(id));
    }

    [Theory]
    [InlineData("")]
    [InlineData("0xA9B4FFFF")]
    [InlineData("0x12345")]
    [InlineData("lb")]
    public void Bad_landblock_ids_do_not_parse(string text) => Assert.False(LandblockIds.TryParse(text, out _));

    [Fact]
    public void Setups_file_takes_ids_comments_and_blank_lines()
    {
        var list = SetupList.Parse("ids.txt", "# header\r\n0x020019FF\r\n\r\n02000281 # trailing comment\n0x020019ff\n");
        Assert.Equal([0x02000281u, 0x020019FFu], list.Ids);
        Assert.Equal("ids.txt", list.Name);
    }

    [Theory]
    [InlineData("0x020019FF\nxyz\n", "ids.txt line 2: 'xyz' is not a Setup id")]
    [InlineData("0x010044B5\n", "ids.txt line 1: 0x010044B5 is outside the Setup range")]
    public void Setups_file_errors_name_the_line(string text, string message)
    {
        var e = Assert.Throws<FormatException>(() => SetupList.Parse("ids.txt", text));
        Assert.StartsWith(message, e.Message);
    }

    [Fact]
    public void Door_catalog_is_the_shared_tsv_with_its_provenance()
    {
        Assert.Equal(58, DoorCatalog.Entries.Count);
        Assert.Contains(DoorCatalog.Entries, e => e.SetupId == 0x020019FF && e.DoorWeenies == 2);
        Assert.Equal(207, DoorCatalog.Entries.Single(e => e.SetupId == 0x0200024F).DoorWeenies);
        Assert.Contains("Provenance", DoorCatalog.ReadResource().Split('\n')[0]);
        Assert.Equal(DoorCatalog.SetupIds.Order(), DoorCatalog.SetupIds);
    }
}
