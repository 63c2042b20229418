namespace AcShadow.Analysis.Chart.Models;

/// <summary>
/// A way to model an object's collision. Preparing turns a Setup into something that answers "does this
/// query sphere overlap the object?"; preparing may be slow, answering should be fast (it is timed).
/// Adding a model: one class implementing this, one line in <see cref="ShapeModels.All"/>.
/// </summary>
internal interface IShapeModel
{
    /// <summary>Short, stable, lower-case name used in CSV rows, SVG labels and the --model option.</summary>
    string Name { get; }

    /// <summary>One sentence for docs and legends.</summary>
    string Description { get; }

    PreparedModel Prepare(ChartSubject subject);
}
