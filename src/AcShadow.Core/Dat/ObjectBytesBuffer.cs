namespace AcShadow.Core.Dat;

/// <summary>
/// Each thread's buffer for an object's raw bytes, reused from object to object by whatever reads them
/// only to decode or hash them (decoders copy what they keep). A batch reads hundreds of MB of objects;
/// the large ones, each a new array, were large-object-heap garbage that only gen2 collections free.
/// Taken while in use, so a nested read gets a buffer of its own.
/// </summary>
public static class ObjectBytesBuffer
{
    /// <summary>A buffer grown past this by a huge object is let go rather than kept by the thread.</summary>
    private const int MaxKeptBytes = 4 << 20;

    [ThreadStatic] private static byte[]? t_buffer;

    public static byte[] Take()
    {
        var buffer = t_buffer ?? [];
        t_buffer = null;
        return buffer;
    }

    /// <summary>Gives back the buffer the read ended with (it may have been replaced by a larger one).</summary>
    public static void Return(byte[] buffer)
    {
        if (buffer.Length <= MaxKeptBytes) t_buffer = buffer;
    }
}
