namespace AcShadow.Fixtures.Movement;

/// <summary>SPHEREPATH insert_type: a moving step, or a placement confirmation (sphere_intersects_solid only).</summary>
internal enum InsertType
{
    Transition,
    Placement,
}
