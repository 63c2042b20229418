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
}
