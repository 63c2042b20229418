using System.Text;
using AcShadow.Core.Verify;

namespace AcShadow.Tests.Verify;

public class JsonDiffTests
{
    private static IReadOnlyList<JsonDifference> Diff(string a, string b) => JsonDiff.Compare(Encoding.UTF8.GetBytes(a), Encoding.UTF8.GetBytes(b))!;

    [Fact]
    public void Changed_values_are_named_by_json_path_with_old_and_new()
    {
        var d = Assert.Single(Diff("""{"shapes": [{"radius": 0.9654}]}""", """{"shapes": [{"radius": 0.9655}]}"""));
        Assert.Equal("$.shapes[0].radius: 0.9654 → 0.9655", d.ToString());
    }

    [Fact]
    public void Numbers_compare_by_text_strings_by_value_and_kinds_strictly()
    {
        Assert.Empty(Diff("""{"a": 1, "b": "x"}""", """{"a": 1, "b": "x"}"""));
        Assert.Equal("$.a: 1 → 1.0", Assert.Single(Diff("""{"a": 1}""", """{"a": 1.0}""")).ToString());
        Assert.Equal("$.a: \"1\" → 1", Assert.Single(Diff("""{"a": "1"}""", """{"a": 1}""")).ToString());
        Assert.Equal("$.a: null → false", Assert.Single(Diff("""{"a": null}""", """{"a": false}""")).ToString());
    }

    [Fact]
    public void Absent_members_and_items_are_reported_as_absent()
    {
        var diffs = Diff("""{"a": 1, "v": [1, 2]}""", """{"v": [1, 2, 3], "b": {"c": 2}}""").Select(d => d.ToString()).ToArray();
        Assert.Equal(["$.a: 1 → (absent)", "$.v[2]: (absent) → 3", "$.b: (absent) → {\"c\":2}"], diffs);
    }

    [Fact]
    public void Arrays_of_objects_with_a_distinct_path_match_by_it()
    {
        var diffs = Diff(
            """{"files": [{"path": "a", "sha256": "1"}, {"path": "c", "sha256": "3"}]}""",
            """{"files": [{"path": "a", "sha256": "1"}, {"path": "b", "sha256": "2"}, {"path": "c", "sha256": "4"}]}""");
        Assert.Equal(["$.files[path=c].sha256: \"3\" → \"4\"", "$.files[path=b]: (absent) → {\"path\":\"b\",\"sha256\":\"2\"}"], diffs.Select(d => d.ToString()));
    }

    [Fact]
    public void Odd_member_names_are_quoted_and_non_json_gives_null()
    {
        Assert.Equal("$[\"two words\"]: 1 → 2", Assert.Single(Diff("""{"two words": 1}""", """{"two words": 2}""")).ToString());
        Assert.Null(JsonDiff.Compare(Encoding.UTF8.GetBytes("{"), Encoding.UTF8.GetBytes("{}")));
    }

    [Fact]
    public void Json_holding_bytes_that_are_not_UTF8_is_not_comparable_rather_than_an_error()
    {
        // Found by the fuzz campaign: a damaged fixture whose string holds an invalid UTF-8 byte parses, but its text cannot be read.
        byte[] broken = [.. "{\"a\": \""u8, 0xC3, 0x28, .. "\"}"u8];
        Assert.Null(JsonDiff.Compare(broken, "{\"a\": \"x\"}"u8.ToArray()));
    }
}
