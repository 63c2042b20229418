using AcShadow.Analysis.Chart.Models;

namespace AcShadow.Analysis.View;

/// <summary>
/// The layers a view can hold, in the order a file lists them: the chart's shape models that have geometry
/// to show (the retail reference, the seed's union, the buggy client's one cylinder, the Setup's own
/// spheres, and the fitted models a compiled scene can choose: each part's sphere, box or hull), a compiled
/// scene's indoor cells, then the chart's failures. Colours are the Okabe–Ito ones the chart uses where they
/// mean the same thing.
/// </summary>
public static class ViewModels
{
    public const string Retail = "retail";
    public const string Union = "union";
    public const string FallbackCylinder = "fallback-cylinder";
    public const string Spheres = "spheres";
    public const string PartSpheres = "part-spheres";
    public const string PartBoxes = "part-boxes";
    public const string PartHulls = "part-hulls";

    /// <summary>A compiled scene's indoor cells: never compiled, always their retail polygons.</summary>
    public const string Cells = "cells";

    public static IReadOnlyList<string> Order { get; } = [Retail, Union, FallbackCylinder, Spheres, PartSpheres, PartBoxes, PartHulls, Cells];

    public static string Colour(string model) => model switch
    {
        Retail => "#56606e",
        Union => "#cc79a7",
        FallbackCylinder => "#d55e00",
        Spheres => "#009e73",
        PartSpheres => "#56b4e9",
        PartBoxes => "#0072b2",
        PartHulls => "#e69f00",
        Cells => "#a08560",
        _ => "#7f7f7f",
    };

    public static string Description(string model) =>
        model == Cells ? "indoor cells' walls, floors and ceilings: their retail physics polygons (a cell is never compiled)"
        : ShapeModels.Find(model)?.Description ?? model;

    public const string FalsePassColour = "#d62728";
    public const string FalseBlockColour = "#1f77b4";

    /// <summary>A failure layer's name: "false passes: fallback-cylinder".</summary>
    public static string FailureGroup(bool falsePass, string model) => (falsePass ? "false passes: " : "false blocks: ") + model;
}
