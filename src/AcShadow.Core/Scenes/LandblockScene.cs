using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;

namespace AcShadow.Core.Scenes;

/// <summary>
/// Everything one LandBlockInfo places, statics first then buildings, in dat order: the objects a
/// scene export describes.
/// </summary>
public sealed record LandblockScene(uint LandBlockInfoId, IReadOnlyList<SceneObject> Objects)
{
    public LandblockCoordinates Coordinates => LandblockCoordinates.Of(LandBlockInfoId);

    public static LandblockScene From(LandBlockInfo info)
    {
        var objects = new List<SceneObject>();
        for (var i = 0; i < info.Objects.Count; i++)
            objects.Add(new SceneObject(objects.Count, ScenePlacedBy.Object, i, info.Objects[i].Id, KindOf(info.Objects[i].Id), info.Objects[i].Frame));
        for (var i = 0; i < info.Buildings.Count; i++)
            objects.Add(new SceneObject(objects.Count, ScenePlacedBy.Building, i, info.Buildings[i].ModelId, KindOf(info.Buildings[i].ModelId), info.Buildings[i].Frame));
        return new LandblockScene(info.Id, objects);
    }

    /// <summary>The distinct Setup ids placed, sorted.</summary>
    public IReadOnlyList<uint> SetupIds => Objects.Where(o => o.Kind == SceneObjectKind.Setup).Select(o => o.Id).Distinct().Order().ToArray();

    /// <summary>The distinct bare GfxObj ids placed, sorted.</summary>
    public IReadOnlyList<uint> GfxObjIds => Objects.Where(o => o.Kind == SceneObjectKind.GfxObj).Select(o => o.Id).Distinct().Order().ToArray();

    private static SceneObjectKind KindOf(uint id) =>
        DatObjectKind.Setup.Contains(id) ? SceneObjectKind.Setup
        : DatObjectKind.GfxObj.Contains(id) ? SceneObjectKind.GfxObj
        : SceneObjectKind.Other;
}
