using AcShadow.Core.Dat.Objects;

namespace AcShadow.Core.Poses;

/// <summary>
/// An animation node as retail builds it from an AnimData, reduced to what a first pose needs: the
/// animation and the frame number the node starts at.
/// </summary>
public readonly record struct AnimationCursor(Animation Animation, int Frame)
{
    /// <summary>
    /// AnimSequenceNode::set_animation_id's clamps, then get_starting_frame: HighFrame &lt; 0 → last frame;
    /// LowFrame ≥ NumFrames (compared unsigned, as retail does) → last frame; HighFrame ≥ NumFrames → last
    /// frame; LowFrame &gt; HighFrame → HighFrame = LowFrame. A forward (framerate ≥ 0) node starts at LowFrame,
    /// a backward one at HighFrame + 1 − 0.0002, whose floor is HighFrame.
    /// </summary>
    public static AnimationCursor Start(Animation animation, AnimData data)
    {
        var last = animation.PartFrames.Count - 1;
        int low = data.LowFrame, high = data.HighFrame;
        if (high < 0) high = last;
        if ((uint)low >= (uint)animation.PartFrames.Count) low = last;
        if (high > last) high = last;
        if (low > high) high = low;
        return new AnimationCursor(animation, data.Framerate >= 0f ? low : high);
    }

    /// <summary>The part frames at <see cref="Frame"/>, or null when the frame number is outside the animation (no pose).</summary>
    public AnimationFrame? PartFrame => Frame >= 0 && Frame < Animation.PartFrames.Count ? Animation.PartFrames[Frame] : null;
}
