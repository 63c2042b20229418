namespace AcShadow.Core.Dat;

/// <summary>The bytes of a dat file (or of one object in it) do not follow the documented layout.</summary>
public sealed class DatFormatException(string message) : Exception(message);
