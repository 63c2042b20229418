using AcShadow.Fixtures.Collision;

namespace AcShadow.Fixtures.Movement;

/// <summary>The transition's constants (docs: movement.md §1.1), in float32 as the client stores them.</summary>
internal static class MovementConstants
{
    public const float Epsilon = PhysicsEpsilon.Value;

    /// <summary>A step whose adjusted offset is shorter than this (squared) ends the transition.</summary>
    public const float EpsilonSquared = Epsilon * Epsilon;

    /// <summary>floor_z: cos(3437.746770784939) in radians, the steepest walkable normal.</summary>
    public const float FloorZ = 0.66417414f;

    /// <summary>z_for_landing (cos 85°): what an airborne mover may land on.</summary>
    public const float LandingZ = 0.0871557f;

    /// <summary>Step-down and step-up height when not on walkable ground (CTransition::transitional_insert, step_up).</summary>
    public const float OffWalkableStep = 0.039999999f;

    /// <summary>PhysicsGlobals gravity, m/s².</summary>
    public const float Gravity = -9.8f;

    /// <summary>The interp floor a polygon step-down may lower walk_interp to (CPolygon::adjust_sphere_to_plane).</summary>
    public const float PolygonInterpFloor = -0.5f;

    /// <summary>The interp floor for terrain, spheres and cylinders.</summary>
    public const float PrimitiveInterpFloor = -0.1f;

    /// <summary>retail's dummy_sphere for a Setup without spheres.</summary>
    public static readonly Geometry.Sphere DummySphere = new(new System.Numerics.Vector3(0f, 0f, 0.1f), 0.1f);
}
