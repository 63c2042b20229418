using AcShadow.Core.Json;

namespace AcShadow.Tests.Json;

/// <summary>Utf8JsonText.Lend hands out the thread's buffer for the call only; what it lends must be what Build returns.</summary>
public sealed class LentTextTests
{
    [Fact]
    public void Lent_bytes_equal_built_bytes_and_a_build_inside_the_loan_does_not_overwrite_them()
    {
        static void Write(Utf8JsonText t, int n)
        {
            for (var i = 0; i < n; i++) t.Raw("{\"v\": "u8).Float(i * 0.25f).Raw("}\n"u8);
        }
        var built = Utf8JsonText.Build(20_000, Write); // larger than the thread's first buffer
        var nested = Utf8JsonText.Build(3, Write);
        var seen = Utf8JsonText.Lend(20_000, Write, lent =>
        {
            var copy = lent.ToArray();
            var inner = Utf8JsonText.Build(3, Write);
            Assert.Equal(nested, inner);
            Assert.True(lent.Span.SequenceEqual(copy), "a nested build changed the lent bytes");
            return copy;
        });
        Assert.Equal(built, seen);
    }
}
