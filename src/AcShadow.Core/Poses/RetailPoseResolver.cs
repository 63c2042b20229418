using AcShadow.Core.Catalog;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Poses;

/// <summary>
/// The pose retail gives a Setup's parts once it has created the object and put it in the world
/// (CPartArray::InitDefaults, CPhysicsObj::InitDefaults, CMotionTable::SetDefaultState and GetObjectSequence,
/// CPhysicsObj::enter_world, CPartArray::UpdateParts), played on a model of the client's sequence:
/// <list type="number">
/// <item>DefaultAnimation, when the Setup has one, is appended to the sequence.</item>
/// <item>Each motion table the object is given, in order (the Setup's DefaultMotionTable, then the weenie's:
/// `--motion-table`, else the door catalog's), enters its default state: DefaultStyle, StyleDefaults[DefaultStyle],
/// Cycles[(style &lt;&lt; 16) | substate]. Success clears the sequence and appends the cycle's animations. A
/// missing entry fails and leaves the sequence as it was.</item>
/// <item>A door then takes the motion state the server sends (closed = NonCombat + Off, open = NonCombat + On):
/// the NonCombat style command first, then the substate (CMotionInterp::apply_interpreted_movement).</item>
/// <item>Entering the world drops every link animation (CSequence::remove_all_link_animations): the last
/// animation appended is current, at its starting frame. An animation missing from the dat never joined the
/// sequence (CSequence::append_animation drops its node).</item>
/// <item>The current animation frame poses the parts it has frames for; the rest keep the frame they were made
/// with (origin, no rotation). With no current animation the placement frame poses them all.</item>
/// </list>
/// Whatever is missing (a table, a key, an animation, a frame, part frames) is a diagnostic.
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

    /// <summary>What appended a sequence node: the pose's provenance when that node is current.</summary>
    private sealed record Origin(string Source, uint? TableId, string? From, uint? Style, uint? Substate, uint AnimationId);

    /// <summary>One Setup's way through the creation steps.</summary>
    private sealed class Walk(Setup setup, IMotionSource? motions, List<Diagnostic> diagnostics)
    {
        private readonly AnimationSequence<Origin> _sequence = new();

        public ResolvedPose Run(PoseSettings options, PlacementFrame? placement)
        {
            if (setup.DefaultAnimation != 0)
                Append(new AnimData(setup.DefaultAnimation, 0, -1, 30f),
                    new Origin(PoseProvenance.DefaultAnimationSource, null, null, null, null, setup.DefaultAnimation), $"DefaultAnimation 0x{setup.DefaultAnimation:X8}");

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
                var taken = active is not null && state is { } s && TakeDoorState(active, s, wanted, tables[^1].From);
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

            // CPhysicsObj::enter_world → MotionTableManager::HandleEnterWorld: the link animations go, so the last
            // animation appended (first_cyclic) is current at its starting frame.
            _sequence.RemoveAllLinkAnimations();
            var frames = CurrentPartFrames();
            var provenance = frames is null || _sequence.Current is not { Origin: var origin }
                ? new PoseProvenance(PosePolicy.Retail.Name(), PoseProvenance.PlacementSource, null, null, null, null, null, null, doorState, ethereal, false)
                : new PoseProvenance(PosePolicy.Retail.Name(), origin.Source, origin.TableId, origin.From, origin.Style, origin.Substate, origin.AnimationId, _sequence.Frame, doorState, ethereal, false);
            return new ResolvedPose(placement, frames, provenance);
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
            _sequence.Clear();
            if (cycle.Anims.Count == 0)
                diagnostics.Add(new(PoseDiagnosticCodes.NoDefaultState,
                    $"MotionTable 0x{table.Id:X8}'s default cycle (key 0x{key:X8}) has no animations: the sequence is cleared and nothing replaces it"));
            AddMotion(table, from, cycle, style, substate, $"cycle 0x{key:X8}");
            return (style, substate);
        }

        /// <summary>
        /// The state the server sends a door (ACE Door: NonCombat with Off, or with On) reaches the client's
        /// CMotionInterp::apply_interpreted_movement: the style command first, then the substate, each through
        /// CMotionTable::GetObjectSequence. The object is in no cell yet, so CMotionInterp::DoInterpretedMotion
        /// drops each motion's link animations at once. True when the door is in the wanted state.
        /// </summary>
        private bool TakeDoorState(MotionTable table, (uint Style, uint Substate) state, DoorState wanted, string from)
        {
            state = TakeStyle(table, state, from);
            _sequence.RemoveAllLinkAnimations();
            var taken = TakeSubstate(table, state, wanted, from);
            _sequence.RemoveAllLinkAnimations();
            return taken;
        }

        /// <summary>
        /// GetObjectSequence for the NonCombat style command: nothing when the door is already in NonCombat; else
        /// the style's default substate cycle (Cycles[NonCombat, StyleDefaults[NonCombat]]) after the links out of
        /// the current state, or failure (state and sequence untouched) when the table has no such cycle.
        /// </summary>
        private (uint Style, uint Substate) TakeStyle(MotionTable table, (uint Style, uint Substate) state, string from)
        {
            const uint style = MotionCommand.NonCombat;
            if (state.Style == style) return state;
            if (!table.TryGetStyleDefault(style, out var substate) || table.FindCycle(MotionCommand.Key(style, substate)) is not { } cycle)
            {
                diagnostics.Add(new(PoseDiagnosticCodes.DoorMotion,
                    $"MotionTable 0x{table.Id:X8} has no NonCombat default cycle: the door's NonCombat style command fails and it stays in style 0x{state.Style:X8}"));
                return state;
            }
            var styleDefault = table.TryGetStyleDefault(state.Style, out var d) ? d : 0;
            var preLink = state.Substate != styleDefault ? Link(table, state.Style, state.Substate, styleDefault) : null;
            var link = Link(table, state.Style, styleDefault, style);
            MotionData? secondLink = null;
            if (link is null)
            {
                // No direct link: through the table's default style (CMotionTable::GetObjectSequence's two-step link).
                link = Link(table, state.Style, styleDefault, table.DefaultStyle);
                secondLink = Link(table, table.DefaultStyle, table.TryGetStyleDefault(table.DefaultStyle, out var s) ? s : 0, style);
            }
            _sequence.RemoveCyclicAnims();
            foreach (var data in new[] { preLink, link, secondLink, cycle })
                AddMotion(table, from, data, style, substate, "NonCombat style command");
            return (style, substate);
        }

        /// <summary>
        /// GetObjectSequence for the door's substate (closed = Off, open = On): the cycle under the current style,
        /// else under the default style; none (or one that may not be entered from here) fails with the sequence
        /// untouched. Already in it: only speeds change. Else the cycle plays after its link.
        /// </summary>
        private bool TakeSubstate(MotionTable table, (uint Style, uint Substate) state, DoorState wanted, string from)
        {
            var command = wanted == DoorState.Closed ? MotionCommand.Off : MotionCommand.On;
            var cycle = table.FindCycle(MotionCommand.Key(state.Style, command)) ?? table.FindCycle(MotionCommand.Key(table.DefaultStyle, command));
            var styleDefault = table.TryGetStyleDefault(state.Style, out var d) ? d : 0;
            // CMotionTable::is_allowed: a cycle with bitfield bit 0x2 is entered only from the style's default substate.
            if (cycle is null || ((cycle.Bitfield & 2) != 0 && command != state.Substate && styleDefault != state.Substate))
            {
                diagnostics.Add(new(PoseDiagnosticCodes.DoorMotion,
                    $"MotionTable 0x{table.Id:X8} has no {wanted.Name()} cycle (command 0x{command:X8}) it may enter under style 0x{state.Style:X8}: the door keeps its pose"));
                return false;
            }
            if (command == state.Substate && _sequence.HasAnims) return true;
            var link = Link(table, state.Style, state.Substate, command);
            MotionData? secondLink = null;
            if (link is null)
            {
                link = Link(table, state.Style, state.Substate, styleDefault);
                secondLink = Link(table, state.Style, styleDefault, command);
            }
            _sequence.RemoveCyclicAnims();
            var appended = AddMotion(table, from, link, state.Style, command, $"{wanted.Name()} link");
            appended += AddMotion(table, from, secondLink, state.Style, command, $"{wanted.Name()} link");
            if (AddMotion(table, from, cycle, state.Style, command, $"{wanted.Name()} cycle") == 0)
                diagnostics.Add(new(PoseDiagnosticCodes.DoorMotion,
                    $"MotionTable 0x{table.Id:X8}'s {wanted.Name()} cycle plays no animation in the dat: retail drops the old cycle and the door is left {(appended > 0 ? "on its link's last animation" : "with no animation")}"));
            return true;
        }

        /// <summary>CMotionTable::get_link at forward speeds: Links[(style, from)][to], else Links[style &lt;&lt; 16][to].</summary>
        private static MotionData? Link(MotionTable table, uint style, uint from, uint to) =>
            table.FindLink(MotionCommand.Key(style, from), to) ?? table.FindLink(unchecked(style << 16), to);

        /// <summary>add_motion: appends each AnimData of the motion in order; returns how many joined the sequence.</summary>
        private int AddMotion(MotionTable table, string from, MotionData? data, uint style, uint substate, string named)
        {
            var appended = 0;
            foreach (var anim in data?.Anims ?? [])
                if (Append(anim, new Origin(PoseProvenance.MotionTableSource, table.Id, from, style, substate, anim.AnimId), $"MotionTable 0x{table.Id:X8} {named}"))
                    appended++;
            return appended;
        }

        /// <summary>CSequence::append_animation drops a node whose animation is not there.</summary>
        private bool Append(AnimData data, Origin origin, string named)
        {
            try
            {
                if (motions?.ReadAnimation(data.AnimId) is { } animation)
                {
                    _sequence.Append(AnimationNode.From(animation, data), origin);
                    return true;
                }
                diagnostics.Add(new(PoseDiagnosticCodes.MissingAnimation, $"Animation 0x{data.AnimId:X8} ({named}) is not in the dat: retail drops it from the sequence"));
            }
            catch (DatFormatException e)
            {
                diagnostics.Add(new(PoseDiagnosticCodes.UnreadableAnimation, $"Animation 0x{data.AnimId:X8} ({named}) cannot be read: {e.Message}"));
            }
            return false;
        }

        private static string Unposed(int first, int count) => first == count - 1 ? $"part {first}" : $"parts {first}-{count - 1}";

        private string Fallback => _sequence.Current is null ? "the placement pose" : "where the DefaultAnimation put it";

        /// <summary>
        /// CPartArray::UpdateParts poses min(Setup parts, frame parts) parts. Its first call (CPhysicsObj::InitObjectEnd)
        /// already has the animation current (CPartArray::SetPlacementFrame before it only stores the placement frame),
        /// so a part past the animation's part frames keeps the frame CPhysicsPart was made with: origin 0, no rotation.
        /// </summary>
        private IReadOnlyList<Frame>? CurrentPartFrames()
        {
            if (_sequence.Current is not { Node: var node }) return null;
            if (node.PartFrameAt(_sequence.Frame) is not { } frame)
            {
                diagnostics.Add(new(PoseDiagnosticCodes.AnimationFrame,
                    $"Animation 0x{node.Animation.Id:X8} has {node.Animation.PartFrames.Count} frame(s), so frame {_sequence.Frame} gives no part frames: the parts keep the placement pose"));
                return null;
            }
            var count = setup.Parts.Count;
            if (frame.Frames.Count >= count) return frame.Frames;
            diagnostics.Add(new(PoseDiagnosticCodes.AnimationParts,
                $"Animation 0x{node.Animation.Id:X8} has part frames for {frame.Frames.Count} of the Setup's {count} parts: retail never places {Unposed(frame.Frames.Count, count)}; "
                + "a part never placed keeps the frame it was made with (origin 0, no rotation), written here in the object's frame"));
            return [.. frame.Frames, .. Enumerable.Repeat(Frame.Identity, count - frame.Frames.Count)];
        }
    }
}
