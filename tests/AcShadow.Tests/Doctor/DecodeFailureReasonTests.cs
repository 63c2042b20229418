using AcShadow.Analysis.Doctor;
using AcShadow.Core.Dat.Binary;

namespace AcShadow.Tests.Doctor;

/// <summary>doctor groups objects that do not decode by a fixed key read from the reader's message (which it never reports).</summary>
public class DecodeFailureReasonTests
{
    /// <summary>Each message is the wording a reader of src/AcShadow.Core/Dat throws, with example numbers.</summary>
    public static TheoryData<string, string> Failures() => new()
    {
        { "Setup 0x02000001 placement 0 frame 1: animation hook type 99 (0x00000063) is unknown, so its length and everything after it cannot be read", DoctorDiagnosticCodes.UnknownHookType },
        { "PhysicsBSP node tag 0x12345678 is not a physics node type", DoctorDiagnosticCodes.UnknownBspNodeTag },
        { "PhysicsBSP deeper than 256 levels", DoctorDiagnosticCodes.BspTooDeep },
        { "vertex type 2 is not the SW vertex type (1)", DoctorDiagnosticCodes.UnknownVertexType },
        { "the object's bytes carry id 0x02000002", DoctorDiagnosticCodes.WrongIdInBytes },
        { "GfxObj polygons count 70000 cannot fit in the 12 byte(s) left.", DoctorDiagnosticCodes.CountLargerThanObject },
        { "GfxObj: needs 4 more byte(s) at offset 20, but only 2 remain (truncated or not this object type).", DoctorDiagnosticCodes.Truncated },
        { "object 0x02000001 points at 0x00FFFF00, outside the 4096-byte file", DoctorDiagnosticCodes.BlockChain },
        { "object 0x02000001 loops back to block 0x00000400", DoctorDiagnosticCodes.BlockChain },
        { "the directory gives it 99999999 bytes, more than any object holds", DoctorDiagnosticCodes.BlockChain },
        { "something no reader says", DoctorDiagnosticCodes.Other },
    };

    [Theory]
    [MemberData(nameof(Failures))]
    public void Each_reader_failure_is_grouped_under_its_reason(string message, string reason) =>
        Assert.Equal(reason, DecodeFailureReason.Of(new DatFormatException(message)));
}
