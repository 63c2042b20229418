namespace AcShadow.Analysis.Doctor;

/// <summary>
/// The reasons doctor.json groups objects that do not decode by (<c>reading.decode</c>'s <c>failuresByReason</c>),
/// each a short fixed key (<see cref="DecodeFailureReason.Of"/> picks one from the reader's message).
/// </summary>
public static class DoctorDiagnosticCodes
{
    /// <summary>An animation hook of a type acshadow has no layout for.</summary>
    public const string UnknownHookType = "unknown-hook-type";
    /// <summary>A BSP node tag that is no node type (physics, drawing or cell BSP).</summary>
    public const string UnknownBspNodeTag = "unknown-bsp-node-tag";
    /// <summary>A BSP deeper than the reader's depth limit.</summary>
    public const string BspTooDeep = "bsp-too-deep";
    /// <summary>A vertex array whose type is not the SW vertex type (1).</summary>
    public const string UnknownVertexType = "unknown-vertex-type";
    /// <summary>An object whose bytes carry another id than the one the directory files it under.</summary>
    public const string WrongIdInBytes = "wrong-id-in-bytes";
    /// <summary>A count that promises more elements than the object's bytes can hold.</summary>
    public const string CountLargerThanObject = "count-larger-than-object";
    /// <summary>An object whose bytes end before its layout does.</summary>
    public const string Truncated = "truncated";
    /// <summary>An object whose blocks in the dat cannot be followed (a chain that points outside the file, loops back or runs past its end, or a directory size larger than any object).</summary>
    public const string BlockChain = "block-chain";
    /// <summary>Any other decode failure.</summary>
    public const string Other = "other";
}
