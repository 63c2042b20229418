namespace AcShadow.Fixtures.Bsp;

/// <summary>
/// Bounds no real PhysicsBSP comes near, so a corrupt or hostile tree cannot exhaust the stack or memory
/// of whatever walks it. Retail trees are a few dozen levels deep at most (the sample's deepest is 10);
/// the dat reader refuses a tree deeper than this while decoding, and extraction and compilation drop
/// what lies below it (with a diagnostic) whatever the tree came from.
/// </summary>
internal static class BspLimits
{
    public const int MaxDepth = 256;
}
