using System.CommandLine;
using AcShadow.Cli.Commands;
using AcShadow.Cli.Conventions;
using AcShadow.Cli.Infrastructure;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;

namespace AcShadow.Cli;

/// <summary>
/// The command tree and the one place errors become exit codes: a usage or input problem prints one
/// line; a stack trace only with --verbose.
/// </summary>
public static class AcShadowApp
{
    public static int Run(string[] args, CliConsole console)
    {
        var verbose = new Option<bool>("--verbose") { Description = "show stack traces for errors", Recursive = true };
        var root = new RootCommand("acshadow: ground-truth collision shapes and BSP dumps from Asheron's Call dat files")
        {
            verbose,
            DumpCommand.Create(console),
        };
        foreach (var command in ExtraCommands.All(console)) root.Subcommands.Add(command);
        ExamplesHelpAction.Install(root);
        VersionAction.Install(root);

        var parse = root.Parse(args);
        // A bad option value is the command's own usage error, reported below like one; any other parse error first.
        var refused = ValueOptions.Refusal(parse);
        if (refused is null && parse.Errors.Count > 0)
        {
            var errors = parse.Errors.Where(e => !ValueOptions.IsRefusal(e)).ToArray();
            // An unrecognised word says more than the "required command" error it also causes.
            var error = errors.FirstOrDefault(e => e.Message.StartsWith("Unrecognized", StringComparison.Ordinal)) ?? errors[0];
            var command = parse.CommandResult.Command;
            var help = command == root ? "acshadow --help" : $"acshadow {command.Name} --help";
            var suggestion = TypoSuggestion.For(parse) is { } near ? $" Did you mean '{near}'?" : "";
            console.Error.WriteLine($"acshadow: {error.Message}{suggestion} (see `{help}`)");
            return ExitCodes.Usage;
        }
        // What this run writes, for the line an interrupted run ends with (and a forced stop's cleanup).
        var ledger = new OutputLedger();
        var outer = OutputLedger.Current;
        OutputLedger.Current = ledger;
        Interrupt.Watch(ledger);
        try
        {
            refused?.Throw();
            return parse.Invoke(new InvocationConfiguration { Output = console.Out, Error = console.Error, EnableDefaultExceptionHandler = false });
        }
        catch (Exception thrown)
        {
            var e = Unwrap(thrown);
            var (code, message) = e switch
            {
                // A command's own line for Ctrl-C says what it wrote; the code tells Ctrl-C (130) from SIGTERM (143).
                CliException { ExitCode: ExitCodes.Interrupted } c => (Interrupt.ExitCode, c.Message),
                CliException c => (c.ExitCode, c.Message),
                StandardOutputException o => (ExitCodes.OutputFailed, $"cannot write to standard output: {o.Message} (redirect it to a file or pipe that can take it)"),
                // A signal where no command said what it had written (e.g. while the dat was being read): the ledger does.
                OperationCanceledException => (Interrupt.ExitCode, $"{Interrupt.Word}: {ledger.Summary()}"),
                // The runtime reports a thread it could not start as out of memory, also when descriptors ran out.
                // Under a virtual-memory limit, whatever could not be allocated (a thread's stack, a mapping) is memory.
                _ when OutOfMemory(e) && VirtualMemoryLimit.Describe() is { } limit => (ExitCodes.InternalError, $"out of memory: {limit}, and this run needs more: raise it (or pass --jobs 1, which needs less)"),
                OutOfMemoryException when e.StackTrace?.Contains("Thread.StartCore", StringComparison.Ordinal) == true => (ExitCodes.InternalError, "cannot start a worker thread: too few file descriptors or threads (raise `ulimit -n` or `ulimit -u`, or pass --jobs 1)"),
                _ when OutOfMemory(e) => (ExitCodes.InternalError, "out of memory: the input asks for more than this machine has (run with --verbose and please report it)"),
                FileNotFoundException or FileLoadException when e.Message.Contains("assembly", StringComparison.Ordinal) => (ExitCodes.InternalError, Describe(e)),
                IOException when DescriptorsExhausted(e) => (ExitCodes.InternalError, Describe(e)),
                // Directory damage a lookup met after the dat opened: the line the dat would have been refused with at open.
                DatDirectoryException d => (ExitCodes.DatUnreadable, DatLocator.Describe(d)),
                DatFormatException d => (ExitCodes.DatUnreadable, d.Message.StartsWith("corrupt dat", StringComparison.Ordinal) ? d.Message : $"corrupt dat: {d.Message}"),
                // Output writes and the --setups file are wrapped where they happen, so a bare I/O error is the dat's.
                IOException io => (ExitCodes.DatUnreadable, $"reading the dat failed: {io.Message} (is the file on a failing disk, or being replaced?)"),
                _ => (ExitCodes.InternalError, $"internal error: {e.Message} (run with --verbose for the stack trace, and please report it)"),
            };
            // A forced stop (Interrupt) that already printed the line is ending the process.
            if (code is ExitCodes.Interrupted or ExitCodes.Terminated && !Interrupt.ClaimReport()) return code;
            try
            {
                console.Error.WriteLine($"acshadow: {OneLine(message)}");
                if (parse.GetValue(verbose)) console.Error.WriteLine(thrown.ToString());
            }
            // stderr itself broken (the tests' writers; the real one is guarded): the exit code still tells.
            catch (IOException)
            {
            }
            return code;
        }
        finally
        {
            OutputLedger.Current = outer;
        }
    }

