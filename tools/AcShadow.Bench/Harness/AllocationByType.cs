using System.Diagnostics.Tracing;

namespace AcShadow.Bench.Harness;

/// <summary>
/// The runtime's allocation samples (GCAllocationTick: one about every 100 KB allocated, naming the type
/// that crossed it), summed by type while it listens: where a run's bytes go, to the nearest sample.
/// </summary>
public sealed class AllocationByType : EventListener
{
    private const string RuntimeSource = "Microsoft-Windows-DotNETRuntime";
    private const EventKeywords GcKeyword = (EventKeywords)0x1;
    private readonly Dictionary<string, (long Small, long Large)> _bytes = new(StringComparer.Ordinal);

    protected override void OnEventSourceCreated(EventSource source)
    {
        if (source.Name == RuntimeSource) EnableEvents(source, EventLevel.Verbose, GcKeyword);
    }

    protected override void OnEventWritten(EventWrittenEventArgs e)
    {
        if (e.EventName is not { } name || !name.StartsWith("GCAllocationTick", StringComparison.Ordinal) || e.Payload is null || e.PayloadNames is null) return;
        var type = e.Payload[e.PayloadNames.IndexOf("TypeName")] as string ?? "?";
        var large = Convert.ToInt32(e.Payload[e.PayloadNames.IndexOf("AllocationKind")], System.Globalization.CultureInfo.InvariantCulture) == 1;
        var amount = Convert.ToInt64(e.Payload[e.PayloadNames.IndexOf("AllocationAmount64")], System.Globalization.CultureInfo.InvariantCulture);
        lock (_bytes)
        {
            _bytes.TryGetValue(type, out var sum);
            _bytes[type] = large ? (sum.Small, sum.Large + amount) : (sum.Small + amount, sum.Large);
        }
    }

    /// <summary>The types with the most bytes, most first: small-object and large-object heap bytes apart.</summary>
    public IReadOnlyList<(string Type, long Small, long Large)> Top(int count)
    {
        lock (_bytes)
            return _bytes.Select(p => (p.Key, p.Value.Small, p.Value.Large))
                .OrderByDescending(t => t.Small + t.Large).ThenBy(t => t.Key, StringComparer.Ordinal).Take(count).ToArray();
    }
}
