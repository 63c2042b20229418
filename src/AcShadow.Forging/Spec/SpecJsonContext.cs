using System.Text.Json.Serialization;

namespace AcShadow.Forging.Spec;

/// <summary>Compile-time JSON metadata for the spec records; <see cref="SpecJson"/> adds its options and converters.</summary>
[JsonSerializable(typeof(ForgeSpec))]
[JsonSerializable(typeof(string))]
internal sealed partial class SpecJsonContext : JsonSerializerContext;
