using AcShadow.Core.Chart.Models;

namespace AcShadow.Core.Scenes.Compile;

/// <summary>
/// The models a scene compiler tries, cheapest kind of shape first: the Setup's own spheres (and
/// CylSpheres), each BSP part's bounding sphere, one cylinder, each part's box, each part's convex hull,
/// and last the retail model itself, which always qualifies. The first that qualifies is chosen, so the
/// choice never depends on a timing.
/// </summary>
public static class ModelLadder
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
}
