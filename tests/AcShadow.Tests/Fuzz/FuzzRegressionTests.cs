using AcShadow.Fuzz;

namespace AcShadow.Tests.Fuzz;

/// <summary>
/// Every failure a campaign found, saved minimised under Fuzz/Inputs (one folder per finding: the two dats
/// and case.txt with the mutation and the failure's signature), run again through `dump` and `batch`:
/// each must now pass the same checks the campaign applies.
/// </summary>
public class FuzzRegressionTests
{
    private static string InputsFolder => Path.Combine(AppContext.BaseDirectory, "Fuzz", "Inputs");

    public static TheoryData<string> SavedInputs()
    {
        var data = new TheoryData<string>();
        foreach (var folder in Directory.GetDirectories(InputsFolder).Order(StringComparer.Ordinal)) data.Add(Path.GetFileName(folder));
        return data;
    }

    [Fact]
    public void Saved_inputs_are_present_and_small()
    {
        var folders = Directory.GetDirectories(InputsFolder);
        Assert.NotEmpty(folders);
        foreach (var folder in folders)
        foreach (var file in Directory.GetFiles(folder))
            Assert.True(new FileInfo(file).Length <= 64 * 1024, $"{file} is {new FileInfo(file).Length} bytes");
    }

    [Theory]
    [MemberData(nameof(SavedInputs))]
    public void A_saved_failing_input_now_passes(string name)
    {
        var input = ReproducerStore.Load(Path.Combine(InputsFolder, name));
        using var scratch = new Support.TempDir();
        var outcome = new CaseRunner(scratch.Path, TimeSpan.FromSeconds(30), 128L << 20).Run(input, name);
        Assert.True(outcome.Failure is null, $"{input.Description}\n{outcome.Failure?.Signature}\n{outcome.Failure?.Detail}");
    }
}
