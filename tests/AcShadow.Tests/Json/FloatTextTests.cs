using System.Text;
using AcShadow.Core.Json;

namespace AcShadow.Tests.Json;

/// <summary>
/// Utf8JsonText keeps each thread's recent float texts; whatever it has cached, a float's text must be the
/// one the canonical tree writer gives it.
/// </summary>
public sealed class FloatTextTests
{
    private static string Written(float value) =>
        Encoding.UTF8.GetString(Utf8JsonText.Build(value, (t, v) => t.Float(v)));

    private static string Expected(float value) => ((JsonNum)JsonNum.Of(value)).Text;

    [Fact]
    public void Repeated_and_colliding_values_always_get_their_own_text()
    {
        var random = new Random(11);
        // More distinct values than the cache has slots, each written several times in shuffled order,
        // so every slot is hit, missed and replaced many times.
        var values = Enumerable.Range(0, 20_000).Select(_ => BitConverter.Int32BitsToSingle(random.Next(int.MinValue, int.MaxValue)))
            .Where(float.IsFinite).ToArray();
        var order = Enumerable.Range(0, values.Length * 3).Select(i => values[i % values.Length]).OrderBy(_ => random.Next()).ToArray();
        foreach (var value in order) Assert.Equal(Expected(value), Written(value));
    }

    [Theory]
    [InlineData(-0f, "0")]
    [InlineData(1e-5f, "1E-05")]
    [InlineData(-1.17549435E-38f, "-1.1754944E-38")]
    [InlineData(float.Epsilon, "1E-45")]
    [InlineData(float.MaxValue, "3.4028235E+38")]
    [InlineData(float.NaN, "null")]
    [InlineData(float.NegativeInfinity, "null")]
    public void Edge_values_are_written_the_same_the_first_time_and_from_the_cache(float value, string expected)
    {
        Assert.Equal(expected, Written(value));
        Assert.Equal(expected, Written(value));
    }

    [Fact]
    public void Threads_writing_the_same_values_get_the_same_text()
    {
        var values = Enumerable.Range(0, 5000).Select(i => i * 0.0137f - 30f).ToArray();
        var expected = values.Select(Expected).ToArray();
        var mismatches = 0;
        Parallel.For(0, 8, new ParallelOptions { MaxDegreeOfParallelism = 8 }, worker =>
        {
            for (var round = 0; round < 4; round++)
                for (var i = 0; i < values.Length; i++)
                {
                    var k = (i * (worker + 1) + round) % values.Length;
                    if (Written(values[k]) != expected[k]) Interlocked.Increment(ref mismatches);
                }
        });
        Assert.Equal(0, mismatches);
    }
}
