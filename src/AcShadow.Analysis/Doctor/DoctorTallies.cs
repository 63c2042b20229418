namespace AcShadow.Analysis.Doctor;

/// <summary>What the passes over the dat count, filled from many threads and read once at the end.</summary>
internal sealed class DoctorTallies
{
    // Reading.
    public readonly Counter GfxObjs = new(), Setups = new(), LandBlockInfos = new();
    public readonly Counter GfxObjsDecoded = new(), SetupsDecoded = new(), LandBlockInfosDecoded = new();
    public readonly Finding DecodeFailed = new();
    public readonly Dictionary<string, Counter> FailureReasons = new(StringComparer.Ordinal);
    public readonly Finding UnknownHookType = new();
    public readonly Finding BytesLeft = new();
    public readonly Counter BytesChecked = new(), BytesNotCheckable = new();
    public readonly Counter[] HookTypes = Enumerable.Range(0, 64).Select(_ => new Counter()).ToArray();
    public readonly Counter PlacementHooks = new();

    // PhysicsBSP.
    public readonly Counter BspGfxObjs = new(), InternalNodes = new(), Leaves = new();
    public readonly Counter PlanesReproduced = new(), PlanesNegated = new(), PlanesWithoutPolygon = new();
    public readonly Finding PlaneNotReproduced = new();
    public readonly UlpHistogram PlaneUlps = new();
    public readonly Finding OneChildNode = new();
    public readonly Counter SolidWithPolygons = new(), SolidEmpty = new(), OpenWithPolygons = new(), OpenEmpty = new();
    public readonly Finding SolidLeafEmpty = new(), SolidFlagOddValue = new();
    public readonly Counter LeafPolygonRefs = new();
    public readonly Finding LeafPolygonMissing = new(), PolygonVertexMissing = new();
    public readonly Counter SpheresChecked = new();
    public readonly Finding SphereTooSmall = new();
    public readonly Counter SpheresExactlyContaining = new(), SpheresWithinSlack = new();
    private long _maxExcessNanometres;

    // Setups.
    public readonly Counter SetupsChecked = new();
    public readonly Finding FlagSetPartsNone = new(), FlagClearPartsBsp = new();
    public readonly Finding PartMissing = new();
    public readonly Counter WithResting = new(), WithDefault = new(), WithOther = new(), WithNoPlacement = new();
    public readonly Finding NeitherRestingNorDefault = new();
    public readonly Counter WithDefaultScale = new();
    public readonly Finding NonUniformBspScale = new();
    public readonly Counter PartsTotal = new();
    public readonly Finding PartsWithoutPose = new();

    // Motion pose.
    public readonly Counter WithMotion = new(), MotionPosed = new();
    public readonly Finding PoseFellBack = new(), PoseDiffers = new();

    public long MaxExcessNanometres => Interlocked.Read(ref _maxExcessNanometres);

    public void ObserveExcess(long nanometres)
    {
        var seen = Interlocked.Read(ref _maxExcessNanometres);
        while (nanometres > seen)
        {
            var was = Interlocked.CompareExchange(ref _maxExcessNanometres, nanometres, seen);
            if (was == seen) return;
            seen = was;
        }
    }

    public void Failed(uint id, Exception e)
    {
        DecodeFailed.Add(id);
        var reason = DecodeFailureReason.Of(e);
        lock (FailureReasons)
        {
            if (!FailureReasons.TryGetValue(reason, out var counter)) FailureReasons[reason] = counter = new Counter();
            counter.Add();
        }
        if (reason == DecodeFailureReason.UnknownHookType) UnknownHookType.Add(id);
    }
}
