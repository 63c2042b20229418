namespace AcShadow.Forge.Scale;

/// <summary>A GfxObj in a part pool and its rough size in metres (what Setups using it are sized by).</summary>
internal readonly record struct PoolPart(uint Id, float Size);
