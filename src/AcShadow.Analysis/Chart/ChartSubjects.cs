using AcShadow.Analysis.Chart.Models;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Scenes;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Analysis.Chart;

/// <summary>
/// Chart subjects from a dat: each Setup with cached GfxObj and compiled-BSP lookups shared across Setups.
/// The two caches hold the same GfxObjs (each compiled BSP is of a GfxObj in the GfxObj cache), and are
/// started afresh before the next subject once they hold more than <see cref="CacheCapacity"/> (2048 by
/// default), so they hold at most that many plus one subject's parts (a subject made earlier keeps the
/// caches it was made with until it is dropped). The dat source beneath keeps its own cache, which this
/// class does not bound: a <see cref="DatDatabase"/> made without a capacity keeps every object it decodes,
/// so a run over a whole dat passes one with a capacity (chart and batch keep 256 decoded objects).
/// </summary>
internal sealed class ChartSubjects
{
    public const int DefaultCacheCapacity = 2048;

    private readonly IDatSource _dat;
    private Dictionary<uint, GfxObj?> _gfxObjs = [];
    private readonly Lock _lock = new();

    internal CompiledBspCache Bsps { get; private set; }
    public int CacheCapacity { get; }

    /// <summary>The portal dat the subjects come from.</summary>
    public IDatSource Dat => _dat;

    private readonly ShapeBuildOptions? _pose;

    /// <param name="dat">The portal dat.</param>
    /// <param name="pose">The pose, door state and motion table every subject's parts take (default: the retail pose).</param>
    /// <param name="cacheCapacity">How many GfxObjs the caches hold before they are started afresh.</param>
    public ChartSubjects(IDatSource dat, ShapeBuildOptions? pose = null, int cacheCapacity = DefaultCacheCapacity)
    {
        _dat = dat;
        _pose = pose;
        CacheCapacity = cacheCapacity;
        Bsps = NewBspCache(_gfxObjs);
    }

    private CompiledBspCache NewBspCache(Dictionary<uint, GfxObj?> gfxObjs) =>
        new(id => Read(gfxObjs, id) is { } g ? BspExtractor.Extract(g) : null);

    /// <summary>The current caches, started afresh when full.</summary>
    private (Func<uint, GfxObj?> GfxObjs, Func<uint, CompiledBsp?> Bsps) Caches()
    {
        lock (_lock)
        {
            if (_gfxObjs.Count > CacheCapacity)
            {
                _gfxObjs = [];
                Bsps = NewBspCache(_gfxObjs);
            }
            var gfxObjs = _gfxObjs;
            return (id => Read(gfxObjs, id), Bsps.Get);
        }
    }

    private GfxObj? Read(Dictionary<uint, GfxObj?> cache, uint id)
    {
        lock (cache)
        {
            if (cache.TryGetValue(id, out var known)) return known;
            GfxObj? read;
            try { read = _dat.ReadGfxObj(id); }
            catch (DatFormatException) { read = null; }
            cache[id] = read;
            return read;
        }
    }

    /// <summary>The GfxObj, or null when the dat does not have it or cannot decode it (the shape builder reports either).</summary>
    public GfxObj? GfxObj(uint id)
    {
        Dictionary<uint, GfxObj?> cache;
        lock (_lock) cache = _gfxObjs;
        return Read(cache, id);
    }

    /// <summary>
    /// The subject for a bare GfxObj a landblock places: the same one-part object a scene export describes
    /// (<see cref="BareGfxObjShape"/>), or null when the dat has no such GfxObj.
    /// </summary>
    public ChartSubject? ForBareGfxObj(uint gfxObjId, float entityScale = 1f)
    {
        var (gfxObjs, bsps) = Caches();
        return gfxObjs(gfxObjId) is { } gfx ? new ChartSubject(BareGfxObjShape.OnePartSetup(gfx), gfxObjs, bsps, entityScale) { Pose = _pose, Motions = _dat } : null;
    }

    /// <summary>The subject for a Setup, or null when the dat has no such Setup.</summary>
    public ChartSubject? For(uint setupId, float entityScale = 1f)
    {
        var (gfxObjs, bsps) = Caches();
        return _dat.ReadSetup(setupId) is { } setup ? new ChartSubject(setup, gfxObjs, bsps, entityScale) { Pose = _pose, Motions = _dat } : null;
    }
}
