using System.Numerics;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Fixtures.Scenes;

/// <summary>
/// A placed object as the compiled scene registers it: each posed part (a BSP tree, box or hull) its own entry
/// behind the part's reach (<see cref="PosedQuery.Reach"/>, moved into the landblock by the object's frame), the
/// object's other shapes (spheres, cylinders, parts without a bound) together behind the object's sphere (the mover's
/// radius stretched where a cylinder's box profile reaches past it, <see cref="BoundStretch"/>); every entry
/// keeps the object's sphere too, asked first and once (<see cref="PlacedQuery.Whole"/>). A mover
/// then meets only the parts it is near, where the client asks every part of every object registered in its cells
/// (CObjCell::find_obj_collisions → CPhysicsObj::FindObjCollisions → CPartArray). Each entry turns the sphere into
/// the object's frame and then the part's, the float operations the whole object makes, so the scene's answer (any
/// entry blocks) is the object-by-object answer. The all-retail scene keeps retail's one entry per object.
/// </summary>
internal static class PlacedParts
{
    public static IEnumerable<PlacedQuery> Of(int index, uint id, Vector3 position, Quaternion rotation, ISphereOverlap entityQuery, Vector3 boundCenter, float boundRadius)
    {
        var parts = PartsOf(entityQuery);
        var whole = new PlacedQuery(index, id, position, rotation, entityQuery, boundCenter, boundRadius, BoundStretch.Of(entityQuery));
        var frame = new object();
        var rest = new List<int>();
        for (var i = 0; i < parts.Count; i++)
        {
            if (parts[i] is PosedQuery { Reach: { IsBounded: true } reach } posed)
                // Its landblock bound is its reach moved out, so the entity-frame refusal would only repeat it.
                yield return new PlacedQuery(index, id, position, rotation, new PosedQuery(posed.Pose, posed.PartQuery, refuseByReach: false), reach.Center, reach.Radius, reach.Stretch)
                    { Shapes = [i], FrameKey = frame, Whole = whole };
            else rest.Add(i);
        }
        if (rest.Count == parts.Count)
            yield return whole;
        else if (rest.Count > 0)
        {
            var others = new AnyOverlap([.. rest.Select(i => parts[i])]);
            yield return new PlacedQuery(index, id, position, rotation, others, boundCenter, boundRadius, BoundStretch.Of(others)) { Shapes = rest, FrameKey = frame, Whole = whole };
        }
    }

    /// <summary>An object query's shapes, one query each in shape order, or the query itself when it is not made of shapes.</summary>
    private static IReadOnlyList<ISphereOverlap> PartsOf(ISphereOverlap query) => query switch
    {
        ObjectOverlapQuery o => o.Parts,
        AnyOverlap a => a.Shapes,
        _ => [query],
    };
}
