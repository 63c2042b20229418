using System.Numerics;

namespace AcShadow.Analysis.Chart;

/// <summary>
/// Targeted probes through a doorway: for an object whose footprint is a slab (its thin horizontal side at
/// most half its wide side, the wide side at least 0.5 m — a door, a gate, a wall piece), lines across the
/// slab (along its thin axis) at walking height, one per lateral offset from the footprint's centre. Each
/// line runs from probe radius + 0.25 m before the slab to as far past it, in steps of
/// <see cref="ChartOptions.DoorwayStep"/>. Other objects get none.
/// </summary>
public static class DoorwayProbes
{
    public sealed record Opening(Vector3 Center, bool AcrossIsY, float HalfWidth, float HalfThickness);

    public static Opening? Find(Bounds reference)
    {
        if (reference.IsEmpty) return null;
        var size = reference.Size;
        var acrossIsY = size.Y <= size.X;
        var wide = acrossIsY ? size.X : size.Y;
        var thin = acrossIsY ? size.Y : size.X;
        if (wide < 0.5f || thin > 0.5f * wide) return null;
        return new Opening(reference.Center, acrossIsY, wide * 0.5f, thin * 0.5f);
    }

    public const int MaxStepsPerLine = 4096;

    public static IReadOnlyList<Probe> Build(Opening? opening, ChartOptions options)
    {
        if (opening is null) return [];
        var probes = new List<Probe>();
        var reach = opening.HalfThickness + options.ProbeRadius + 0.25f;
        // At most MaxStepsPerLine per line: a door scaled up hugely gets a coarser step, not millions of probes.
        var step = Math.Max(options.DoorwayStep, 2f * reach / MaxStepsPerLine);
        var steps = (int)MathF.Floor(2f * reach / step);
        var z = options.EffectiveWalkHeight;
        var offsets = options.DoorwayOffsets.Order().ToArray();
        for (var line = 0; line < offsets.Length; line++)
        {
            var lateral = offsets[line] * opening.HalfWidth;
            for (var s = 0; s <= steps; s++)
            {
                var along = -reach + s * step;
                var center = opening.AcrossIsY
                    ? new Vector3(opening.Center.X + lateral, opening.Center.Y + along, z)
                    : new Vector3(opening.Center.X + along, opening.Center.Y + lateral, z);
                probes.Add(new Probe(center, options.ProbeRadius, ProbeKind.Doorway, line, lateral));
            }
        }
        return probes;
    }
}
