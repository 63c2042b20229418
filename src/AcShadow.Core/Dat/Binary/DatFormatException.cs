namespace AcShadow.Core.Dat.Binary;

/// <summary>
/// The bytes of a dat file (or of one object in it) do not follow the documented layout. When one object
/// is at fault, <see cref="ObjectId"/> names it and the message reads "corrupt dat: {object}: {what is wrong}".
/// </summary>
public sealed class DatFormatException : Exception
{
    public DatFormatException(string message) : base(message) { }

    private DatFormatException(string message, uint objectId, Exception? inner) : base(message, inner) => ObjectId = objectId;

    /// <summary>The id of the object whose bytes are damaged, when the failure is one object's.</summary>
    public uint? ObjectId { get; }

    /// <summary>
    /// Any failure met while reading object <paramref name="id"/> (described by <paramref name="subject"/>,
    /// e.g. "GfxObj 0x01000001 in client_portal.dat"), as the one exception the dat layer throws.
    /// </summary>
    public static DatFormatException CorruptObject(string subject, uint id, Exception cause)
    {
        var detail = cause is DatFormatException ? cause.Message : $"{cause.GetType().Name}: {cause.Message}";
        return new DatFormatException($"corrupt dat: {subject}: {detail}", id, cause);
    }
}
