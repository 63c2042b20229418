namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// The uint that opens every animation hook (retail <c>CAnimHook::UnPackHook</c> switches on it).
/// Each type's byte layout is in <see cref="AnimationHookLayout"/>; a value not listed here has no known layout.
/// </summary>
public enum AnimationHookType : uint
{
    NoOp = 0,
    Sound = 1,
    SoundTable = 2,
    Attack = 3,
    AnimationDone = 4,
    ReplaceObject = 5,
    Ethereal = 6,
    TransparentPart = 7,
    Luminous = 8,
    LuminousPart = 9,
    Diffuse = 10,
    DiffusePart = 11,
    Scale = 12,
    CreateParticle = 13,
    DestroyParticle = 14,
    StopParticle = 15,
    NoDraw = 16,
    DefaultScript = 17,
    DefaultScriptPart = 18,
    CallPES = 19,
    Transparent = 20,
    SoundTweaked = 21,
    SetOmega = 22,
    TextureVelocity = 23,
    TextureVelocityPart = 24,
    SetLight = 25,
    CreateBlockingParticle = 26,
}
