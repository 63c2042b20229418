namespace AcShadow.Cli.Conventions;

/// <summary>
/// The examples `--help` prints under each command: one line each, pasteable as they stand (the
/// sample-data ones need no dat). A test parses every one of them.
/// </summary>
public static class CommandExamples
{
    public static IReadOnlyDictionary<string, string[]> ByCommand { get; } = new Dictionary<string, string[]>
    {
        ["acshadow"] =
        [
            "acshadow dump --setup 0x020019FF",
            "acshadow batch --doors --all --landblock 0xA9B4 --out my-fixtures",
            "acshadow formats",
            "acshadow completions bash",
        ],
        ["dump"] =
        [
            "acshadow dump --setup 0x020019FF",
            "acshadow dump --setup 0x020019FF --dat ~/ac/client_portal.dat --out my-fixtures --format both",
            "acshadow dump --setup 0x020019FF --policy union --out union-door",
            "acshadow dump --cell 0xA9B40100 --out cottage --format both",
            "acshadow @dump-door.rsp",
        ],
        ["batch"] =
        [
            "acshadow batch --doors --all --landblock 0xA9B4 --out my-fixtures",
            "acshadow batch --doors --out door-fixtures --format acdream --jobs 4",
            "acshadow batch --setups ids.txt --out fixtures --incremental --quiet",
            "acshadow batch --landblock 0xA9B4 --no-cells --out outdoors",
            "acshadow batch --doors --movement 0x020019FF --out fixtures",
        ],
        ["audit"] =
        [
            "acshadow audit --only-bsp --sort coverage",
            "acshadow audit --doors --format csv --out audit.csv",
            "acshadow audit --all --chart --format md",
        ],
        ["verify"] =
        [
            "acshadow verify --fixtures fixtures",
            "acshadow verify --fixtures my-fixtures --dat ~/ac/client_portal.dat --cell-dat ~/ac/client_cell_1.dat",
        ],
        ["chart"] =
        [
            "acshadow chart --setup 0x020019FF --out chart-door",
            "acshadow chart --doors --out chart-doors --probe-radius 0.5 --spacing 0.25",
        ],
        ["scene"] =
        [
            "acshadow scene --landblock 0xA9B4 --out compiled-a9b4",
            "acshadow scene --landblock 0xA9B4 --dat ~/ac/client_portal.dat --cell-dat ~/ac/client_cell_1.dat --out compiled --mover-radius 0.48 --mover-radius 1.2 --tolerance 0.5",
        ],
        ["move"] =
        [
            "acshadow move --setup 0x020019FF --out cases",
            "acshadow move --doors --dat ~/ac/client_portal.dat --mover 0x02000001 --state closed --out door-cases",
        ],
        ["view"] =
        [
            "acshadow view --setup 0x020019FF --out v",
            "acshadow view --fixtures fixtures --out v",
            "acshadow view --setup 0x020019FF --chart chart-door --out v",
            "acshadow view --scene compiled-a9b4 --out v",
        ],
        ["doctor"] =
        [
            "acshadow doctor",
            "acshadow doctor --dat ~/ac/client_portal.dat --cell-dat ~/ac/client_cell_1.dat --out doctor.json",
        ],
        ["formats"] =
        [
            "acshadow formats",
        ],
        ["completions"] =
        [
            "acshadow completions bash >> ~/.bashrc",
            "acshadow completions pwsh >> $PROFILE",
        ],
    };
}
