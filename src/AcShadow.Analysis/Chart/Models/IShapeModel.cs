namespace AcShadow.Analysis.Chart.Models;

/// <summary>
/// A way to model an object's collision. Preparing turns a Setup into something that answers "does this
/// query sphere overlap the object?"; preparing may be slow, answering should be fast (it is timed).
/// Adding a model: one class implementing this, one line in <see cref="ShapeModels.All"/>.
/// </summary>
internal interface IShapeModel
{
    /// <summary>Short, stable, lower-case name used in chart's and scene's CSV rows and SVG labels, compiled-scene.json's chosen model and view's layer names (no option selects models by it).</summary>
    string Name { get; }

    /// <summary>One sentence for docs and legends.</summary>
    string Description { get; }

    PreparedModel Prepare(ChartSubject subject);
}
