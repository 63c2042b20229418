using System.Numerics;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Compile;

namespace AcShadow.Tests.Scenes;

public sealed class ProbeSpheresTests
{
    [Fact]
    public void Each_probe_reads_back_with_its_centre_radius_and_kind()
    {
        Probe[] probes =
        [
            new(new Vector3(1.5f, -2f, 0.25f), 0.48f, ProbeKind.Grid),
            new(new Vector3(float.Epsilon, 3f, 1e7f), 0.1f, ProbeKind.Face),
            new(new Vector3(-0f, 0f, -4f), 0.48f, ProbeKind.SplittingPlane),
            new(new Vector3(9f, 9f, 9f), -0f, ProbeKind.Vertex),
        ];

        var spheres = new ProbeSpheres(probes);

        Assert.Equal(probes.Length, spheres.Count);
        Assert.Equal(probes, spheres.ToArray());
        Assert.Equal(probes, Enumerable.Range(0, spheres.Count).Select(i => spheres[i]).ToArray());
        Assert.True(float.IsNegative(spheres[3].Radius));
        Assert.Equal(2, ChartProbes.Count(spheres, ProbeKind.Grid) + ChartProbes.Count(spheres, ProbeKind.Face));
    }

    [Fact]
    public void A_doorway_probe_keeps_its_sphere_and_kind_but_not_its_line()
    {
        var spheres = new ProbeSpheres([new Probe(new Vector3(0f, 1f, 0.5f), 0.3f, ProbeKind.Doorway, 4, 0.75f)]);

        Assert.Equal(new Probe(new Vector3(0f, 1f, 0.5f), 0.3f, ProbeKind.Doorway), spheres[0]);
    }

    [Fact]
    public void More_distinct_radii_than_a_byte_indexes_are_refused()
    {
        var probes = Enumerable.Range(0, 257).Select(i => new Probe(Vector3.Zero, i, ProbeKind.Grid)).ToArray();

        Assert.Throws<ArgumentException>(() => new ProbeSpheres(probes));
        Assert.Equal(256, new ProbeSpheres(probes[..256]).Count);
    }
}
