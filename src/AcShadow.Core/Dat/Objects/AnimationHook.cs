using System.Globalization;
using System.Numerics;
using AcShadow.Core.Dat.Binary;
using AcShadow.Fixtures.Geometry;

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

    /// <summary>The bytes after type and direction (<see cref="AnimationHookLayout.Fields"/> names them).</summary>
    public ReadOnlyMemory<byte> Payload => _payload;

    /// <summary>Reads one hook (no padding follows it); an unknown type is a <see cref="DatFormatException"/> naming <paramref name="where"/>.</summary>
    public static AnimationHook Read(DatBinaryReader r, string where)
    {
        var type = (AnimationHookType)r.ReadUInt32();
        var direction = r.ReadInt32();
        var payload = AnimationHookLayout.ReadPayload(r, type)
            ?? throw new DatFormatException($"{where}: animation hook type {(uint)type} (0x{(uint)type:X8}) is unknown, so its length and everything after it cannot be read");
        return new AnimationHook(type, direction, payload);
    }

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt32((uint)Type);
        w.WriteInt32(Direction);
        w.WriteBytes(_payload);
    }

    /// <summary>
    /// The payload's fields as "name=value", space-separated, in stored order (ids in hex, floats round-trip,
    /// invariant culture): what a report shows of a hook, and what tests compare with hand-worked values.
    /// </summary>
    public string FieldText()
    {
        var r = new DatBinaryReader(_payload);
        var parts = new List<string>();
        foreach (var field in AnimationHookLayout.Fields(Type))
            parts.Add($"{field.Name}={FieldValue(r, field.Kind)}");
        return string.Join(' ', parts);
    }

    private static string FieldValue(DatBinaryReader r, AnimationHookFieldKind kind) => kind switch
    {
        AnimationHookFieldKind.UInt32 => r.ReadUInt32().ToString(CultureInfo.InvariantCulture),
        AnimationHookFieldKind.DataId => $"0x{r.ReadUInt32():X8}",
        AnimationHookFieldKind.Bool32 => r.ReadUInt32() != 0 ? "true" : "false",
        AnimationHookFieldKind.Float => Number(r.ReadSingle()),
        AnimationHookFieldKind.UInt16 => r.ReadUInt16().ToString(CultureInfo.InvariantCulture),
        AnimationHookFieldKind.PackedGfxObjId => $"0x{r.ReadPackedDataId(AnimationHookField.GfxObjBase):X8}",
        AnimationHookFieldKind.Vector3 => Vector(r.ReadVector3()),
        AnimationHookFieldKind.Frame => FrameText(r.ReadFrame()),
        _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, null),
    };

    private static string Number(float f) => f.ToString("R", CultureInfo.InvariantCulture);
    private static string Vector(Vector3 v) => $"[{Number(v.X)}, {Number(v.Y)}, {Number(v.Z)}]";
    private static string FrameText(Frame f) =>
        $"{Vector(f.Position)}@[{Number(f.Rotation.W)}, {Number(f.Rotation.X)}, {Number(f.Rotation.Y)}, {Number(f.Rotation.Z)}]";

    public bool Equals(AnimationHook? other) =>
        other is not null && Type == other.Type && Direction == other.Direction && _payload.AsSpan().SequenceEqual(other._payload);

    public override int GetHashCode() => HashCode.Combine(Type, Direction, _payload.Length);
}
