using AcShadow.Core.Bsp;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Dat;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Core.Chart;

/// <summary>Chart subjects from a dat: each Setup with cached GfxObj and compiled-BSP lookups shared across Setups.</summary>
public sealed class ChartSubjects
{
    private readonly IDatSource _dat;
    private readonly Dictionary<uint, GfxObj?> _gfxObjs = [];
    private readonly Lock _lock = new();

    public CompiledBspCache Bsps { get; }

    private readonly ShapeBuildOptions? _pose;

    /// <param name="pose">The pose, door state and motion table every subject's parts take (default: the retail pose).</param>
    public ChartSubjects(IDatSource dat, ShapeBuildOptions? pose = null)
    {
        _dat = dat;
        _pose = pose;
        Bsps = new CompiledBspCache(id => GfxObj(id) is { } g ? BspExtractor.Extract(g) : null);
    }

    /// <summary>The GfxObj, or null when the dat does not have it or cannot decode it (the shape builder reports either).</summary>
    public GfxObj? GfxObj(uint id)
    {
        lock (_lock)
        {
            if (_gfxObjs.TryGetValue(id, out var known)) return known;
            GfxObj? read;
            try { read = _dat.ReadGfxObj(id); }
            catch (DatFormatException) { read = null; }
            _gfxObjs[id] = read;
            return read;
        }
    }

    /// <summary>
    /// The subject for a bare GfxObj a landblock places: the same one-part object a scene export describes
    /// (<see cref="Scenes.BareGfxObjShape"/>), or null when the dat has no such GfxObj.
    /// </summary>
    public ChartSubject? ForBareGfxObj(uint gfxObjId, float entityScale = 1f) =>
        GfxObj(gfxObjId) is { } gfx ? new ChartSubject(Scenes.BareGfxObjShape.OnePartSetup(gfx), GfxObj, Bsps.Get, entityScale) { Pose = _pose, Motions = _dat } : null;

    /// <summary>The subject for a Setup, or null when the dat has no such Setup.</summary>
    public ChartSubject? For(uint setupId, float entityScale = 1f) =>
        _dat.ReadSetup(setupId) is { } setup ? new ChartSubject(setup, GfxObj, Bsps.Get, entityScale) { Pose = _pose, Motions = _dat } : null;
}
