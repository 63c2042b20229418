using System.Numerics;
using AcShadow.Fixtures.Movement;

namespace AcShadow.Core.Movement;

/// <summary>One case to run: its id, the object state, the heading from the gate's normal (degrees), the walk and the gate plane.</summary>
public sealed record MovementCasePlan(string Id, string State, float Heading, Walk Walk, Plane Gate);
