using AcShadow.Tests.Support;

namespace AcShadow.Tests.View;

/// <summary>Issue 32 item 16: the rasterising tests skip, saying why, where rsvg-convert is missing.</summary>
public class RasterisingFactTests
{
    [Fact]
    public void A_path_without_rsvg_convert_skips_and_one_with_it_runs()
    {
        using var empty = new TempDir();
        using var tools = new TempDir();
        File.WriteAllText(Path.Combine(tools.Path, RasterisingFactAttribute.Tool), "");
        Assert.False(RasterisingFactAttribute.Installed(empty.Path));
        Assert.False(RasterisingFactAttribute.Installed(null));
        Assert.True(RasterisingFactAttribute.Installed(empty.Path + Path.PathSeparator + tools.Path));
    }
}
