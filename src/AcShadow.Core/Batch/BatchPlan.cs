using AcShadow.Core.Export;
using AcShadow.Core.Scenes;

namespace AcShadow.Core.Batch;

/// <summary>A Setup a batch exports and which parts of the selection asked for it.</summary>
public sealed record PlannedSetup(uint Id, SelectionSource From);

/// <summary>
/// What a batch will do: the Setups to export (sorted by id, each once), the scene to describe (if a
/// landblock was selected), and the ids skipped before any work because the dat lacks them.
/// </summary>
public sealed record BatchPlan(IReadOnlyList<PlannedSetup> Setups, LandblockScene? Scene, IReadOnlyList<SkippedItem> Skipped);
