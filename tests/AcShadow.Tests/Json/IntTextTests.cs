using System.Globalization;
using System.Text;
using AcShadow.Core.Json;

namespace AcShadow.Tests.Json;

/// <summary>Utf8JsonText writes small integers itself; every integer must read as the invariant formatter writes it.</summary>
public sealed class IntTextTests
{
    [Theory]
    [InlineData(0L)]
    [InlineData(7L)]
    [InlineData(9L)]
    [InlineData(10L)]
    [InlineData(99L)]
    [InlineData(100L)]
    [InlineData(999L)]
    [InlineData(1000L)]
    [InlineData(9999L)]
    [InlineData(10000L)]
    [InlineData(-1L)]
    [InlineData(-10000L)]
    [InlineData(long.MinValue)]
    [InlineData(long.MaxValue)]
    public void Integers_are_written_as_the_invariant_formatter_writes_them(long value) =>
        Assert.Equal(value.ToString(CultureInfo.InvariantCulture), Encoding.UTF8.GetString(Utf8JsonText.Build(value, (t, v) => t.Int(v))));

    [Fact]
    public void Every_integer_up_to_twenty_thousand_in_one_buffer_reads_back()
    {
        var text = Encoding.UTF8.GetString(Utf8JsonText.Build(0, static (t, _) =>
        {
            for (var i = 0; i <= 20_000; i++) t.Int(i).Raw(" "u8);
        }));
        Assert.Equal(Enumerable.Range(0, 20_001), text.Split(' ', StringSplitOptions.RemoveEmptyEntries).Select(s => int.Parse(s, CultureInfo.InvariantCulture)));
    }
}
