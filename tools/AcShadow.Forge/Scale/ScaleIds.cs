namespace AcShadow.Forge.Scale;

/// <summary>
/// Hands out the scale spec's ids in order: GfxObjs from 0x01000100, Setups from 0x02002000 skipping the
/// door catalog's Setup ids (the doors keep those).
/// </summary>
internal sealed class ScaleIds(IEnumerable<uint> reservedSetupIds)
{
    private readonly HashSet<uint> _takenSetups = [.. reservedSetupIds];
    private uint _nextGfxObj = 0x01000100u;
    private uint _nextSetup = 0x02002000u;

    public uint NewGfxObj() => _nextGfxObj++;

    public uint NewSetup()
    {
        while (_takenSetups.Contains(_nextSetup)) _nextSetup++;
        _takenSetups.Add(_nextSetup);
        return _nextSetup++;
    }
}
