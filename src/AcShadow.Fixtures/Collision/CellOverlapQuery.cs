using System.Numerics;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// The collision reference for an indoor cell, as retail answers it for cells (EnvCell::find_env_collisions,
/// ported by ACE as EnvCell.FindEnvCollisions): the query sphere is moved into the cell's own frame
/// (CSpherePath::CacheLocalSpaceSphere with the cell's position and scale 1: Frame::globaltolocal by the
/// transpose of the matrix Frame::cache builds from the stored, unnormalised quaternion,
/// <see cref="ClientFrameMatrix"/>) and asked of the cell structure's PhysicsBSP, the same tree walk as a part's
/// (<see cref="BspSphereQuery"/>). A cell has no broad-phase sphere of its own beyond its tree's root.
/// </summary>
internal sealed class CellOverlapQuery : ISphereOverlap
{
    private readonly ClientFrameMatrix _frame;
    private readonly BspSphereQuery _bsp;
    private readonly ISphereOverlap _tree;
    private readonly bool _unitRotation;

    /// <param name="physics">The cell structure's physics polygons and PhysicsBSP, in the cell's own frame.</param>
    /// <param name="origin">The cell's origin in the frame the queries use (landblock-relative, as the dat stores it).</param>
    /// <param name="orientation">The cell's rotation in that frame.</param>
    public CellOverlapQuery(BspDump physics, Vector3 origin, Quaternion orientation)
        : this(CompiledBsp.Compile(physics), origin, orientation)
    {
    }

    /// <param name="physics">The cell structure's PhysicsBSP already compiled, in the cell's own frame.</param>
    /// <param name="origin">The cell's origin in the frame the queries use.</param>
    /// <param name="orientation">The cell's rotation in that frame.</param>
    internal CellOverlapQuery(CompiledBsp physics, Vector3 origin, Quaternion orientation)
    {
        var length = orientation.Length();
        if (!float.IsFinite(length) || length < 1e-6f || !Vec.IsFinite(origin))
            throw new ArgumentException($"a cell frame needs a finite origin and a non-zero rotation; got {origin}, {orientation}");
        _frame = ClientFrameMatrix.From(new Frame(origin, ClientFrameMatrix.PlacedRotation(orientation)));
        _bsp = new BspSphereQuery(physics);
        _tree = _bsp;
        _unitRotation = MathF.Abs(orientation.LengthSquared() - 1f) <= 1e-4f;
    }

    private CellOverlapQuery(CellOverlapQuery cell, ISphereOverlap tree)
    {
        _frame = cell._frame;
        _bsp = cell._bsp;
        _tree = tree;
        _unitRotation = cell._unitRotation;
    }

    /// <summary>The same cell with its tree asked through its <see cref="BspReachGrid"/>s (the radius is not scaled in a cell's frame): the same answers.</summary>
    internal CellOverlapQuery Indexed(BspReachGrids grids) => new(this, grids.Index(_bsp, new PartPose(Vector3.Zero, Quaternion.Identity, 1f)));

    /// <summary>
    /// The tree's root sphere in the frame of the cell's origin, widened by 1e-3 of its reach for the rounding
    /// of the cell's turn: no sphere outside it gets past the root (CGfxObj::find_obj_collisions' broad phase).
    /// Null when there is none to give: no tree, or a rotation so far from unit length that Frame::cache's
    /// matrix stretches distances.
    /// </summary>
    public (Vector3 Center, float Radius)? Bound
    {
        get
        {
            var nodes = _bsp.Bsp.Nodes;
            if (nodes.Length == 0 || !_unitRotation) return null;
            var root = nodes[0];
            var reach = root.SphereRadius + root.SphereCenter.Length();
            return (_frame.LocalToGlobal(root.SphereCenter), root.SphereRadius + 1e-3f * reach);
        }
    }

    /// <summary>Does a sphere at this centre (same frame as the cell's origin) touch one of the cell's physics polygons?</summary>
    public bool Overlaps(Vector3 center, float radius)
    {
        return _tree.Overlaps(_frame.GlobalToLocal(center), radius);
    }

    /// <summary>The cell's frame as <see cref="Overlaps"/> turns a sphere into it.</summary>
    internal ClientFrameMatrix Frame => _frame;

    /// <summary>The cell's tree, as <see cref="Overlaps"/> asks it (directly or through its grids: the same answers).</summary>
    internal BspSphereQuery Tree => _bsp;

    /// <summary>A point in the cell's own frame.</summary>
    public Vector3 ToCell(Vector3 point) => _frame.GlobalToLocal(point);

    /// <summary>A point of the cell's own frame in the frame of its origin.</summary>
    public Vector3 FromCell(Vector3 local) => _frame.LocalToGlobal(local);
}
