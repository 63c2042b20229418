namespace AcShadow.Fixtures.Collision;

/// <summary>Which BSP query answers for a part: the retail tree traversal or the brute-force oracle.</summary>
public enum BspEngine
{
    Reference,
    BruteForce,
}
