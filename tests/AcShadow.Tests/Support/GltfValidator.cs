using System.Diagnostics;

namespace AcShadow.Tests.Support;

/// <summary>
/// The Khronos glTF Validator (npm <c>gltf-validator</c>, installed under tools/view-check by
/// <c>npm ci</c>, which .ci/run does) run through node on the glbs a test wrote: zero errors and zero
/// warnings. Where node or the package is missing, <see cref="Missing"/> says so: the tests that exist only
/// to validate are then skipped with that reason (<see cref="ValidatorFactAttribute"/>), and the view tests
/// that also check other things validate only when it is there.
/// </summary>
internal static class GltfValidator
{
    private static readonly string Folder = System.IO.Path.Combine(RepositoryRoot.Path, "tools", "view-check");

    /// <summary>Why the validator cannot run here, or null when it can.</summary>
    public static string? Missing { get; } = FindMissing();

    private static string? FindMissing()
    {
        if (!Directory.Exists(System.IO.Path.Combine(Folder, "node_modules", "gltf-validator")))
            return "the Khronos glTF Validator is not installed: run `npm ci` in tools/view-check (.ci/run does; needs node and npm)";
        try
        {
            using var node = Process.Start(new ProcessStartInfo("node", ["--version"]) { RedirectStandardOutput = true })!;
            node.StandardOutput.ReadToEnd();
            node.WaitForExit();
            return node.ExitCode == 0 ? null : "node does not run: install Node.js 18 or later";
        }
        catch (System.ComponentModel.Win32Exception)
        {
            return "node is not installed: install Node.js 18 or later (Debian: apt-get install nodejs npm)";
        }
    }

    /// <summary>Validates every .glb under <paramref name="paths"/>; fails with the validator's report unless each has no error and no warning. Nothing when the validator is missing.</summary>
    public static void AssertValid(params string[] paths)
    {
        if (Missing is not null) return;
        var (exit, output) = Run(paths);
        Assert.True(exit == 0, $"the glTF Validator found problems:\n{output}");
        Assert.Contains("validated ", output);
    }

    /// <summary>Runs validate.mjs; its exit code and output.</summary>
    public static (int Exit, string Output) Run(params string[] paths)
    {
        var start = new ProcessStartInfo("node", [System.IO.Path.Combine(Folder, "validate.mjs"), .. paths])
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
        };
        using var process = Process.Start(start)!;
        var output = process.StandardOutput.ReadToEndAsync();
        var error = process.StandardError.ReadToEnd();
        process.WaitForExit();
        return (process.ExitCode, output.Result + error);
    }
}

/// <summary>A fact that needs the glTF Validator: skipped, with the reason, where it is not installed.</summary>
internal sealed class ValidatorFactAttribute : FactAttribute
{
    public ValidatorFactAttribute()
    {
        if (GltfValidator.Missing is { } reason) Skip = reason;
    }
}
