namespace AcShadow.Analysis.Doctor;

/// <param name="Jobs">Parallel workers for the passes over the dat and the export.</param>
/// <param name="ToolVersion">The acshadow version the report names.</param>
/// <param name="PeakMemoryBytes">The process's peak memory so far, measured by the caller (Core reads no process state); null: not measured.</param>
/// <param name="Export">Whether to run the export twice (the tool check); off, that check is "not checked".</param>
public sealed record DoctorOptions(int Jobs, string ToolVersion, Func<long>? PeakMemoryBytes = null, bool Export = true);
