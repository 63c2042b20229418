using AcShadow.Core.Dat;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Dat;

/// <summary>A bounded cache (what batch uses) drops old objects but never changes what a read returns.</summary>
public class DatDatabaseCacheTests
{
    [Fact]
    public void A_bounded_cache_rereads_evicted_objects_equal_to_an_unbounded_one()
    {
        using var unbounded = SampleDat.OpenPortal();
        var bounded = new DatDatabase(unbounded.Archive, cacheCapacity: 2);
        var setups = unbounded.ListIds(DatObjectKind.Setup);
        Assert.True(setups.Count > 2);
        for (var pass = 0; pass < 2; pass++)
            foreach (var id in setups)
            {
                var first = bounded.ReadSetup(id)!;
                Assert.Equal(id, first.Id);
                Assert.Equal(unbounded.ReadSetup(id)!.Parts, first.Parts);
            }
        // With room for two, the third read evicts the first: a fresh decode, not the cached instance.
        var a = bounded.ReadSetup(setups[0]);
        bounded.ReadSetup(setups[1]);
        bounded.ReadSetup(setups[2]);
        Assert.NotSame(a, bounded.ReadSetup(setups[0]));
        // Unbounded keeps every object.
        Assert.Same(unbounded.ReadSetup(setups[0]), unbounded.ReadSetup(setups[0]));
    }

    [Fact]
    public void A_cache_capacity_below_one_is_refused()
    {
        using var dat = SampleDat.OpenPortal();
        Assert.Throws<ArgumentOutOfRangeException>(() => new DatDatabase(dat.Archive, cacheCapacity: 0));
    }
}
