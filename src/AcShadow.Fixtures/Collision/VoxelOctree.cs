namespace AcShadow.Fixtures.Collision;

/// <summary>
/// The cell codes of an octree under a coarse grid, as <see cref="BspReachGrid"/> and <see cref="Scenes.SceneReachGrid"/>
/// store them: top cells x-major, then y, then z; a negative code is minus the index of a cell's eight children
/// (x bit 0, y bit 1, z bit 2). Finding a finest voxel's code is one read per level it descends.
/// </summary>
internal static class VoxelOctree
{
    /// <summary>The code of finest voxel (x, y, z) in a tree of <paramref name="levels"/> levels under top cells <paramref name="topY"/> by <paramref name="topZ"/> deep.</summary>
    public static int Code(int[] cells, int x, int y, int z, int topY, int topZ, int levels)
    {
        var code = cells[((x >> levels) * topY + (y >> levels)) * topZ + (z >> levels)];
        for (var level = levels - 1; code < 0; level--)
            code = cells[-code + ((x >> level) & 1 | ((y >> level) & 1) << 1 | ((z >> level) & 1) << 2)];
        return code;
    }

    /// <summary>
    /// The same octree with each top cell's subtree stored in one run, depth first (a cell's eight children, then each
    /// child's subtree in turn). A build splits level by level, so one descent otherwise reads as many distant places as
    /// it has levels; laid out this way it stays within a few neighbouring cache lines. Codes other than child indexes
    /// are kept as they are.
    /// </summary>
    public static int[] DepthFirst(int[] cells, int topCount)
    {
        var laid = new int[cells.Length];
        Array.Copy(cells, laid, topCount);
        var next = topCount;
        for (var top = 0; top < topCount; top++)
            if (cells[top] < 0) laid[top] = -LayOut(cells, laid, -cells[top], ref next);
        return laid;
    }

    /// <summary>Copies the eight children at <paramref name="from"/> and their subtrees to <paramref name="next"/> onward; returns where the eight went.</summary>
    private static int LayOut(int[] cells, int[] laid, int from, ref int next)
    {
        var to = next;
        next += 8;
        for (var k = 0; k < 8; k++)
            laid[to + k] = cells[from + k] < 0 ? -LayOut(cells, laid, -cells[from + k], ref next) : cells[from + k];
        return to;
    }
}