    /// <summary>
    /// The exception that says what went wrong: a parallel loop wraps what a worker threw (the first worker's
    /// is reported); a type initializer or the task scheduler wraps, for example, an assembly that could not load.
    /// </summary>
    private static Exception Unwrap(Exception thrown)
    {
        var e = thrown;
        while (true)
        {
            if (e is AggregateException a) e = a.Flatten().InnerExceptions[0];
            else if (e is TypeInitializationException or TaskSchedulerException && e.InnerException is { } inner) e = inner;
            else return e;
        }
    }

    /// <summary>
    /// Memory ran out: the runtime's exception, or an operating-system call that failed with ENOMEM (12,
    /// "Cannot allocate memory"), or an assembly that could not be mapped under a virtual-memory limit.
    /// </summary>
    private static bool OutOfMemory(Exception e) =>
        e is OutOfMemoryException or InsufficientExecutionStackException
        || (e is IOException { HResult: 12 } && !OperatingSystem.IsWindows())
        || e.Message.Contains("Cannot allocate memory", StringComparison.Ordinal)
        || (e is FileNotFoundException or FileLoadException or BadImageFormatException && VirtualMemoryLimit.Bytes() is not null);

    /// <summary>Constants, so the last-resort line in Program needs no code of this class to run.</summary>
    public const string CannotLoad = "cannot load part of acshadow itself";
    public const string CannotLoadCause = "too few file descriptors (ulimit -n) or an incomplete installation";

    /// <summary>A failure of acshadow's own process rather than its input: which part could not load, and the likely cause.</summary>
    public static string Describe(Exception thrown) => Unwrap(thrown) switch
    {
        var e when OutOfMemory(e) && VirtualMemoryLimit.Describe() is { } limit => $"out of memory: {limit}, too little to load acshadow ({OneLine(e.Message)}): raise it",
        var e when e is FileNotFoundException or FileLoadException => $"{CannotLoad} ({OneLine(e.Message)}): {CannotLoadCause}",
        var e when DescriptorsExhausted(e) => $"too few file descriptors: {OneLine(e.Message)} (raise the limit, e.g. `ulimit -n 1024`; acshadow needs about 100)",
        var e => $"internal error: {OneLine(e.Message)} (run with --verbose for the stack trace, and please report it)",
    };

    // EMFILE (the process's limit) and ENFILE (the system's): .NET gives an I/O error the errno as its HResult on Unix; both are 24 and 23 on Linux and macOS.
    private static bool DescriptorsExhausted(Exception e) => e is IOException { HResult: 24 or 23 } && !OperatingSystem.IsWindows();

    /// <summary>
    /// Every error is one line, even when an exception's message (or a path in it) holds line breaks; any
    /// other control character a path carries (ESC) is written as an escape, never sent to the terminal.
    /// </summary>
    private static string OneLine(string message) =>
        PrintableText.Escape(string.Join(' ', message.Split(['\r', '\n'], StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries)));
}
