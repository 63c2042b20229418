using AcShadow.Core.Dat.Objects;

namespace AcShadow.Core.Poses;

/// <summary>
/// An animation node as retail builds it from an AnimData (AnimSequenceNode), reduced to what a first pose
/// needs: the animation, its clamped frame range and its direction.
/// </summary>
public readonly record struct AnimationNode(Animation Animation, int LowFrame, int HighFrame, bool Forward)
{
    /// <summary>
    /// AnimSequenceNode::set_animation_id's clamps: HighFrame &lt; 0 → last frame; LowFrame ≥ NumFrames
    /// (compared unsigned, as retail does) → last frame; HighFrame ≥ NumFrames → last frame; LowFrame &gt;
    /// HighFrame → HighFrame = LowFrame. A framerate ≥ 0 plays forward.
    /// </summary>
    public static AnimationNode From(Animation animation, AnimData data)
    {
        var last = animation.PartFrames.Count - 1;
        int low = data.LowFrame, high = data.HighFrame;
        if (high < 0) high = last;
        if ((uint)low >= (uint)animation.PartFrames.Count) low = last;
        if (high > last) high = last;
        if (low > high) high = low;
        return new AnimationNode(animation, low, high, data.Framerate >= 0f);
    }

    /// <summary>get_starting_frame, floored: LowFrame forward; backward HighFrame + 1 − 0.0002, whose floor is HighFrame.</summary>
    public int StartingFrame => Forward ? LowFrame : HighFrame;

    /// <summary>get_ending_frame, floored: forward HighFrame + 1 − 0.0002, whose floor is HighFrame; backward LowFrame.</summary>
    public int EndingFrame => Forward ? HighFrame : LowFrame;

    /// <summary>get_part_frame: the part frames at <paramref name="frame"/>, or null when it is outside the animation (no pose).</summary>
    public AnimationFrame? PartFrameAt(int frame) => frame >= 0 && frame < Animation.PartFrames.Count ? Animation.PartFrames[frame] : null;
}
