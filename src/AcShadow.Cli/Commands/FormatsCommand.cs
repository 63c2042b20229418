using System.CommandLine;
using AcShadow.Cli.Infrastructure;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures;

namespace AcShadow.Cli.Commands;

/// <summary>`acshadow formats`: every file format the tool writes, its version, where it goes, its schema.</summary>
public static class FormatsCommand
{
    public static Command Create(CliConsole console)
    {
        var command = new Command("formats", "List the file formats acshadow writes, with their versions and JSON Schemas");
        command.SetAction(_ =>
        {
            var o = console.Out;
            var formatWidth = FileFormats.All.Max(f => f.Format.Length) + 2;
            var pathWidth = FileFormats.All.Max(f => f.PathPattern.Length) + 2;
            o.WriteLine($"{"format".PadRight(formatWidth)}{"file".PadRight(pathWidth)}schema $id");
            foreach (var f in FileFormats.All)
                o.WriteLine($"{f.Format.PadRight(formatWidth)}{f.PathPattern.PadRight(pathWidth)}{f.SchemaId}");
            o.WriteLine();
            foreach (var f in FileFormats.All) o.WriteLine($"{f.Format}: {f.Description}");
            o.WriteLine();
            o.WriteLine("Schemas: schemas/*.schema.json in the repository (and in the AcShadow.Fixtures package); description: docs/formats.md.");
            o.WriteLine("acdream.gfxobj and acdream.cell files carry no format field: acdream fixes their fields. Every other file's \"format\" names its version.");
            return 0;
        });
        return command;
    }
}
