namespace AcShadow.Analysis.Doctor;

/// <summary>What the Setup checks need to know of each GfxObj id, kept for the whole 0x0100xxxx range in one byte each.</summary>
internal sealed class GfxObjPhysics
{
    public enum State : byte { Absent, NoBsp, Bsp, Unreadable }

    private readonly byte[] _states = new byte[0x10000];

    public void Set(uint id, State state)
    {
        if (id is >= 0x01000000 and <= 0x0100FFFF) Volatile.Write(ref _states[id & 0xFFFF], (byte)state);
    }

    public State Get(uint id) => id is >= 0x01000000 and <= 0x0100FFFF ? (State)Volatile.Read(ref _states[id & 0xFFFF]) : State.Absent;
}
