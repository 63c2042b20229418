using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.View;

/// <summary>
/// Turns a shadow shape into triangles and an outline in its entity's frame. A BSP part is its physics
/// polygons, posed as the collision reference poses them (<see cref="PartPose"/>), each polygon with its
/// retail plane's normal; a polygon whose SidesType is not single-sided (0) is two-sided. A compiled
/// scene's fitted solids (part boxes, part hulls) are their faces, one-sided and outward. Cylinders and
/// spheres get 32 segments around (and a sphere 16 bands), enough to read as round.
/// </summary>
internal static class ShapeTessellation
{
    private const int SphereBands = UnitCircle.Steps / 2;

    /// <summary>
    /// The shape's name in a view, as compiled-scene.json and the chart name it: "part 0 (GfxObj 0x010044B5)",
    /// "CylSphere 1", "Sphere 0", "Setup Radius x Height".
    /// </summary>
    public static string NameOf(ShadowShape shape) => shape switch
    {
        { SourceIndex: < 0 } => "Setup Radius x Height",
        { Source: ShapeSource.Part } => $"part {shape.SourceIndex} (GfxObj 0x{shape.GfxObjId ?? 0:X8})",
        { Source: ShapeSource.CylSphere } => $"CylSphere {shape.SourceIndex}",
        _ => $"Sphere {shape.SourceIndex}",
    } + (shape.CollisionType == CollisionType.Cylinder && shape.Source == ShapeSource.Sphere && shape.SourceIndex >= 0 ? " as cylinder" : "");

    /// <summary>The shape, or null when there is nothing to draw (a BSP whose dump is missing, a zero radius).</summary>
    public static ViewShape? Tessellate(ShadowShape shape, Func<uint, BspDump?> bsps) => shape.CollisionType switch
    {
        CollisionType.Bsp => shape.GfxObjId is { } id && bsps(id) is { } dump ? Bsp(shape, dump) : null,
        CollisionType.Cylinder when shape.Radius > 0f && shape.CylHeight >= 0f => Cylinder(NameOf(shape), shape.LocalPosition, shape.Radius, shape.CylHeight),
        CollisionType.Sphere when shape.Radius > 0f => Sphere(NameOf(shape), shape.LocalPosition, shape.Radius),
        _ => null,
    };

    public static ViewShape Bsp(ShadowShape shape, BspDump dump) =>
        Polygons(NameOf(shape), PartPose.InEntity(shape.LocalPosition, shape.LocalRotation, shape.Scale), dump);

    /// <summary>A BSP dump's physics polygons posed by <paramref name="pose"/> (a part's in its entity, the identity for a cell in its own frame).</summary>
    public static ViewShape Polygons(string name, PartPose pose, BspDump dump)
    {
        var vertices = new Dictionary<int, Vector3>();
        foreach (var v in dump.Vertices) vertices[v.Id] = pose.ToEntity(v.Position);
        var oneSided = new TriangleMesh();
        var twoSided = new TriangleMesh();
        var outline = new List<Vector3[]>();
        foreach (var polygon in dump.Polygons)
        {
            // A degenerate polygon has no plane and so no face to show; retail never hits it either.
            if (polygon.Plane is not { } plane || polygon.VertexIds.Any(id => !vertices.ContainsKey(id))) continue;
            var loop = polygon.VertexIds.Select(id => vertices[id]).ToArray();
            (polygon.SidesType == SidesType.Landblock ? oneSided : twoSided).AddPolygon(loop, Posed(pose, plane.Normal));
            outline.Add(loop);
        }
        return new ViewShape(name, oneSided, twoSided, new PolygonOutline(outline), Anchor(pose, outline));
    }

    /// <summary>A fitted part box (the compiled scene's <c>part-boxes</c>): its six faces, one-sided and outward, 12 triangles (a flat box its two faces, 4).</summary>
    public static ViewShape Box(string name, PartPose pose, OrientedBox box) => Solid(name, pose, box.ToPolytope());

    /// <summary>
    /// A convex solid in a part's space (a part's hull, or a box as one): each face a one-sided polygon with
    /// its outward plane normal, triangulated as a fan (a hull's faces are convex).
    /// </summary>
    public static ViewShape Solid(string name, PartPose pose, ConvexPolytope solid)
    {
        var mesh = new TriangleMesh();
        var outline = new List<Vector3[]>();
        foreach (var face in solid.Faces)
        {
            var loop = face.Vertices.Select(pose.ToEntity).ToArray();
            mesh.AddPolygon(loop, Posed(pose, face.Normal));
            outline.Add(loop);
        }
        return new ViewShape(name, mesh, new TriangleMesh(), new PolygonOutline(outline), Anchor(pose, outline));
    }

    /// <summary>
    /// A part-space normal in the entity for shading: turned by the part's rotation, reversed by a mirroring
    /// (negative) scale. Drawing only (no client counterpart), so the plain rotation, not the client's matrix.
    /// </summary>
    private static Vector3 Posed(PartPose pose, Vector3 normal)
    {
        var turned = QuaternionRotation.Rotate(pose.Rotation, normal);
        return pose.Scale < 0f ? new Vector3(-turned.X, -turned.Y, -turned.Z) : turned;
    }

    /// <summary>Where a part's label goes: its origin, at the height of the middle of what is drawn.</summary>
    private static Vector3 Anchor(PartPose pose, List<Vector3[]> outline)
    {
        var zs = outline.SelectMany(l => l).Select(v => v.Z).DefaultIfEmpty(pose.Position.Z).ToArray();
        return pose.Position with { Z = (zs.Min() + zs.Max()) / 2 };
    }

