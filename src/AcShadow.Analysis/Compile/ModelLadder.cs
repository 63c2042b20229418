using AcShadow.Analysis.Chart.Models;

namespace AcShadow.Analysis.Compile;

/// <summary>
/// The models a scene compiler tries: the Setup's own spheres (and CylSpheres), each BSP part's bounding
/// sphere, one cylinder, each part's box, each part's convex hull, and the retail model itself, which
/// always qualifies. They are tried fewest counted operations per query first (<see cref="ByCost"/>),
/// and the first that qualifies is chosen: a count is the same on every machine and run, so the choice
/// never depends on a timing, and a "cheaper kind" of shape that costs more than the BSP on this object
/// (a hull of many faces against a shallow tree) is never preferred to it.
/// </summary>
internal static class ModelLadder
{
    public static IReadOnlyList<IShapeModel> Models { get; } =
    [
        new SpheresModel(),
        new PartSpheresModel(),
        new FallbackCylinderModel(),
        new PartBoxesModel(),
        new PartHullsModel(),
        new RetailModel(),
    ];

    public static IReadOnlyList<string> Names => [.. Models.Select(m => m.Name)];

    public const string Retail = "retail";

    /// <summary>Ladder indices by counted cost per query, ascending; equal counts keep ladder order (cheaper kind of shape first).</summary>
    public static IReadOnlyList<int> ByCost(IReadOnlyList<double> costs) =>
        [.. Enumerable.Range(0, costs.Count).OrderBy(i => costs[i]).ThenBy(i => i)];
}
