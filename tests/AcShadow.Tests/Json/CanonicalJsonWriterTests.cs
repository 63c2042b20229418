using System.Numerics;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Json;

namespace AcShadow.Tests.Json;

public class CanonicalJsonWriterTests
{
    [Theory]
    [InlineData(0.141f, "0.141")]
    [InlineData(0.1f, "0.1")]
    [InlineData(-0f, "0")]
    [InlineData(1f, "1")]
    [InlineData(-2.5f, "-2.5")]
    [InlineData(1e-5f, "1E-05")]
    [InlineData(16777216f, "16777216")]
    public void Floats_use_the_shortest_text_that_round_trips_float32(float value, string expected)
    {
        var text = ((JsonNum)JsonNum.Of(value)).Text;
        Assert.Equal(expected, text);
        Assert.Equal(value == 0 ? 0f : value, float.Parse(text, System.Globalization.CultureInfo.InvariantCulture));
    }

    [Fact]
    public void Every_float32_bit_pattern_sampled_round_trips()
    {
        var random = new Random(7);
        for (var i = 0; i < 20000; i++)
        {
            var f = BitConverter.Int32BitsToSingle(random.Next(int.MinValue, int.MaxValue));
            if (!float.IsFinite(f)) continue;
            var node = JsonNum.Of(f);
            var back = float.Parse(((JsonNum)node).Text, System.Globalization.CultureInfo.InvariantCulture);
            Assert.Equal(f == 0 ? 0u : BitConverter.SingleToUInt32Bits(f), BitConverter.SingleToUInt32Bits(back));
        }
    }

    [Fact]
    public void Non_finite_numbers_become_null()
    {
        Assert.Same(JsonNull.Value, JsonNum.Of(float.NaN));
        Assert.Same(JsonNull.Value, JsonNum.Of(float.PositiveInfinity));
    }

    [Fact]
    public void Layout_is_two_space_indent_lf_final_newline_with_vectors_inline()
    {
        var root = new JsonObj()
            .Add("id", "0x020019FF")
            .Add("position", new Vector3(1, -0f, 0.5f))
            .Add("rotation", JsonShapes.Quaternion(Quaternion.Identity))
            .Add("items", JsonArr.Of(new[] { 1, 2 }, i => new JsonObj().Add("n", i).Add("list", new JsonArr())))
            .Add("empty", new JsonObj());
        var text = CanonicalJsonWriter.Write(root);
        Assert.Equal(
            "{\n" +
            "  \"id\": \"0x020019FF\",\n" +
            "  \"position\": [1, 0, 0.5],\n" +
            "  \"rotation\": {\"w\": 1, \"x\": 0, \"y\": 0, \"z\": 0},\n" +
            "  \"items\": [\n" +
            "    {\"n\": 1, \"list\": []},\n" +
            "    {\"n\": 2, \"list\": []}\n" +
            "  ],\n" +
            "  \"empty\": {}\n" +
            "}\n", text);
        Assert.DoesNotContain('\r', text);
    }

    [Fact]
    public void Strings_are_escaped()
    {
        var text = CanonicalJsonWriter.Write(new JsonObj().Add("s", "a\"b\\c\n\u0001"));
        Assert.Contains("\"a\\\"b\\\\c\\n\\u0001\"", text);
    }

    [Theory]
    [InlineData("0x020019FF", 0x020019FFu)]
    [InlineData("020019FF", 0x020019FFu)]
    [InlineData("0X020019ff", 0x020019FFu)]
    public void Ids_parse_with_or_without_0x(string text, uint expected)
    {
        Assert.True(JsonIds.TryParse(text, out var id));
        Assert.Equal(expected, id);
        Assert.Equal("0x020019FF", JsonIds.Format(id));
    }

    [Theory]
    [InlineData("")]
    [InlineData("0x")]
    [InlineData("door")]
    [InlineData("0x1234567890")]
    [InlineData("-1")]
    public void Bad_ids_do_not_parse(string text) => Assert.False(JsonIds.TryParse(text, out _));
}
