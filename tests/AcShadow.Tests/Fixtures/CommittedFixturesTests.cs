using System.Text.Json;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Fixtures;

/// <summary>
/// The committed fixtures/ must be exactly what the current code makes from the built-in sample. When
/// this fails, the message is verify's report: the files and JSON paths that changed. If the change is
/// intended, run scripts/regenerate-fixtures.sh and commit the fixtures with the change.
/// </summary>
public class CommittedFixturesTests
{
    internal static string RepositoryFixtures() => Path.Combine(RepositoryRoot.Path, "fixtures");

    [Fact]
    public void Committed_fixtures_match_a_fresh_regeneration()
    {
        var run = CliRun.Of("verify", "--fixtures", RepositoryFixtures());
        Assert.True(run.ExitCode == 0,
            $"fixtures/ drifted from what the code makes (exit {run.ExitCode}). If intended, run scripts/regenerate-fixtures.sh.\n{run.Out}\n{run.Error}");
    }

    [Fact]
    public void Fixtures_cover_the_door_catalog_every_setup_and_the_sample_scene()
    {
        using var index = JsonDocument.Parse(File.ReadAllText(Path.Combine(RepositoryFixtures(), "index.json")));
        var selection = index.RootElement.GetProperty("inputs").GetProperty("selection");
        Assert.True(selection.GetProperty("doors").GetBoolean());
        Assert.True(selection.GetProperty("all").GetBoolean());
        Assert.Equal("0xA9B4FFFE", selection.GetProperty("landblock").GetString());
        var paths = index.RootElement.GetProperty("files").EnumerateArray().Select(f => f.GetProperty("path").GetString()).ToArray();
        Assert.Contains("scene.json", paths);
        Assert.Equal(Batch.BatchCommandTests.SampleSetups.Length, paths.Count(p => p!.StartsWith("setups/")));
        Assert.Equal(["movement/0x020019FF.movement.json"], paths.Where(p => p!.StartsWith("movement/")));
    }

    [Fact]
    public void Tampering_with_one_fixture_fails_verify_naming_the_file_and_the_field()
    {
        using var copy = new TempDir();
        var source = RepositoryFixtures();
        foreach (var file in Directory.GetFiles(source, "*", SearchOption.AllDirectories))
        {
            var target = Path.Combine(copy.Path, Path.GetRelativePath(source, file));
            Directory.CreateDirectory(Path.GetDirectoryName(target)!);
            File.Copy(file, target);
        }
        const string door = "setups/0x020019FF.shadow.json";
        var path = Path.Combine(copy.Path, door);
        var text = File.ReadAllText(path);
        var radius = JsonDocument.Parse(text).RootElement.GetProperty("shapes")[1].GetProperty("radius").GetRawText();
        var at = text.IndexOf("\"radius\": " + radius, text.IndexOf("\"sourceIndex\": 1", StringComparison.Ordinal), StringComparison.Ordinal);
        File.WriteAllText(path, text[..at] + "\"radius\": 9.5" + text[(at + ("\"radius\": " + radius).Length)..]);

        var run = CliRun.Of("verify", "--fixtures", copy.Path);
        Assert.Equal(5, run.ExitCode);
        Assert.Contains($"changed {door}", run.Out);
        Assert.Contains($"{door}: $.shapes[1].radius: 9.5 → {radius}", run.Out);
        Assert.Single(run.Out.Split('\n'), l => l.StartsWith("changed "));
    }
}
