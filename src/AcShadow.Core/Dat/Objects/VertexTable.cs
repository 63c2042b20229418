using System.Diagnostics.CodeAnalysis;
using System.Numerics;

namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// A vertex array's origins by id, when the stored ids count up from 0 (vertex i has id i): the origins alone,
/// 12 bytes a vertex, an id looked up by indexing. A hash table of the same vertices took 28 bytes a vertex, and a
/// batch decodes millions of them. Enumerates in id order, as the hash table did for such ids.
/// </summary>
internal sealed class VertexTable(Vector3[] origins) : IReadOnlyDictionary<ushort, Vector3>
{
    public int Count => origins.Length;

    public Vector3 this[ushort key] => TryGetValue(key, out var origin) ? origin : throw new KeyNotFoundException($"no vertex {key}");

    public IEnumerable<ushort> Keys => Enumerable.Range(0, origins.Length).Select(i => (ushort)i);

    public IEnumerable<Vector3> Values => origins;

    public bool ContainsKey(ushort key) => key < origins.Length;

    public bool TryGetValue(ushort key, [MaybeNullWhen(false)] out Vector3 value)
    {
        if (key < origins.Length)
        {
            value = origins[key];
            return true;
        }
        value = default;
        return false;
    }

    public IEnumerator<KeyValuePair<ushort, Vector3>> GetEnumerator()
    {
        for (var i = 0; i < origins.Length; i++) yield return new((ushort)i, origins[i]);
    }

    System.Collections.IEnumerator System.Collections.IEnumerable.GetEnumerator() => GetEnumerator();
}
