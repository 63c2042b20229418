namespace AcShadow.Forge;

/// <summary>
/// The Setup id of every door weenie (type 19) in the public ACE world database, as listed in the
/// project's shared domain notes (door-setups.tsv, 58 ids). Facts copied as data so the forge runs
/// without the shared folder; the scale spec makes each of these a door.
/// </summary>
public static class DoorSetupIds
{
    public static readonly IReadOnlyList<uint> All =
    [
        0x0200024F, 0x0200027C, 0x02000281, 0x02000310, 0x02000311, 0x02000312, 0x02000313, 0x0200037E,
        0x020003B5, 0x02000422, 0x020005DA, 0x020005F1, 0x020005F2, 0x0200098C, 0x020009A9, 0x02000A7E,
        0x02000BDE, 0x02000C07, 0x02000C08, 0x02000C09, 0x02000C0A, 0x02000C0B, 0x02000C0C, 0x02000C0D,
        0x02000C56, 0x02000C7E, 0x02000C9D, 0x02000D55, 0x02000F84, 0x02000FDA, 0x02000FDB, 0x02000FE6,
        0x02000FE7, 0x02000FEE, 0x02000FF1, 0x02000FF2, 0x02001056, 0x020010A8, 0x020011AB, 0x020011C5,
        0x02001204, 0x02001215, 0x02001216, 0x020013D0, 0x0200187D, 0x020018C4, 0x020018CC, 0x020018F7,
        0x02001940, 0x020019FF, 0x02001A4C, 0x02001A97, 0x02001A98, 0x02001B40, 0x02001B7C, 0x02001B7D,
        0x02001B92, 0x02001BE0
    ];
}
