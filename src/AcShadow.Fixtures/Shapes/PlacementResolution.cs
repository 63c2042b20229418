namespace AcShadow.Fixtures.Shapes;

/// <summary>The placement a part array asked for and the one it got ("None" when it got none).</summary>
public sealed record PlacementResolution(string Requested, string Used)
{
    public const string NoneName = "None";
}
