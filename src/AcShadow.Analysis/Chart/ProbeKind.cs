namespace AcShadow.Analysis.Chart;

public enum ProbeKind
{
    /// <summary>A point of the 3-D grid around the object.</summary>
    Grid,
    /// <summary>A point on a line across the doorway at walking height.</summary>
    Doorway,
    /// <summary>A stability probe just either side of where a sphere starts touching a polygon's face, or across the face itself.</summary>
    Face,
    /// <summary>A stability probe just either side of where a sphere starts touching a polygon edge.</summary>
    Edge,
    /// <summary>A stability probe just either side of where a sphere starts touching a polygon vertex.</summary>
    Vertex,
    /// <summary>A stability probe just either side of a BSP splitting plane's reach (dist = ±(r − ε)) or of the plane itself.</summary>
    SplittingPlane,
}

/// <summary>The names probe kinds have in CSV files and the compiled scene.</summary>
public static class ProbeKinds
{
    public static readonly ProbeKind[] Stability = [ProbeKind.Face, ProbeKind.Edge, ProbeKind.Vertex, ProbeKind.SplittingPlane];

    public static string Name(ProbeKind kind) => kind switch
    {
        ProbeKind.Grid => "grid",
        ProbeKind.Doorway => "doorway",
        ProbeKind.Face => "face",
        ProbeKind.Edge => "edge",
        ProbeKind.Vertex => "vertex",
        _ => "plane",
    };

    public static bool IsStability(ProbeKind kind) => kind >= ProbeKind.Face;
}
