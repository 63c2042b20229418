using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures.Collision;

/// <summary>Diagnostic codes of the collision reference (stable; consumers filter on them).</summary>
public static class CollisionDiagnosticCodes
{
    /// <summary>A polygon without a usable plane or vertices: never tested.</summary>
    public const string SkippedPolygon = "skipped-polygon";
    /// <summary>A non-planar polygon: tested against its averaged plane, as retail does.</summary>
    public const string NonPlanarPolygon = "non-planar-polygon";
    /// <summary>A node that is malformed (bad child index, missing plane, non-finite sphere): repaired as stated.</summary>
    public const string MalformedNode = "malformed-node";
    /// <summary>A leaf names a polygon id that is not a physics polygon.</summary>
    public const string MissingPolygon = "missing-polygon";
    /// <summary>A physics polygon no reachable leaf holds: retail never tests it, the brute force does.</summary>
    public const string UnreferencedPolygon = "unreferenced-polygon";
    /// <summary>A node's bounding sphere does not contain a polygon below it: the tree can miss contacts.</summary>
    public const string SphereMissesPolygon = "sphere-misses-polygon";
    /// <summary>A polygon reaches past an ancestor's splitting plane with no copy on that side: the tree can miss contacts.</summary>
    public const string PolygonCrossesPlane = "polygon-crosses-plane";
    /// <summary>A solid leaf holding no polygons: BSPLEAF::sphere_intersects_solid returns before its centre check.</summary>
    public const string InertSolidLeaf = "inert-solid-leaf";
    /// <summary>An empty tree, or a root that is missing: nothing of the part collides.</summary>
    public const string EmptyTree = "empty-tree";
    /// <summary>A shape the object query cannot use (missing BSP, NaN in its frame, zero scale, zero radius).</summary>
    public const string SkippedShape = "skipped-shape";
    /// <summary>A shape whose rotation was not a unit quaternion: normalised.</summary>
    public const string NormalisedRotation = "normalised-rotation";
    /// <summary>More diagnostics of one kind than are listed.</summary>
    public const string Truncated = "truncated";
}
