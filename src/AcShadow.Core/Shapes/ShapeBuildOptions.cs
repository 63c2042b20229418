using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Shapes;

/// <summary>How to build: the policy, and the entity scale (the object's own scale, 1 for most).</summary>
public sealed record ShapeBuildOptions(ShapePolicy Policy, float EntityScale = 1f);
