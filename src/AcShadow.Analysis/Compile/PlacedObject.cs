using AcShadow.Core.Scenes;
namespace AcShadow.Analysis.Compile;

/// <summary>
/// One object a compiled scene places: the LandBlockInfo's static objects and buildings, then each
/// indoor cell's static objects (<see cref="CellId"/> names the cell; their frames are landblock-relative
/// like every other placement's). Indices run on through all of them.
/// </summary>
public sealed record PlacedObject(SceneObject Object, uint? CellId)
{
    public static IReadOnlyList<PlacedObject> Of(LandblockScene scene)
    {
        var placed = scene.Objects.Select(o => new PlacedObject(o, null)).ToList();
        foreach (var cell in scene.Cells)
            for (var i = 0; i < cell.StaticObjects.Count; i++)
            {
                var stab = cell.StaticObjects[i];
                placed.Add(new PlacedObject(new SceneObject(placed.Count, ScenePlacedBy.Cell, i, stab.Id, LandblockScene.KindOf(stab.Id), stab.Frame), cell.Id));
            }
        return placed;
    }
}
