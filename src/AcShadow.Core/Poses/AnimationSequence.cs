namespace AcShadow.Core.Poses;

/// <summary>
/// The part of retail's CSequence that decides a first pose: the animation nodes in order, which one is
/// current and at which frame, and first_cyclic (the last node appended; the nodes before it are links).
/// Each node carries what appended it (<typeparamref name="TOrigin"/>), for the pose's provenance.
/// </summary>
public sealed class AnimationSequence<TOrigin>
{
    private readonly List<(AnimationNode Node, TOrigin Origin)> _nodes = [];
    private int _current = -1, _firstCyclic = -1, _frame;

    /// <summary>The current node and what appended it, or null when there is none (the placement frame poses).</summary>
    public (AnimationNode Node, TOrigin Origin)? Current => _current < 0 ? null : _nodes[_current];

    /// <summary>The current frame number, floored (CSequence::get_curr_frame_number).</summary>
    public int Frame => _frame;

    /// <summary>CSequence::has_anims.</summary>
    public bool HasAnims => _nodes.Count > 0;

    /// <summary>CSequence::clear_animations.</summary>
    public void Clear()
    {
        _nodes.Clear();
        _current = _firstCyclic = -1;
        _frame = 0;
    }

    /// <summary>
    /// CSequence::append_animation for a node whose animation is in the dat (one that is not never gets here:
    /// retail drops it): the node becomes first_cyclic, and the list's head becomes current when none is.
    /// </summary>
    public void Append(AnimationNode node, TOrigin origin)
    {
        _nodes.Add((node, origin));
        _firstCyclic = _nodes.Count - 1;
        if (_current >= 0) return;
        _current = 0;
        _frame = _nodes[0].Node.StartingFrame;
    }

    /// <summary>
    /// CSequence::remove_cyclic_anims: drops first_cyclic and every node after it; a dropped current hands over
    /// to the node before first_cyclic at its ending frame, or to none. The last node left becomes first_cyclic.
    /// </summary>
    public void RemoveCyclicAnims()
    {
        if (_firstCyclic >= 0)
        {
            if (_current >= _firstCyclic)
            {
                _current = _firstCyclic - 1;
                _frame = _current >= 0 ? _nodes[_current].Node.EndingFrame : 0;
            }
            _nodes.RemoveRange(_firstCyclic, _nodes.Count - _firstCyclic);
        }
        _firstCyclic = _nodes.Count - 1;
    }

    /// <summary>
    /// CSequence::remove_all_link_animations: drops every node before first_cyclic; a dropped current hands over
    /// to first_cyclic at its starting frame.
    /// </summary>
    public void RemoveAllLinkAnimations()
    {
        if (_firstCyclic <= 0) return;
        if (_current >= 0 && _current < _firstCyclic)
        {
            _current = _firstCyclic;
            _frame = _nodes[_firstCyclic].Node.StartingFrame;
        }
        _nodes.RemoveRange(0, _firstCyclic);
        if (_current >= 0) _current -= _firstCyclic;
        _firstCyclic = 0;
    }
}
