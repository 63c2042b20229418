using AcShadow.Analysis.Chart;
using AcShadow.Core.Dat;
using AcShadow.Forging;

namespace AcShadow.Tests.Chart;

/// <summary>Chart runs on the built-in sample with the fixed timer, computed once per options.</summary>
public static class SampleChart
{
    internal static readonly Lazy<ChartSubjects> Subjects = new(() =>
    {
        var (portal, _) = SampleDats.Build();
        return new ChartSubjects(DatDatabase.Open(new MemoryStream(portal), "sample_portal.dat"));
    });

    public const uint Door = 0x020019FF;

    public static ChartReport Run(ChartOptions? options = null, params uint[] setups) =>
        ChartRunner.Run(setups.Select(id => Subjects.Value.For(id)!), options ?? new ChartOptions(), timer: new FixedTimer());

    private static readonly Lazy<ChartReport> DoorReport = new(() => Run(null, Door));

    public static ChartReport DoorOnly => DoorReport.Value;
}
