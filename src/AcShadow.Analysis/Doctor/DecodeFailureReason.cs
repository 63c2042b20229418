namespace AcShadow.Analysis.Doctor;

/// <summary>
/// Why an object could not be read, as a short fixed key (the report groups failures by it and never
/// carries the message itself, which may quote offsets and values of the user's dat).
/// </summary>
public static class DecodeFailureReason
{
    public const string UnknownHookType = "unknown-hook-type";

    public static string Of(Exception e)
    {
        var message = e.Message;
        return message switch
        {
            _ when Has("animation hook type") => UnknownHookType,
            _ when Has("node tag") => "unknown-bsp-node-tag",
            _ when Has("deeper than") => "bsp-too-deep",
            _ when Has("vertex type") => "unknown-vertex-type",
            _ when Has("carry id") => "wrong-id-in-bytes",
            _ when Has("cannot fit") => "count-larger-than-object",
            _ when Has("more byte(s)") => "truncated",
            _ when Has("block chain") || Has("points at") || Has("loops back") || Has("runs past") || Has("gives it") => "block-chain",
            _ => "other",
        };

        bool Has(string text) => message.Contains(text, StringComparison.Ordinal);
    }
}
