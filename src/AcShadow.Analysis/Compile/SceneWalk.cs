namespace AcShadow.Analysis.Compile;

/// <summary>Which walk a scene is asked along: the land-cell partition's (what the client asks), or every object and cell (the oracle).</summary>
internal enum SceneWalk
{
    Partitioned,
    Exhaustive,
}
