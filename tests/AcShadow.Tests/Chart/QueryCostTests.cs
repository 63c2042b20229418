using System.Numerics;
using AcShadow.Analysis.Chart;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Tests.Chart;

/// <summary>The counted cost per query: fixed weights per step, worked out by hand for hand-built shapes.</summary>
public class QueryCostTests
{
    private static readonly PartPose Identity = new(Vector3.Zero, Quaternion.Identity, 1f);

    private static PreparedShape Sphere(Vector3 at, float radius) =>
        new(new ShadowShape(ShapeSource.Sphere, 0, null, CollisionType.Sphere, at, Quaternion.Identity, 1f, radius, 0f, null), "Sphere 0", Identity, null);

    private static Probe[] Probes(params Vector3[] at) => [.. at.Select(p => new Probe(p, 0.5f, ProbeKind.Grid))];

    [Fact]
    public void A_sphere_is_one_evaluation_and_the_count_stops_at_the_first_shape_that_blocks()
    {
        PreparedShape[] two = [Sphere(Vector3.Zero, 1f), Sphere(new Vector3(10, 0, 0), 1f)];
        // Near the first sphere: it blocks, the second is never asked (1); far from both: both asked (2).
        Assert.Equal(1.0, QueryCost.PerQuery(two, Probes(Vector3.Zero), 4096));
        Assert.Equal(2.0, QueryCost.PerQuery(two, Probes(new Vector3(0, 50, 0)), 4096));
        Assert.Equal(1.5, QueryCost.PerQuery(two, Probes(Vector3.Zero, new Vector3(0, 50, 0)), 4096));
        Assert.Equal(0.0, QueryCost.PerQuery(two, [], 4096));
    }

    [Fact]
    public void A_box_is_the_turn_into_its_part_and_two_evaluations()
    {
        var box = new OrientedBox(Vector3.Zero, Quaternion.Identity, new Vector3(1, 1, 1));
        var shape = Sphere(Vector3.Zero, 1f) with { Box = box, Polytope = box.ToPolytope() };
        Assert.Equal(QueryCost.Transform + 2, QueryCost.PerQuery([shape], Probes(new Vector3(5, 0, 0)), 4096));
    }

    [Fact]
    public void A_hull_far_away_costs_its_turn_and_bounding_sphere_and_one_nearby_pays_per_face()
    {
        var box = new OrientedBox(Vector3.Zero, Quaternion.Identity, new Vector3(1, 1, 1));
        var hull = Sphere(Vector3.Zero, 1f) with { Polytope = box.ToPolytope() };
        Assert.Equal(QueryCost.Transform + 1, QueryCost.PerQuery([hull], Probes(new Vector3(50, 0, 0)), 4096));
        // The centre inside: every one of the six face planes is evaluated, none separates.
        Assert.Equal(QueryCost.Transform + 1 + 6, QueryCost.PerQuery([hull], Probes(Vector3.Zero), 4096));
    }
}
