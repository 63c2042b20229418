namespace AcShadow.Fixtures.Movement;

/// <summary>What one collision test says about the check position (retail TransitionState).</summary>
internal enum TransitionState
{
    Invalid = 0,
    OK = 1,
    Collided = 2,
    Adjusted = 3,
    Slid = 4,
}
