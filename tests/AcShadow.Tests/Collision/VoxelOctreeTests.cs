using AcShadow.Fixtures.Collision;

namespace AcShadow.Tests.Collision;

/// <summary>
/// An octree laid out depth first (<see cref="VoxelOctree.DepthFirst"/>) gives every finest voxel the code it had, and
/// keeps each top cell's subtree in one run of the array.
/// </summary>
public class VoxelOctreeTests
{
    // Two top cells along z (1 × 1 × 2), two levels under each. Built level by level, as the grids build: top cell 0
    // splits at 2..9, top cell 1 at 10..17; then top cell 0's child 3 at 18..25 and top cell 1's child 0 at 26..33, so
    // each top cell's second level lies past the other's first.
    private const int Levels = 2;

    private static int[] LevelByLevel()
    {
        var cells = new int[34];
        cells[0] = -2;
        cells[1] = -10;
        for (var k = 0; k < 8; k++)
        {
            cells[2 + k] = 100 + k;
            cells[10 + k] = 200 + k;
            cells[18 + k] = 300 + k;
            cells[26 + k] = 400 + k;
        }
        cells[2 + 3] = -18;
        cells[10 + 0] = -26;
        return cells;
    }

    [Fact]
    public void Every_voxel_keeps_its_code()
    {
        var cells = LevelByLevel();
        var laid = VoxelOctree.DepthFirst(cells, topCount: 2);
        Assert.Equal(cells.Length, laid.Length);
        var seen = new HashSet<int>();
        for (var x = 0; x < 1 << Levels; x++)
            for (var y = 0; y < 1 << Levels; y++)
                for (var z = 0; z < 2 << Levels; z++)
                {
                    var code = VoxelOctree.Code(cells, x, y, z, topY: 1, topZ: 2, Levels);
                    Assert.Equal(code, VoxelOctree.Code(laid, x, y, z, topY: 1, topZ: 2, Levels));
                    seen.Add(code);
                }
        // Every leaf code of the tree is some voxel's: 7 + 8 under each top cell.
        Assert.Equal(30, seen.Count);
    }

    [Fact]
    public void Each_top_cell_subtree_is_one_run_children_first()
    {
        var laid = VoxelOctree.DepthFirst(LevelByLevel(), topCount: 2);
        // Top cell 0: its eight children at 2..9, its child 3's eight at 10..17; then top cell 1's at 18..25 and 26..33.
        Assert.Equal(-2, laid[0]);
        Assert.Equal(-18, laid[1]);
        Assert.Equal(-10, laid[2 + 3]);
        Assert.Equal(-26, laid[18 + 0]);
        Assert.Equal([300, 301, 302, 303, 304, 305, 306, 307], laid[10..18]);
        Assert.Equal([400, 401, 402, 403, 404, 405, 406, 407], laid[26..34]);
    }
}
