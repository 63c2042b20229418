namespace AcShadow.Analysis.Doctor;

/// <summary>What a doctor check found on the user's dat.</summary>
public enum DoctorVerdict
{
    /// <summary>The claim held for every object it applies to.</summary>
    Holds,

    /// <summary>At least one object breaks the claim; the check names the first ids.</summary>
    Differs,

    /// <summary>The dat holds nothing the claim applies to (e.g. no cell dat, no physics BSP).</summary>
    NotApplicable,

    /// <summary>This build of acshadow cannot check the claim yet (it does not read what the claim needs).</summary>
    NotChecked,
}

public static class DoctorVerdicts
{
    /// <summary>The word the summary and the JSON use.</summary>
    public static string Text(this DoctorVerdict verdict) => verdict switch
    {
        DoctorVerdict.Holds => "holds",
        DoctorVerdict.Differs => "differs",
        DoctorVerdict.NotApplicable => "not applicable",
        DoctorVerdict.NotChecked => "not checked",
        _ => throw new ArgumentOutOfRangeException(nameof(verdict)),
    };

    /// <summary>Differs when anything broke the claim, not applicable when nothing was checked, else holds.</summary>
    public static DoctorVerdict Of(long checkedCount, long breaking) =>
        breaking > 0 ? DoctorVerdict.Differs : checkedCount == 0 ? DoctorVerdict.NotApplicable : DoctorVerdict.Holds;
}
