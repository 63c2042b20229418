using System.Numerics;
using AcShadow.Core.Dat.Binary;

namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// The SW vertex array a GfxObj and a CellStruct both carry: type 1, a uint count, then per vertex its id,
/// UV count, origin, normal and UVs. Collision needs only the origins; normals and UVs are stepped over.
/// </summary>
internal static class VertexArrayLayout
{
    /// <summary>
    /// The origins by id: a <see cref="VertexTable"/> when the stored ids count up from 0 (the forge's arrays, and
    /// the cheap case), else a hash table from the first id that does not (in stored order; a repeated id keeps its
    /// first place and its last origin).
    /// </summary>
    internal static IReadOnlyDictionary<ushort, Vector3> Read(DatBinaryReader r)
    {
        var vertexType = r.ReadInt32();
        if (vertexType != 1) throw new DatFormatException($"vertex type {vertexType} is not the SW vertex type (1)");
        var count = r.ReadCount(r.ReadUInt32(), 28, "vertex");
        var origins = new Vector3[count];
        Dictionary<ushort, Vector3>? byId = null;
        for (var i = 0; i < count; i++)
        {
            var key = r.ReadUInt16();
            var uvCount = r.ReadUInt16();
            var origin = r.ReadVector3();
            r.Skip(12 + uvCount * 8); // normal and UVs: drawing only
            if (byId is null && key == i)
            {
                origins[i] = origin;
                continue;
            }
            if (byId is null)
            {
                byId = new Dictionary<ushort, Vector3>(count);
                for (var k = 0; k < i; k++) byId[(ushort)k] = origins[k];
            }
            byId[key] = origin;
        }
        return byId is null ? new VertexTable(origins) : byId;
    }

    /// <summary>Origins in id order, each with no UVs and a zero normal: what collision reads, nothing more.</summary>
    internal static void Write(DatBinaryWriter w, IReadOnlyDictionary<ushort, Vector3> vertices)
    {
        w.WriteInt32(1);
        w.WriteUInt32((uint)vertices.Count);
        foreach (var (key, origin) in vertices.OrderBy(kv => kv.Key))
        {
            w.WriteUInt16(key);
            w.WriteUInt16(0);
            w.WriteVector3(origin);
            w.WriteVector3(Vector3.Zero);
        }
    }
}
