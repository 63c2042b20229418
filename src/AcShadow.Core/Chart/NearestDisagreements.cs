using AcShadow.Fixtures.Collision;

namespace AcShadow.Core.Chart;

/// <summary>
/// A model's disagreements with the reference nearest the boundary: up to <c>perKind</c> false passes and
/// up to <c>perKind</c> false blocks, each ranked by <see cref="Disagreement.Nearness"/> then probe index,
/// all together in that order. Only these are kept, so a probe is measured in full only while it could
/// still be among them; the rest are ruled out by a distance search that stops at the current cut-off.
/// The result is the one ranking every disagreement would give.
/// </summary>
internal static class NearestDisagreements
{
    public static Disagreement[] Select(Probe[] probes, bool[] expected, bool[] answers, GapCache referenceGaps,
        IReadOnlyList<PreparedShape> referenceShapes, IReadOnlyList<PreparedShape> modelShapes, int perKind)
    {
        if (perKind == 0) return [];
        var passes = Kind(falsePass: true);
        var blocks = Kind(falsePass: false);
        return [.. passes.Concat(blocks).OrderBy(d => d.Nearness).ThenBy(d => d.ProbeIndex)];

        List<Disagreement> Kind(bool falsePass)
        {
            // Sorted nearest first; probes come in index order, so a newcomer must be strictly nearer than the last kept.
            var kept = new List<Disagreement>(perKind + 1);
            for (var i = 0; i < probes.Length; i++)
            {
                if (answers[i] == expected[i] || expected[i] != falsePass) continue;
                var p = probes[i];
                if (kept.Count == perKind)
                {
                    var limit = kept[^1].Nearness;
                    if (float.IsNaN(limit)) break;
                    var (toReference, referenceKnown) = BoundaryGap.Within(referenceShapes, p.Center, p.Radius, limit);
                    var (toModel, modelKnown) = BoundaryGap.Within(modelShapes, p.Center, p.Radius, limit);
                    var nearer = (referenceKnown && Before(MathF.Abs(toReference), limit)) || (modelKnown && Before(MathF.Abs(toModel), limit));
                    if (!nearer) continue;
                    kept.RemoveAt(kept.Count - 1);
                }
                var found = new Disagreement(i, p, falsePass, referenceGaps[i], BoundaryGap.Of(modelShapes, p.Center, p.Radius));
                var at = kept.FindIndex(k => Before(found.Nearness, k.Nearness));
                kept.Insert(at < 0 ? kept.Count : at, found);
            }
            return kept;
        }
    }

    /// <summary>Strictly nearer in the order OrderBy uses for floats (NaN first).</summary>
    private static bool Before(float a, float b) => a.CompareTo(b) < 0;
}
