using AcShadow.Fixtures.Bsp;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// Compiles each GfxObj's <see cref="BspDump"/> once, however many parts and models use it. The lookup
/// answers null for a GfxObj without a PhysicsBSP. Thread-safe.
/// </summary>
internal sealed class CompiledBspCache(Func<uint, BspDump?> dumps)
{
    private readonly Dictionary<uint, CompiledBsp?> _compiled = [];
    private readonly Lock _lock = new();

    public CompiledBsp? Get(uint gfxObjId)
    {
        lock (_lock)
        {
            if (_compiled.TryGetValue(gfxObjId, out var known)) return known;
            var dump = dumps(gfxObjId);
            var compiled = dump is null ? null : CompiledBsp.Compile(dump);
            _compiled[gfxObjId] = compiled;
            return compiled;
        }
    }
}
