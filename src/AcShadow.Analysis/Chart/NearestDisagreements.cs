using AcShadow.Fixtures.Collision;

namespace AcShadow.Analysis.Chart;

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
        IReadOnlyList<PreparedShape> modelShapes, int perKind)
    {
        if (perKind == 0) return [];
        var passes = Kind(falsePass: true);
        var blocks = Kind(falsePass: false);
        return [.. passes.Concat(blocks).OrderBy(d => d.Nearness).ThenBy(d => d.ProbeIndex)];

        List<Disagreement> Kind(bool falsePass)
        {
            // Sorted by (nearness, probe index). Probes are taken last to first: the stability probes, laid last
            // and hugging the boundary, set a tight cut-off early, and the grid behind them is then ruled out cheaply.
            var kept = new List<Disagreement>(perKind + 1);
            for (var i = probes.Length - 1; i >= 0; i--)
            {
                if (answers[i] == expected[i] || expected[i] != falsePass) continue;
                var p = probes[i];
                float? modelGap = null;
                if (kept.Count == perKind)
                {
                    var last = kept[^1];
                    var limit = last.Nearness;
                    var (toReference, referenceKnown) = referenceGaps.Within(i, limit);
                    // A known reference gap bounds the model's search too: only a nearer model surface changes the nearness.
                    var modelLimit = referenceKnown ? MathF.Min(limit, MathF.Abs(toReference)) : limit;
                    var (toModel, modelKnown) = BoundaryGap.Within(modelShapes, p.Center, p.Radius, modelLimit);
                    // Not known means wider than the limit; the nearness is the smaller of the known ones.
                    var nearness = float.PositiveInfinity;
                    if (referenceKnown) nearness = MathF.Min(nearness, MathF.Abs(toReference));
                    if (modelKnown) nearness = MathF.Min(nearness, MathF.Abs(toModel));
                    if (!Before(nearness, i, limit, last.ProbeIndex)) continue;
                    kept.RemoveAt(kept.Count - 1);
                    if (modelKnown) modelGap = toModel;
                }
                var found = new Disagreement(i, p, falsePass, referenceGaps[i], modelGap ?? BoundaryGap.Of(modelShapes, p.Center, p.Radius));
                // A plain loop, not a lambda: a closure over `found` would be allocated for every probe looked at.
                var at = 0;
                while (at < kept.Count && !Before(found.Nearness, found.ProbeIndex, kept[at].Nearness, kept[at].ProbeIndex)) at++;
                kept.Insert(at, found);
            }
            return kept;
        }
    }

    /// <summary>Ranked ahead in the order OrderBy(nearness).ThenBy(index) gives (a NaN nearness first).</summary>
    private static bool Before(float nearness, int index, float otherNearness, int otherIndex)
    {
        var c = nearness.CompareTo(otherNearness);
        return c < 0 || (c == 0 && index < otherIndex);
    }
}
