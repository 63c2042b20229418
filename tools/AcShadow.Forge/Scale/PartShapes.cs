using System.Numerics;
using AcShadow.Forging.Geometry;
using static AcShadow.Forge.Scale.SpecValues;

namespace AcShadow.Forge.Scale;

/// <summary>
/// The meshes of the scale spec's pooled parts: closed physics parts whose polygon counts are long-tailed
/// from 4 to 2,000 (boxes, walls, prisms, tables, buildings), and small drawing-only parts (limbs, items).
/// </summary>
internal static class PartShapes
{
    private const int MinPolygons = ScaleSpecGenerator.MinPhysicsPolygons, MaxPolygons = ScaleSpecGenerator.MaxPhysicsPolygons;

    /// <summary>
    /// 4 × 500^(u⁴), u uniform: long-tailed from 4 to 2,000 (median 6, about 11 % at 200 or more, 3 % at
    /// 1,000 or more). The shapes below come within a few polygons of it.
    /// </summary>
    public static int PhysicsPolygonCount(Random random)
    {
        var u = random.NextDouble();
        var n = (int)Math.Round(MinPolygons * Math.Pow(MaxPolygons / (double)MinPolygons, u * u * u * u));
        return Math.Clamp(n, MinPolygons, MaxPolygons);
    }

    /// <summary>A closed physics part of about <paramref name="polygons"/> polygons and its rough size (metres).</summary>
    public static (MeshBuilder Mesh, float Size) Physics(Random random, int polygons)
    {
        var m = new MeshBuilder();
        if (polygons < 6)
        {
            var s = (float)Range(random, 0.2, 2);
            return (polygons == 4 ? Tetrahedron(m, s) : Pyramid(m, s), s);
        }
        var kind = polygons >= 200 ? random.Next(5) switch { 0 => 0, 1 => 1, 2 => 2, _ => 4 } : random.Next(4);
        switch (kind)
        {
            case 0:
            {
                // A subdivided box: 6 k² polygons on six planes (big leaves, shallow tree).
                var k = Math.Max(1, (int)Math.Round(Math.Sqrt(polygons / 6.0)));
                var s = (float)Range(random, 0.3, 3);
                m.Box(new(-s / 2, -s / 2, 0), new(s / 2, s / 2, s), k, k, k);
                return (m, s);
            }
            case 1:
            {
                // A wall: 2(nx + nz + nx·nz) polygons.
                var length = (float)Range(random, 2, 12);
                var height = (float)Range(random, 1, 4);
                var thick = (float)Range(random, 0.1, 0.6);
                var nz = Math.Max(1, (int)Math.Round(Math.Sqrt(polygons / 8.0)));
                var nx = Math.Max(1, (polygons / 2 - nz) / (nz + 1));
                m.Box(new(-length / 2, -thick / 2, 0), new(length / 2, thick / 2, height), nx, 1, nz);
                return (m, length);
            }
            case 2:
            {
                // A prism (column, tower): sides · rings + 2 polygons.
                var r = (float)Range(random, 0.1, 2);
                var h = (float)Range(random, 0.3, 6);
                var sides = Math.Clamp(polygons - 2, 3, 48);
                var rings = Math.Max(1, (polygons - 2) / sides);
                m.Prism(Vector3.Zero, r, h, sides, rings);
                return (m, Math.Max(2 * r, h));
            }
            case 3:
            {
                // A compound: a slab top on 2-4 legs (a table, a stall), each a closed box.
                var w = (float)Range(random, 0.8, 4);
                var d = (float)Range(random, 0.6, 3);
                var h = (float)Range(random, 0.6, 2);
                var legs = random.Next(2, 5);
                var sub = Math.Max(1, (int)Math.Round(Math.Sqrt(Math.Max(1, polygons - 6 * legs) / 6.0)));
                m.Box(new(-w / 2, -d / 2, h - 0.1f), new(w / 2, d / 2, h), sub, sub, 1);
                for (var k = 0; k < legs; k++)
                {
                    var x = (k % 2 == 0 ? -1 : 1) * (w / 2 - 0.1f);
                    var y = (k / 2 == 0 ? -1 : 1) * (d / 2 - 0.1f);
                    m.Box(new(x - 0.05f, y - 0.05f, 0), new(x + 0.05f, y + 0.05f, h - 0.1f));
                }
                return (m, Math.Max(w, h));
            }
            default:
                return Building(m, random, polygons);
        }
    }

    /// <summary>
    /// A building: rooms, pillars and furniture as separate closed boxes of their own sizes on a floor grid,
    /// so their planes differ and the BSP is deep and branching (6 polygons per box).
    /// </summary>
    private static (MeshBuilder Mesh, float Size) Building(MeshBuilder m, Random random, int polygons)
    {
        var boxes = Math.Max(1, polygons / 6);
        var columns = (int)Math.Ceiling(Math.Sqrt(boxes));
        var cell = (float)Range(random, 1.5, 3);
        for (var b = 0; b < boxes; b++)
        {
            var x0 = b % columns * cell;
            var y0 = b / columns * cell;
            var w = (float)Range(random, 0.15, cell * 0.4);
            var d = (float)Range(random, 0.15, cell * 0.4);
            var h = (float)Range(random, 0.2, 4);
            var cx = x0 + cell / 2 + (float)Range(random, -0.1, 0.1);
            var cy = y0 + cell / 2 + (float)Range(random, -0.1, 0.1);
            m.Box(new(cx - w, cy - d, 0), new(cx + w, cy + d, h));
        }
        return (m, columns * cell);
    }

    /// <summary>4 triangles, outward wound.</summary>
    private static MeshBuilder Tetrahedron(MeshBuilder m, float s)
    {
        Vector3 a = new(0, 0, 0), b = new(s, 0, 0), c = new(0, s, 0), d = new(0, 0, s);
        return m.Polygon([a, c, b]).Polygon([a, b, d]).Polygon([a, d, c]).Polygon([b, c, d]);
    }

    /// <summary>A square pyramid: base and 4 sides, outward wound.</summary>
    private static MeshBuilder Pyramid(MeshBuilder m, float s)
    {
        Vector3 a = new(0, 0, 0), b = new(s, 0, 0), c = new(s, s, 0), d = new(0, s, 0), top = new(s / 2, s / 2, s);
        return m.Polygon([a, d, c, b]).Polygon([a, b, top]).Polygon([b, c, top]).Polygon([c, d, top]).Polygon([d, a, top]);
    }

    /// <summary>A drawing-only part (limb, item): a box or a prism.</summary>
    public static (MeshBuilder Mesh, float Size) Drawing(Random random)
    {
        var size = (float)Range(random, 0.1, 0.8);
        var mesh = random.Next(2) == 0
            ? new MeshBuilder().Box(new(-size / 2, -size / 3, 0), new(size / 2, size / 3, size))
            : new MeshBuilder().Prism(Vector3.Zero, size / 2, size, random.Next(6, 13));
        return (mesh, size);
    }
}
