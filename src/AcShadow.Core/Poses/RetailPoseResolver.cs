using AcShadow.Core.Catalog;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Poses;

/// <summary>
/// The pose retail gives a Setup's parts right after it creates the object (CPartArray::InitDefaults,
/// CPhysicsObj::InitDefaults, CMotionTable::SetDefaultState, CSequence::get_curr_animframe):
/// <list type="number">
/// <item>DefaultAnimation, when the Setup has one, becomes the current animation at its first frame.</item>
/// <item>Each motion table the object is given, in order (the Setup's DefaultMotionTable, then the weenie's:
/// `--motion-table`, else the door catalog's), enters its default state: DefaultStyle, StyleDefaults[DefaultStyle],
/// Cycles[(style &lt;&lt; 16) | substate]. Success clears every animation and appends the cycle's; its first
/// animation becomes current at its starting frame. A missing entry fails and leaves the sequence as it was.</item>
/// <item>A door then takes its state's motion (closed = Off, open = On) unless it is already in it; the pose is
/// the motion's settled one: the cycle's last (looping) animation at its starting frame.</item>
/// <item>The current animation frame poses the parts it has frames for; with no current frame the placement
/// frame poses them all.</item>
/// </list>
/// Whatever is missing (a table, a key, an animation, a frame, part frames) is a diagnostic, and the parts
/// it leaves unposed keep the placement pose.
/// </summary>
public static class RetailPoseResolver
{
    public static ResolvedPose Resolve(Setup setup, PoseSettings options, IMotionSource? motions, List<Diagnostic> diagnostics)
    {
        var placement = PlacementResolver.Choose(setup, options.Placement);
        if (options.Pose == PosePolicy.Placement) return new(placement, null, PoseProvenance.Placement(PosePolicy.Placement.Name()));
        var walk = new Walk(setup, motions, diagnostics);
        return walk.Run(options, placement);
    }

    /// <summary>One Setup's way through the creation steps, keeping what the current animation came from.</summary>
    private sealed class Walk(Setup setup, IMotionSource? motions, List<Diagnostic> diagnostics)
    {
        private AnimationCursor? _current;
        private string _source = PoseProvenance.PlacementSource;
        private uint? _tableId, _style, _substate, _animationId;
        private string? _from;

        public ResolvedPose Run(PoseSettings options, PlacementFrame? placement)
        {
            if (setup.DefaultAnimation != 0 && Start(new AnimData(setup.DefaultAnimation, 0, -1, 30f), $"DefaultAnimation 0x{setup.DefaultAnimation:X8}") is { } first)
                SetCurrent(first, PoseProvenance.DefaultAnimationSource, null, null, null, null, setup.DefaultAnimation);

            var door = DoorCatalog.Find(setup.Id);
            var tables = new List<(uint Id, string From)>();
            if (setup.DefaultMotionTable != 0) tables.Add((setup.DefaultMotionTable, "setup"));
            if (options.MotionTable is { } chosen) tables.Add((chosen, "option"));
            else if (door?.MotionTables.FirstOrDefault() is { } catalog and not 0) tables.Add((catalog, "door-catalog"));

            MotionTable? active = null;
            (uint Style, uint Substate)? state = null;
            foreach (var (id, from) in tables)
            {
                // Each table replaces the movement manager, so an earlier table's state is gone even when this one fails.
                state = null;
                active = ReadTable(id, from);
                if (active is not null) state = EnterDefaultState(active, from);
            }
            string? doorState = null;
            var wanted = options.DoorState;
            if (door is not null && tables.Count > 0)
            {
                var taken = active is not null && state is { } s && TakeDoorMotion(active, s, wanted, tables[^1].From);
                if (active is null || state is null)
                    diagnostics.Add(new(PoseDiagnosticCodes.DoorMotion,
                        $"the door cannot take its {wanted.Name()} motion: its motion table has no default state, so retail refuses every motion"));
                // Retail refuses the open motion (CMotionInterp fails it), so the door stays as created: closed,
                // and not ethereal on its account. The file says what retail shows, not what was asked.
                if (!taken && wanted == DoorState.Open)
                {
                    wanted = DoorState.Closed;
                    diagnostics.Add(new(PoseDiagnosticCodes.DoorMotion,
                        "--state open: retail refuses this door's open motion, so it stays closed: written as closed (doorState \"closed\", not ethereal)"));
                }
                doorState = wanted.Name();
            }
            var ethereal = door is not null && wanted == DoorState.Open;
            if (ethereal)
                diagnostics.Add(new(PoseDiagnosticCodes.OpenDoorEthereal,
                    "an open door is ethereal in retail (no collision until it closes): these shapes are for testing, not for blocking"));

            var frames = CurrentPartFrames();
            var provenance = frames is null
                ? new PoseProvenance(PosePolicy.Retail.Name(), PoseProvenance.PlacementSource, null, null, null, null, null, null, doorState, ethereal, false)
                : new PoseProvenance(PosePolicy.Retail.Name(), _source, _tableId, _from, _style, _substate, _animationId, _current!.Value.Frame, doorState, ethereal, false);
            return new ResolvedPose(placement, frames, provenance);
        }

        private void SetCurrent(AnimationCursor cursor, string source, uint? table, string? from, uint? style, uint? substate, uint animation)
        {
            _current = cursor;
            (_source, _tableId, _from, _style, _substate, _animationId) = (source, table, from, style, substate, animation);
        }

