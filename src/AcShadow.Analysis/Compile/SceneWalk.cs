namespace AcShadow.Analysis.Compile;

/// <summary>
/// Which walk a scene is asked along: the land-cell partition's (what the client asks), or every object and cell (the
/// oracle); or, counted only, the narrow phase alone (<see cref="NarrowFloor"/>).
/// </summary>
internal enum SceneWalk
{
    Partitioned,
    Exhaustive,

    /// <summary>
    /// Not a walk but the least any broad phase in front of these models can leave (<see cref="SceneCost"/>): nothing
    /// counted for finding the entries; at a clear position every entry whose own bound the sphere is within asked (its
    /// turn and its model's count, which none may skip: it could block), at a blocked one only its cheapest blocker.
    /// </summary>
    NarrowFloor,
}
