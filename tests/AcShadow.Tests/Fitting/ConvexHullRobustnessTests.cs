using System.Globalization;
using System.Numerics;
using AcShadow.Analysis.Fitting;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Fitting;

/// <summary>
/// A part with hundreds of vertices on its floor and roof planes: the faces a new vertex sees there can be
/// two patches, or ring a sliver it does not see. The hull must come out whole (every vertex inside it, in
/// a few dozen faces) instead of tearing and growing until the process runs out of memory, as it once did
/// in `chart --all` on the scale dat.
/// </summary>
public class ConvexHullRobustnessTests
{
    [Fact]
    public void A_flat_hall_with_many_coplanar_vertices_gets_a_whole_hull()
    {
        var vertices = File.ReadAllLines(Path.Combine(RepositoryRoot.Path, "tests", "AcShadow.Tests", "Fitting", "Data", "flat-hall-vertices.txt"))
            .Where(l => l.Length > 0 && l[0] != '#')
            .Select(l => l.Split(' ').Select(t => float.Parse(t, CultureInfo.InvariantCulture)).ToArray())
            .Select(v => new Vector3(v[0], v[1], v[2])).ToArray();
        Assert.Equal(1360, vertices.Length);

        var hull = ConvexHullBuilder.Build(vertices, []);

        Assert.NotNull(hull);
        Assert.InRange(hull.Faces.Count, 6, 200);
        // Every vertex inside or on every face's plane, within the builder's widest margin (100 × 1e-6 × the 40 m extent).
        var slack = 100 * ConvexHullBuilder.RelativeTolerance * 40 + 1e-5;
        foreach (var v in vertices)
            foreach (var face in hull.Faces)
                Assert.True(face.Distance(v) <= slack, $"vertex {v} is {face.Distance(v)} m outside face {face.Id}");
        // Closed: the hull holds a point in the middle of the hall and not one above its roof.
        Assert.True(hull.Overlaps(new Vector3(20, 20, 2), 0.1f));
        Assert.False(hull.Overlaps(new Vector3(20, 20, 10), 0.1f));
    }
}