    public static ViewShape Cylinder(string name, Vector3 baseCentre, float radius, float height)
    {
        var mesh = new TriangleMesh();
        var top = baseCentre.Z + height;
        Vector3 Rim(int k, float z)
        {
            var (c, s) = UnitCircle.At(k);
            return new Vector3(baseCentre.X + radius * c, baseCentre.Y + radius * s, z);
        }
        for (var k = 0; k < UnitCircle.Steps; k++)
            mesh.AddFace(Rim(k, baseCentre.Z), Rim(k + 1, baseCentre.Z), Rim(k + 1, top), Rim(k, top));
        var bottomCap = new Vector3[UnitCircle.Steps];
        var topCap = new Vector3[UnitCircle.Steps];
        for (var k = 0; k < UnitCircle.Steps; k++)
        {
            bottomCap[k] = Rim(UnitCircle.Steps - k, baseCentre.Z);
            topCap[k] = Rim(k, top);
        }
        mesh.AddPolygon(bottomCap, new Vector3(0, 0, -1));
        mesh.AddPolygon(topCap, new Vector3(0, 0, 1));
        return new ViewShape(name, mesh, new TriangleMesh(), new CylinderOutline(baseCentre, radius, height), baseCentre with { Z = baseCentre.Z + height / 2 });
    }

    public static ViewShape Sphere(string name, Vector3 centre, float radius) =>
        new(name, SphereMesh(centre, radius, SphereBands, 1), new TriangleMesh(), new SphereOutline(centre, radius), centre);

    /// <summary>
    /// A marker at each point, <paramref name="size"/> from its centre to a corner: an octahedron (a diamond
    /// from every side) for a false pass, a cube for a false block, so the two verdicts differ in shape as
    /// well as in layer.
    /// </summary>
    public static ViewShape Markers(string name, IReadOnlyList<Vector3> points, float size, bool falsePass)
    {
        var mesh = new TriangleMesh();
        foreach (var p in points)
            if (falsePass) AddOctahedron(mesh, p, size);
            else AddCube(mesh, p, size / MathF.Sqrt(3));
        return new ViewShape(name, mesh, new TriangleMesh(), new PointsOutline(points, falsePass), points.Count > 0 ? points[0] : Vector3.Zero);
    }

    private static void AddOctahedron(TriangleMesh mesh, Vector3 c, float r)
    {
        Vector3 x = new(r, 0, 0), y = new(0, r, 0), z = new(0, 0, r);
        foreach (var sx in new[] { 1f, -1f })
            foreach (var sy in new[] { 1f, -1f })
                foreach (var sz in new[] { 1f, -1f })
                {
                    Vector3 a = c + sx * x, b = c + sy * y, t = c + sz * z;
                    // Counter-clockwise seen from outside: the sign of the octant decides the order.
                    if (sx * sy * sz > 0) mesh.AddFace(a, b, t);
                    else mesh.AddFace(a, t, b);
                }
    }

    private static void AddCube(TriangleMesh mesh, Vector3 c, float h)
    {
        Vector3 P(float x, float y, float z) => c + new Vector3(x * h, y * h, z * h);
        mesh.AddFace(P(-1, -1, -1), P(-1, 1, -1), P(1, 1, -1), P(1, -1, -1));
        mesh.AddFace(P(-1, -1, 1), P(1, -1, 1), P(1, 1, 1), P(-1, 1, 1));
        mesh.AddFace(P(-1, -1, -1), P(1, -1, -1), P(1, -1, 1), P(-1, -1, 1));
        mesh.AddFace(P(-1, 1, -1), P(-1, 1, 1), P(1, 1, 1), P(1, 1, -1));
        mesh.AddFace(P(-1, -1, -1), P(-1, -1, 1), P(-1, 1, 1), P(-1, 1, -1));
        mesh.AddFace(P(1, -1, -1), P(1, 1, -1), P(1, 1, 1), P(1, -1, 1));
    }

    private static TriangleMesh SphereMesh(Vector3 centre, float radius, int bands, int stride)
    {
        var mesh = new TriangleMesh();
        AddSphere(mesh, centre, radius, bands, stride);
        return mesh;
    }

    /// <summary>A latitude–longitude sphere: <paramref name="bands"/> from pole to pole, every <paramref name="stride"/>-th step of the unit circle around.</summary>
    private static void AddSphere(TriangleMesh mesh, Vector3 centre, float radius, int bands, int stride)
    {
        // Latitude steps are the unit circle's too: band b spans polar angles b·π/bands to (b+1)·π/bands.
        var latitudeStride = UnitCircle.Steps / 2 / bands;
        Vector3 Point(int band, int k)
        {
            var (cosPolar, sinPolar) = UnitCircle.At(band * latitudeStride);
            var (c, s) = UnitCircle.At(k);
            return new Vector3(centre.X + radius * sinPolar * c, centre.Y + radius * sinPolar * s, centre.Z + radius * cosPolar);
        }
        for (var band = 0; band < bands; band++)
            for (var k = 0; k < UnitCircle.Steps; k += stride)
            {
                Vector3 a = Point(band, k), b = Point(band + 1, k), c = Point(band + 1, k + stride), d = Point(band, k + stride);
                if (band == 0) mesh.AddFace(a, b, c);
                else if (band == bands - 1) mesh.AddFace(a, b, d);
                else mesh.AddFace(a, b, c, d);
            }
    }
}
