namespace AcShadow.Core.Export;

public enum OutputKind
{
    Shadow,
    Bsp,
    Scene,
    AcdreamGfxObj,
    Cell,
    AcdreamCell,
}

/// <summary>
/// One file of an export, in memory: where it goes (relative, '/' separated), what it is, its bytes. A file
/// handed to a streaming batch's writer may lend its bytes (<see cref="Json.Utf8JsonText.Lend"/>): they are
/// valid only during that call, so a writer that keeps files keeps a copy.
/// </summary>
public sealed record OutputFile(string RelativePath, OutputKind Kind, uint Id, ReadOnlyMemory<byte> Content, int ShapeCount, int PolygonCount);
