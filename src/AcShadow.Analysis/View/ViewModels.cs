using AcShadow.Analysis.Chart.Models;
using AcShadow.Analysis.Chart.Output;

namespace AcShadow.Analysis.View;

/// <summary>
/// The layers a view can hold, in the order a file lists them: the chart's shape models that have geometry
/// to show (the retail reference, the seed's union, the buggy client's one cylinder, the Setup's own
/// spheres, and the fitted models a compiled scene can choose: each part's sphere, box or hull), a compiled
/// scene's indoor cells, then the chart's failures. Colours are the one palette every drawing uses.
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

    /// <summary>The model's colour in every drawing (<see cref="DrawingPalette"/>).</summary>
    public static string Colour(string model) => DrawingPalette.Model(model);

    public static string Description(string model) =>
        model == Cells ? "indoor cells' walls, floors and ceilings: their retail physics polygons (a cell is never compiled)"
        : ShapeModels.Find(model)?.Description ?? model;

    /// <summary>A failure layer's name: "part-boxes false passes". A model's two layers sit side by side.</summary>
    public static string FailureGroup(bool falsePass, string model) => model + (falsePass ? " false passes" : " false blocks");
}
