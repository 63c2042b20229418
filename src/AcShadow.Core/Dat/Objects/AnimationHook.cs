namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// One animation hook of an animation frame (a Setup's placement frames carry them). acshadow gives hooks no
/// meaning: it keeps the type, the direction and the payload bytes, so the fields after them can be read and
/// the hook written back unchanged. The payload always fits its type's layout (<see cref="AnimationHookLayout"/>).
/// </summary>
public sealed record AnimationHook
{
    private readonly byte[] _payload;

    public AnimationHook(AnimationHookType type, int direction, ReadOnlySpan<byte> payload)
    {
        if (!AnimationHookLayout.IsKnown(type))
            throw new ArgumentException($"animation hook type {(uint)type} (0x{(uint)type:X8}) has no known layout", nameof(type));
        if (!AnimationHookLayout.Fits(type, payload))
            throw new ArgumentException($"{payload.Length} byte(s) are not one {type} hook payload", nameof(payload));
        Type = type;
        Direction = direction;
        _payload = payload.ToArray();
    }

    public AnimationHookType Type { get; }

    /// <summary>When the hook fires: 1 forward, -1 backward, 0 both ways (stored as an int).</summary>
    public int Direction { get; }

    /// <summary>The bytes after type and direction, without the alignment padding.</summary>
    public ReadOnlyMemory<byte> Payload => _payload;

    /// <summary>Reads one hook, padding included; an unknown type is a <see cref="DatFormatException"/> naming <paramref name="where"/>.</summary>
    public static AnimationHook Read(DatBinaryReader r, string where)
    {
        var type = (AnimationHookType)r.ReadUInt32();
        var direction = r.ReadInt32();
        var payload = AnimationHookLayout.ReadPayload(r, type)
            ?? throw new DatFormatException($"{where}: animation hook type {(uint)type} (0x{(uint)type:X8}) is unknown, so its length and everything after it cannot be read");
        r.Align(AnimationHookLayout.Alignment);
        return new AnimationHook(type, direction, payload);
    }

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt32((uint)Type);
        w.WriteInt32(Direction);
        w.WriteBytes(_payload);
        w.Align(AnimationHookLayout.Alignment);
    }

    public bool Equals(AnimationHook? other) =>
        other is not null && Type == other.Type && Direction == other.Direction && _payload.AsSpan().SequenceEqual(other._payload);

    public override int GetHashCode() => HashCode.Combine(Type, Direction, _payload.Length);
}
