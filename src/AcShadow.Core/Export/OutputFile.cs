namespace AcShadow.Core.Export;

public enum OutputKind
{
    Shadow,
    Bsp,
    Scene,
    AcdreamGfxObj,
}

/// <summary>One file of an export, in memory: where it goes (relative, '/' separated), what it is, its bytes.</summary>
public sealed record OutputFile(string RelativePath, OutputKind Kind, uint Id, byte[] Content, int ShapeCount, int PolygonCount);
