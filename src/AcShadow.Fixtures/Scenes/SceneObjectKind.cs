namespace AcShadow.Fixtures.Scenes;

/// <summary>What a placed id is: a Setup (0x02…), a bare GfxObj (0x01…), or something acshadow does not describe.</summary>
public enum SceneObjectKind
{
    Setup,
    GfxObj,
    Other,
}
