namespace AcShadow.Fixtures.Collision;

/// <summary>
/// The region a solid leaf stands for, written out as the path to it: for each internal ancestor, root
/// first, which child the path takes. The brute force tests a centre against every solid cell this way,
/// without descending the tree.
/// </summary>
internal sealed record SolidCell(int Leaf, IReadOnlyList<int> Ancestors, IReadOnlyList<bool> TakesPos);