        private MotionTable? ReadTable(uint id, string from)
        {
            var named = from switch { "setup" => "the Setup's DefaultMotionTable", "option" => "--motion-table", _ => "the door catalog" };
            try
            {
                var table = motions?.ReadMotionTable(id);
                if (table is null)
                    diagnostics.Add(new(PoseDiagnosticCodes.MissingMotionTable, $"MotionTable 0x{id:X8} ({named}) is not in the dat: it gives no default state"));
                return table;
            }
            catch (DatFormatException e)
            {
                diagnostics.Add(new(PoseDiagnosticCodes.UnreadableMotionTable, $"MotionTable 0x{id:X8} ({named}) cannot be read: {e.Message}"));
                return null;
            }
        }

        /// <summary>CMotionTable::SetDefaultState: the default style's default substate's cycle, or failure with the sequence untouched.</summary>
        private (uint, uint)? EnterDefaultState(MotionTable table, string from)
        {
            var style = table.DefaultStyle;
            if (!table.TryGetStyleDefault(style, out var substate))
            {
                diagnostics.Add(new(PoseDiagnosticCodes.NoDefaultState,
                    $"MotionTable 0x{table.Id:X8} has no default substate for its default style 0x{style:X8}: its default state fails and the pose stays {Fallback}"));
                return null;
            }
            var key = MotionCommand.Key(style, substate);
            if (table.FindCycle(key) is not { } cycle)
            {
                diagnostics.Add(new(PoseDiagnosticCodes.NoDefaultState,
                    $"MotionTable 0x{table.Id:X8} has no cycle for its default state (style 0x{style:X8}, substate 0x{substate:X8}, key 0x{key:X8}): its default state fails and the pose stays {Fallback}"));
                return null;
            }
            _current = null;
            _source = PoseProvenance.PlacementSource;
            if (cycle.Anims.Count == 0)
                diagnostics.Add(new(PoseDiagnosticCodes.NoDefaultState,
                    $"MotionTable 0x{table.Id:X8}'s default cycle (key 0x{key:X8}) has no animations: the sequence is cleared and nothing replaces it"));
            foreach (var data in cycle.Anims)
                if (Start(data, $"MotionTable 0x{table.Id:X8} cycle 0x{key:X8}") is { } node && _current is null)
                    SetCurrent(node, PoseProvenance.MotionTableSource, table.Id, from, style, substate, data.AnimId);
            return (style, substate);
        }

        /// <summary>
        /// CMotionTable::GetObjectSequence for the door's substate: nothing changes when the door is already in
        /// it; else the cycle under the current style (falling back to the default style) plays after its link,
        /// and the pose it settles in is the cycle's last animation at its starting frame.
        /// </summary>
        /// <summary>Whether the door took the motion (is now in the wanted state's pose).</summary>
        private bool TakeDoorMotion(MotionTable table, (uint Style, uint Substate) state, DoorState wanted, string from)
        {
            var command = wanted == DoorState.Closed ? MotionCommand.Off : MotionCommand.On;
            if (state.Substate == command && _current is not null) return true;
            var cycle = table.FindCycle(MotionCommand.Key(state.Style, command)) ?? table.FindCycle(MotionCommand.Key(table.DefaultStyle, command));
            if (cycle is null || cycle.Anims.Count == 0)
            {
                diagnostics.Add(new(PoseDiagnosticCodes.DoorMotion,
                    $"MotionTable 0x{table.Id:X8} has no {wanted.Name()} cycle (command 0x{command:X8}) with animations under style 0x{state.Style:X8}: the door keeps its default-state pose"));
                return false;
            }
            for (var i = cycle.Anims.Count - 1; i >= 0; i--)
                if (Start(cycle.Anims[i], $"MotionTable 0x{table.Id:X8} {wanted.Name()} cycle") is { } settled)
                {
                    SetCurrent(settled, PoseProvenance.MotionTableSource, table.Id, from, state.Style, command, cycle.Anims[i].AnimId);
                    return true;
                }
            return false;
        }

        /// <summary>CSequence::append_animation drops a node whose animation is not there.</summary>
        private AnimationCursor? Start(AnimData data, string named)
        {
            try
            {
                if (motions?.ReadAnimation(data.AnimId) is { } animation) return AnimationCursor.Start(animation, data);
                diagnostics.Add(new(PoseDiagnosticCodes.MissingAnimation, $"Animation 0x{data.AnimId:X8} ({named}) is not in the dat: retail drops it from the sequence"));
            }
            catch (DatFormatException e)
            {
                diagnostics.Add(new(PoseDiagnosticCodes.UnreadableAnimation, $"Animation 0x{data.AnimId:X8} ({named}) cannot be read: {e.Message}"));
            }
            return null;
        }

        private static string Unposed(int first, int count) => first == count - 1 ? $"part {first}" : $"parts {first}-{count - 1}";

        private string Fallback => _current is null ? "the placement pose" : "where the DefaultAnimation put it";

        private IReadOnlyList<Frame>? CurrentPartFrames()
        {
            if (_current is not { } cursor) return null;
            if (cursor.PartFrame is not { } frame)
            {
                diagnostics.Add(new(PoseDiagnosticCodes.AnimationFrame,
                    $"Animation 0x{cursor.Animation.Id:X8} has {cursor.Animation.PartFrames.Count} frame(s), so frame {cursor.Frame} gives no part frames: the parts keep the placement pose"));
                return null;
            }
            if (frame.Frames.Count < setup.Parts.Count)
                diagnostics.Add(new(PoseDiagnosticCodes.AnimationParts,
                    $"Animation 0x{cursor.Animation.Id:X8} has part frames for {frame.Frames.Count} of the Setup's {setup.Parts.Count} parts: retail never places {Unposed(frame.Frames.Count, setup.Parts.Count)} on a new object, so the placement pose stands in"));
            return frame.Frames;
        }
    }
}
