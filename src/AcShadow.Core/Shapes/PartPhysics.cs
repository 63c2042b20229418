using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Core.Shapes;

/// <summary>
/// What a Setup's shapes need of a part's GfxObj: whether it has a PhysicsBSP (CPartArray::CacheHasPhysicsBSP
/// asks exactly that of each part) and the BSP's root sphere. A few bytes where the decoded GfxObj holds every
/// polygon and node, so a run exporting many Setups keeps one per GfxObj instead of decoding a shared part again.
/// </summary>
public sealed record PartPhysics(uint Id, Sphere? BspBound)
{
    public bool HasPhysics => BspBound is not null;

    public static PartPhysics Of(GfxObj gfx) => new(gfx.Id, gfx.HasPhysics ? gfx.PhysicsBsp!.BoundingSphere : null);
}
