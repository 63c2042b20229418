using System.Numerics;
using AcShadow.Core.Dat.Binary;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// A Setup (0x02xxxxxx): parts, placement frames, CylSpheres, Spheres, radius and height.
/// Holding locations, connection points and lights are skipped on read (no collision meaning) and
/// written empty; placement frames' animation hooks are kept as bytes (<see cref="AnimationHook"/>) and written back.
/// The five ids at the end (default animation, script, motion table, sound table, script table) are kept:
/// the first and third decide how a live object is posed.
/// </summary>
public sealed record Setup(
    uint Id,
    SetupFlags Flags,
    IReadOnlyList<uint> Parts,
    IReadOnlyList<uint> ParentIndex,
    IReadOnlyList<Vector3> DefaultScale,
    IReadOnlyList<PlacementFrame> PlacementFrames,
    IReadOnlyList<CylSphere> CylSpheres,
    IReadOnlyList<Sphere> Spheres,
    float Height,
    float Radius,
    float StepUpHeight,
    float StepDownHeight,
    Sphere SortingSphere,
    Sphere SelectionSphere)
{
    private const int LocationTypeBytes = 4 + 28;
    private const int LightInfoBytes = 28 + 4 + 12;

    /// <summary>The Animation a new object plays when no motion table state replaces it (0: none).</summary>
    public uint DefaultAnimation { get; init; }
    public uint DefaultScript { get; init; }
    /// <summary>The MotionTable a new object gets before any weenie's own (0: none).</summary>
    public uint DefaultMotionTable { get; init; }
    public uint DefaultSoundTable { get; init; }
    public uint DefaultScriptTable { get; init; }

    public PlacementFrame? FindPlacement(uint key) => PlacementFrames.FirstOrDefault(p => p.Placement == key);

    public static Setup Read(DatBinaryReader r)
    {
        var id = r.ReadUInt32();
        var flags = (SetupFlags)r.ReadUInt32();
        var numParts = r.ReadCount(r.ReadUInt32(), 4, "part");
        var parts = new uint[numParts];
        for (var i = 0; i < numParts; i++) parts[i] = r.ReadUInt32();
        var parents = new uint[flags.HasFlag(SetupFlags.HasParent) ? numParts : 0];
        for (var i = 0; i < parents.Length; i++) parents[i] = r.ReadUInt32();
        var scales = new Vector3[flags.HasFlag(SetupFlags.HasDefaultScale) ? numParts : 0];
        for (var i = 0; i < scales.Length; i++) scales[i] = r.ReadVector3();

        SkipKeyed(r, LocationTypeBytes, "holding location");
        SkipKeyed(r, LocationTypeBytes, "connection point");

        var placementCount = r.ReadCount((uint)r.ReadInt32(), 8, "placement");
        var placements = new PlacementFrame[placementCount];
        for (var p = 0; p < placementCount; p++)
        {
            // A placement frame is an AnimationFrame of the Setup's part count, read by the same reader.
            var key = r.ReadUInt32();
            var frame = AnimationFrame.Read(r, numParts, $"placement {Placement.Name(key)}");
            placements[p] = new PlacementFrame(key, frame.Frames) { Hooks = frame.Hooks };
        }

        var cylCount = r.ReadCount(r.ReadUInt32(), 20, "CylSphere");
        var cyls = new CylSphere[cylCount];
        for (var i = 0; i < cylCount; i++) cyls[i] = CylSphere.Read(r);
        var sphereCount = r.ReadCount(r.ReadUInt32(), 16, "Sphere");
        var spheres = new Sphere[sphereCount];
        for (var i = 0; i < sphereCount; i++) spheres[i] = Sphere.Read(r);

        var height = r.ReadSingle();
        var radius = r.ReadSingle();
        var stepUp = r.ReadSingle();
        var stepDown = r.ReadSingle();
        var sorting = Sphere.Read(r);
        var selection = Sphere.Read(r);
        SkipKeyed(r, LightInfoBytes, "light");
        return new Setup(id, flags, parts, parents, scales, placements, cyls, spheres, height, radius, stepUp, stepDown, sorting, selection)
        {
            DefaultAnimation = r.ReadUInt32(),
            DefaultScript = r.ReadUInt32(),
            DefaultMotionTable = r.ReadUInt32(),
            DefaultSoundTable = r.ReadUInt32(),
            DefaultScriptTable = r.ReadUInt32(),
        };
    }

    private static void SkipKeyed(DatBinaryReader r, int valueBytes, string what)
    {
        var count = r.ReadCount((uint)r.ReadInt32(), 4 + valueBytes, what);
        r.Skip(count * (4 + valueBytes));
    }

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt32(Id);
        var flags = Flags;
        if (DefaultScale.Count > 0) flags |= SetupFlags.HasDefaultScale; else flags &= ~SetupFlags.HasDefaultScale;
        if (ParentIndex.Count > 0) flags |= SetupFlags.HasParent; else flags &= ~SetupFlags.HasParent;
        w.WriteUInt32((uint)flags);
        w.WriteUInt32((uint)Parts.Count);
        foreach (var p in Parts) w.WriteUInt32(p);
        if (ParentIndex.Count > 0)
        {
            if (ParentIndex.Count != Parts.Count) throw new InvalidOperationException($"Setup 0x{Id:X8}: parent index needs one entry per part");
            foreach (var p in ParentIndex) w.WriteUInt32(p);
        }
        if (DefaultScale.Count > 0)
        {
            if (DefaultScale.Count != Parts.Count) throw new InvalidOperationException($"Setup 0x{Id:X8}: the dat stores DefaultScale with exactly one entry per part ({Parts.Count}), not {DefaultScale.Count}");
            foreach (var s in DefaultScale) w.WriteVector3(s);
        }
        w.WriteInt32(0);
        w.WriteInt32(0);
        w.WriteInt32(PlacementFrames.Count);
        foreach (var placement in PlacementFrames)
        {
            if (placement.Frames.Count != Parts.Count)
                throw new InvalidOperationException($"Setup 0x{Id:X8}: placement {placement.Name} has {placement.Frames.Count} frame(s); the dat stores exactly one per part ({Parts.Count})");
            w.WriteUInt32(placement.Placement);
            foreach (var f in placement.Frames) w.WriteFrame(f);
            w.WriteUInt32((uint)placement.Hooks.Count);
            foreach (var hook in placement.Hooks) hook.Write(w);
        }
        w.WriteUInt32((uint)CylSpheres.Count);
        foreach (var c in CylSpheres) c.Write(w);
        w.WriteUInt32((uint)Spheres.Count);
        foreach (var s in Spheres) s.Write(w);
        w.WriteSingle(Height);
        w.WriteSingle(Radius);
        w.WriteSingle(StepUpHeight);
        w.WriteSingle(StepDownHeight);
        SortingSphere.Write(w);
        SelectionSphere.Write(w);
        w.WriteInt32(0);
        w.WriteUInt32(DefaultAnimation);
        w.WriteUInt32(DefaultScript);
        w.WriteUInt32(DefaultMotionTable);
        w.WriteUInt32(DefaultSoundTable);
        w.WriteUInt32(DefaultScriptTable);
    }
}
