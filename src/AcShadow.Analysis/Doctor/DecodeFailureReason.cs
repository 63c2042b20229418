namespace AcShadow.Analysis.Doctor;

/// <summary>
/// Why an object could not be read, as a short fixed key (<see cref="DoctorDiagnosticCodes"/>: the report
/// groups failures by it and never carries the message itself, which may quote offsets and values of the user's dat).
/// </summary>
public static class DecodeFailureReason
{
    /// <summary>The key of an unknown animation hook type (<see cref="DoctorDiagnosticCodes.UnknownHookType"/>), which doctor also counts on its own.</summary>
    public const string UnknownHookType = DoctorDiagnosticCodes.UnknownHookType;

    public static string Of(Exception e)
    {
        var message = e.Message;
        return message switch
        {
            _ when Has("animation hook type") => DoctorDiagnosticCodes.UnknownHookType,
            _ when Has("node tag") => DoctorDiagnosticCodes.UnknownBspNodeTag,
            _ when Has("deeper than") => DoctorDiagnosticCodes.BspTooDeep,
            _ when Has("vertex type") => DoctorDiagnosticCodes.UnknownVertexType,
            _ when Has("carry id") => DoctorDiagnosticCodes.WrongIdInBytes,
            _ when Has("cannot fit") => DoctorDiagnosticCodes.CountLargerThanObject,
            _ when Has("more byte(s)") => DoctorDiagnosticCodes.Truncated,
            _ when Has("block chain") || Has("points at") || Has("loops back") || Has("runs past") || Has("gives it") => DoctorDiagnosticCodes.BlockChain,
            _ => DoctorDiagnosticCodes.Other,
        };

        bool Has(string text) => message.Contains(text, StringComparison.Ordinal);
    }
}
