namespace AcShadow.Analysis.Chart.Models;

/// <summary>The models the chart compares, in chart order. The first is the reference.</summary>
internal static class ShapeModels
{
    public static IReadOnlyList<IShapeModel> All { get; } =
    [
        new RetailModel(),
        new UnionModel(),
        new FallbackCylinderModel(),
        new SpheresModel(),
        new PartSpheresModel(),
        new PartBoxesModel(),
        new PartHullsModel(),
        new PlacementPoseModel(),
    ];

    public static IShapeModel? Find(string name) => All.FirstOrDefault(m => string.Equals(m.Name, name, StringComparison.OrdinalIgnoreCase));
}
