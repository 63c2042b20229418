namespace AcShadow.Fixtures.Batch;

/// <summary>What a file an export writes is, as index.json lists it.</summary>
public enum FixtureKind
{
    /// <summary>A Setup's shadow file, setups/0x%08X.shadow.json.</summary>
    Shadow,
    /// <summary>A GfxObj's BSP dump, gfxobjs/0x%08X.bsp.json.</summary>
    Bsp,
    /// <summary>A landblock's scene.json.</summary>
    Scene,
    /// <summary>A GfxObj in acdream's fixture shape.</summary>
    AcdreamGfxObj,
    /// <summary>An indoor cell, cells/0x%08X.cell.json.</summary>
    Cell,
    /// <summary>An indoor cell in acdream's EnvCell fixture shape.</summary>
    AcdreamCell,
    /// <summary>An object Setup's movement cases, movement/0x%08X.movement.json.</summary>
    Movement,
}
