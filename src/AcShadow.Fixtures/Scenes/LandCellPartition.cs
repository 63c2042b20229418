using System.Numerics;

namespace AcShadow.Fixtures.Scenes;

/// <summary>
/// A scene's outdoor land cells (24 m squares, 8 x 8 per landblock; the grid runs on into the neighbouring
/// landblocks as far as something registered reaches, as the client's cell lists cross landblock edges), each
/// listing the entries (a scene's objects, then its indoor cells) whose bound reaches it.
/// <list type="bullet">
/// <item>An entry is registered in every land cell its bound's footprint covers: the cells
/// CPhysicsObj::calc_cross_cells_static puts a static object's shadow in (find_bbox_cell_list over its parts'
/// box; a CylSphere object, find_cell_list over its spheres).</item>
/// <item>A mover sphere is asked of the land cells CObjCell::find_cell_list gives it outdoors
/// (add_all_outside_cells: its own land cell, and each neighbour, diagonals included, whose edge it is within
/// r of — check_add_cell_boundary).</item>
/// </list>
/// Both footprints are padded (<see cref="Pad"/>) beyond the float rounding of the bound tests the entries
/// make themselves, the mover's radius first stretched by the factor an entry's bound test puts on it. Two
/// ranges, so that a few stretched entries do not widen every query: the plain entries (stretch at most
/// <see cref="PlainStretch"/>: spheres, trees, a part's reach, a not quite unit quaternion) are found with the
/// radius times their largest stretch, the stretched ones (a CylSphere's box profile reaches √2·r past its
/// object's sphere, <see cref="Collision.BoundStretch"/>) with the radius times theirs. So a sphere whose
/// exhaustive bound test passes always shares a land cell of its range with the entry: the partition only skips
/// entries that cannot answer, and answers are the exhaustive walk's, bit for bit.
/// An entry asked in several of the mover's cells is asked once (in the first cell, y then x, of the overlap of
/// its footprint and its range), plain and stretched entries in one walk over the cells, in each cell's order.
/// An entry whose bound is missing, not finite or wider than <see cref="MaxSpan"/> cells is asked everywhere.
/// A mover's plain range is at most 3 x 3 cells while its radius is under a cell (every mover the scenes declare),
/// its stretched range at most one cell wider each side: for each such pair of ranges the walk's candidates
/// (deduplicated, in the walk's order) are one flat array built here, so a query is one index and one loop;
/// other ranges walk the cells' lists, with the same answers.
/// </summary>
internal sealed class LandCellPartition
{
    /// <summary>A land cell's side in metres (LandDefs: 8 cells of 24 m per 192 m landblock).</summary>
    public const double CellSize = 24.0;

    /// <summary>Footprints wider than this many cells are asked at every position instead.</summary>
    public const int MaxSpan = 16;

    /// <summary>
    /// The widest stretch an entry may put on the mover's radius and still be found by the plain range: a part's
    /// reach (1 + 1e-4 over its turn's least σ) and a quaternion a little off unit (1 + 4 |1 − |q|²|) stay under it;
    /// a CylSphere's √2 does not.
    /// </summary>
    public const float PlainStretch = 1.01f;

    /// <summary>How far from the landblock, in cells, the grid may run; beyond it an entry is asked everywhere.</summary>
    private const int MaxReach = 64;

    /// <summary>The widest mover range, in cells a side, that has a flat candidate array.</summary>
    private const int FlatSpan = 3;

    private readonly int _x0, _y0, _width, _height;
    private readonly float _plainStretch, _wideStretch;
    private readonly int[][] _cells;
    private readonly bool[] _cellHoldsStretched;
    private readonly int[] _everywhere;
    private readonly CellRange[] _footprints;
    private readonly bool[] _stretched;
    /// <summary>Flat arrays per plain range: 1, or (stretched entries present) 16, one per side the stretched range reaches a cell further.</summary>
    private readonly int _widenings;
    private readonly int[]?[] _ranges;

    /// <summary>Land cells x0..x1 by y0..y1, inclusive (cell i spans [24 i, 24 (i + 1)) metres).</summary>
    public readonly record struct CellRange(int X0, int Y0, int X1, int Y1)
    {
        public bool Meets(CellRange other) => X0 <= other.X1 && other.X0 <= X1 && Y0 <= other.Y1 && other.Y0 <= Y1;

        public bool Holds(int x, int y) => X0 <= x && x <= X1 && Y0 <= y && y <= Y1;

        public int Cells => (X1 - X0 + 1) * (Y1 - Y0 + 1);
    }

    /// <summary>What the partition asks of an entry; a struct, so the walk is compiled per caller without a delegate.</summary>
    public interface IEntryTest
    {
        /// <summary>Asks entry <paramref name="entry"/>; true ends the walk (the entry blocks).</summary>
        bool Test(int entry);

        /// <summary>Told of each candidate list the walk loads: one flat array, or each land cell's list (a counted cost may weigh it).</summary>
        void Visit();
    }

    public int Entries => _footprints.Length;

    /// <summary>How many entries are asked at every position (no footprint).</summary>
    public int Everywhere => _everywhere.Length;

    /// <summary>How many entries are found by the stretched range.</summary>
    public int Stretched => _stretched.Count(s => s);

    /// <summary>How many land cells hold at least one entry.</summary>
    public int OccupiedCells => _cells.Count(c => c.Length > 0);

    private LandCellPartition(int x0, int y0, int width, int height, int[][] cells, int[] everywhere, CellRange[] footprints, bool[] stretched,
        float plainStretch, float wideStretch)
    {
        (_x0, _y0, _width, _height) = (x0, y0, width, height);
        (_plainStretch, _wideStretch) = (plainStretch, wideStretch);
        _cells = cells;
        _everywhere = everywhere;
        _footprints = footprints;
        _stretched = stretched;
        _cellHoldsStretched = [.. cells.Select(c => c.Any(e => stretched[e]))];
        _widenings = stretched.Any(s => s) ? 16 : 1;
        _ranges = FlatRanges();
    }

    /// <summary>
    /// For every plain range of at most <see cref="FlatSpan"/> x <see cref="FlatSpan"/> cells inside the grid, and
    /// every widening of it the stretched range can take inside the grid, the entries the cell-by-cell walk asks
    /// there, in its order, each once (index: <see cref="FlatIndex"/>; null where the widening leaves the grid).
    /// </summary>
    private int[]?[] FlatRanges()
    {
        var ranges = new int[]?[_width * _height * FlatSpan * FlatSpan * _widenings];
        var listed = new Listed([]);
        for (var y0 = _y0; y0 < _y0 + _height; y0++)
            for (var x0 = _x0; x0 < _x0 + _width; x0++)
                for (var h = 1; h <= FlatSpan; h++)
                    for (var w = 1; w <= FlatSpan; w++)
                    {
                        var q = new CellRange(x0, y0, x0 + w - 1, y0 + h - 1);
                        if (q.X1 >= _x0 + _width || q.Y1 >= _y0 + _height) continue;
                        int[] unwidened = [];
                        for (var widening = 0; widening < _widenings; widening++)
                        {
                            var wide = Widened(q, widening);
                            if (wide.X0 < _x0 || wide.Y0 < _y0 || wide.X1 >= _x0 + _width || wide.Y1 >= _y0 + _height) continue;
                            listed.Entries.Clear();
                            Walk(q, true, wide, ref listed);
                            int[] list = listed.Entries.Count == 0 ? [] : [.. listed.Entries];
                            if (widening == 0) unwidened = list;
                            // Most widenings reach no further stretched entry: they share the plain range's array.
                            ranges[FlatIndex(q, widening)] = list.AsSpan().SequenceEqual(unwidened) ? unwidened : list;
                        }
                    }
        return ranges;
    }

    /// <summary>Range <paramref name="q"/> a cell wider on each side whose bit is set: 1 west, 2 east, 4 south, 8 north.</summary>
    private static CellRange Widened(CellRange q, int widening) =>
        new(q.X0 - (widening & 1), q.Y0 - (widening >> 2 & 1), q.X1 + (widening >> 1 & 1), q.Y1 + (widening >> 3 & 1));

    private int FlatIndex(CellRange q, int widening) =>
        ((((q.Y0 - _y0) * _width + (q.X0 - _x0)) * FlatSpan + (q.Y1 - q.Y0)) * FlatSpan + (q.X1 - q.X0)) * _widenings + widening;

    /// <summary>Is (x, y) the first cell, y then x, that entry <paramref name="e"/>'s footprint and range <paramref name="q"/> share.</summary>
    private bool IsFirstShared(int e, CellRange q, int x, int y)
    {
        ref readonly var f = ref _footprints[e];
        return x == Math.Max(f.X0, q.X0) && y == Math.Max(f.Y0, q.Y0);
    }

    /// <summary>
    /// The partition of entries with these landblock-relative bounds (null: asked everywhere), each putting its
    /// stretch (<paramref name="stretches"/>, in the same order; none: 1) on the mover's radius
    /// (<see cref="PlacedQuery.RadiusStretch"/>). Entry order is kept within every cell's list.
    /// </summary>
    public static LandCellPartition Build(IReadOnlyList<(Vector3 Center, float Radius)?> bounds, IReadOnlyList<float>? stretches = null)
    {
        if (stretches is not null && stretches.Count != bounds.Count)
            throw new ArgumentException($"{stretches.Count} stretches for {bounds.Count} bounds", nameof(stretches));
        foreach (var s in stretches ?? [])
            if (!(s >= 1f) || !float.IsFinite(s)) throw new ArgumentOutOfRangeException(nameof(stretches), s, "a radius stretch is finite and at least 1");
        var footprints = new CellRange[bounds.Count];
        var stretched = new bool[bounds.Count];
        float plainStretch = 1f, wideStretch = 1f;
        var everywhere = new List<int>();
        int x0 = int.MaxValue, y0 = int.MaxValue, x1 = int.MinValue, y1 = int.MinValue;
        for (var i = 0; i < bounds.Count; i++)
        {
            if (bounds[i] is not { } b || Footprint(b.Center, b.Radius) is not { } f)
            {
                footprints[i] = new CellRange(0, 0, -1, -1);
                everywhere.Add(i);
                continue;
            }
            footprints[i] = f;
            var stretch = stretches?[i] ?? 1f;
            stretched[i] = stretch > PlainStretch;
            if (stretched[i]) wideStretch = MathF.Max(wideStretch, stretch);
            else plainStretch = MathF.Max(plainStretch, stretch);
            (x0, y0, x1, y1) = (Math.Min(x0, f.X0), Math.Min(y0, f.Y0), Math.Max(x1, f.X1), Math.Max(y1, f.Y1));
        }
        wideStretch = MathF.Max(wideStretch, plainStretch);
        if (x0 > x1) return new LandCellPartition(0, 0, 0, 0, [], [.. everywhere], footprints, stretched, plainStretch, wideStretch);
        int width = x1 - x0 + 1, height = y1 - y0 + 1;
        var lists = new List<int>[width * height];
        for (var i = 0; i < footprints.Length; i++)
        {
            var f = footprints[i];
            if (f.X0 > f.X1) continue;
            for (var y = f.Y0; y <= f.Y1; y++)
                for (var x = f.X0; x <= f.X1; x++)
                    (lists[(y - y0) * width + (x - x0)] ??= []).Add(i);
        }
        return new LandCellPartition(x0, y0, width, height, [.. lists.Select(l => l is null ? [] : l.ToArray())], [.. everywhere], footprints, stretched,
            plainStretch, wideStretch);
    }

    /// <summary>
    /// Asks <paramref name="test"/> each entry the sphere's land cells hold (entries asked everywhere first),
    /// each once; true as soon as one answers true.
    /// </summary>
    public bool Any<T>(Vector3 center, float radius, ref T test) where T : struct, IEntryTest
    {
        foreach (var e in _everywhere)
            if (test.Test(e)) return true;
        if (!Ranges(center, radius, out var plain, out var plainMet, out var wide)) return false;
        if (plainMet && plain.X1 - plain.X0 < FlatSpan && plain.Y1 - plain.Y0 < FlatSpan
            && plain.X0 - wide.X0 <= 1 && plain.Y0 - wide.Y0 <= 1 && wide.X1 - plain.X1 <= 1 && wide.Y1 - plain.Y1 <= 1)
        {
            var widening = (plain.X0 - wide.X0) | (wide.X1 - plain.X1) << 1 | (plain.Y0 - wide.Y0) << 2 | (wide.Y1 - plain.Y1) << 3;
            test.Visit();
            foreach (var e in _ranges[FlatIndex(plain, widening)]!)
                if (test.Test(e)) return true;
            return false;
        }
        return Walk(plain, plainMet, wide, ref test);
    }

    /// <summary>
    /// The cell-by-cell walk over the stretched range (the plain one within it): each cell holding an entry either
    /// range asks, each such entry in the cell's order, asked in the first cell its footprint and its own range share.
    /// </summary>
    private bool Walk<T>(CellRange plain, bool plainMet, CellRange wide, ref T test) where T : struct, IEntryTest
    {
        for (var y = wide.Y0; y <= wide.Y1; y++)
            for (var x = wide.X0; x <= wide.X1; x++)
            {
                var cell = (y - _y0) * _width + (x - _x0);
                var inPlain = plainMet && plain.Holds(x, y);
                if (!inPlain && !_cellHoldsStretched[cell]) continue;
                test.Visit();
                foreach (var e in _cells[cell])
                    if ((_stretched[e] ? IsFirstShared(e, wide, x, y) : inPlain && IsFirstShared(e, plain, x, y)) && test.Test(e)) return true;
            }
        return false;
    }

    /// <summary>Can the sphere reach entry <paramref name="entry"/>: is it asked everywhere, or does its footprint meet its range?</summary>
    public bool Reaches(int entry, Vector3 center, float radius)
    {
        var f = _footprints[entry];
        if (f.X0 > f.X1) return true;
        return Reach(center, radius, out var q, _stretched[entry]) && f.Meets(q);
    }

    /// <summary>
    /// The land cells of the grid a mover sphere asks the plain entries in, or (<paramref name="stretched"/>) the
    /// stretched ones (false: none, the range is beyond every footprint).
    /// </summary>
    public bool Reach(Vector3 center, float radius, out CellRange cells, bool stretched = false)
    {
        cells = default;
        if (!Ranges(center, radius, out var plain, out var plainMet, out var wide)) return false;
        if (stretched)
        {
            cells = wide;
            return true;
        }
        cells = plain;
        return plainMet;
    }

    /// <summary>
    /// The sphere's plain range (<paramref name="plainMet"/>: it meets the grid) and its stretched range, which holds it;
    /// false when the stretched range misses the grid. Without stretched entries both are the plain range.
    /// </summary>
    private bool Ranges(Vector3 center, float radius, out CellRange plain, out bool plainMet, out CellRange wide)
    {
        (plain, plainMet, wide) = (default, false, default);
        if (_width == 0 || !float.IsFinite(center.X) || !float.IsFinite(center.Y) || !float.IsFinite(radius) || radius < 0f) return false;
        double plainPad = Pad(radius * _plainStretch), widePad = _widenings == 1 ? plainPad : Pad(radius * _wideStretch);
        if (!(widePad < CellSize))
        {
            plainMet = Clamped(center, plainPad, out plain);
            wide = plain;
            return _widenings == 1 ? plainMet : Clamped(center, widePad, out wide);
        }
        // Both ranges under a cell's side, by one formula so that the stretched range holds the plain one: the
        // centre's cell, found once, and each neighbour whose edge is nearer than the pad (check_add_cell_boundary).
        double cellX = Math.Floor(center.X / CellSize), cellY = Math.Floor(center.Y / CellSize);
        double intoX = center.X - cellX * CellSize, intoY = center.Y - cellY * CellSize;
        plainMet = Neighbours(cellX, cellY, intoX, intoY, plainPad, out plain);
        wide = plain;
        return _widenings == 1 ? plainMet : Neighbours(cellX, cellY, intoX, intoY, widePad, out wide);
    }

    /// <summary>Cell (x, y) and each neighbour whose edge is nearer than <paramref name="pad"/> to a centre (intoX, intoY) into it, clamped to the grid.</summary>
    private bool Neighbours(double x, double y, double intoX, double intoY, double pad, out CellRange cells) =>
        Clamped(x - (intoX < pad ? 1 : 0), y - (intoY < pad ? 1 : 0), x + (CellSize - intoX <= pad ? 1 : 0), y + (CellSize - intoY <= pad ? 1 : 0), out cells);

    /// <summary>The grid's cells within <paramref name="pad"/> of the centre's x and y, however wide (false: none).</summary>
    private bool Clamped(Vector3 center, double pad, out CellRange cells) =>
        Clamped(Math.Floor((center.X - pad) / CellSize), Math.Floor((center.Y - pad) / CellSize),
            Math.Floor((center.X + pad) / CellSize), Math.Floor((center.Y + pad) / CellSize), out cells);

    /// <summary>Cells x0..x1 by y0..y1 clamped to the grid (false: they miss it).</summary>
    private bool Clamped(double x0, double y0, double x1, double y1, out CellRange cells)
    {
        cells = default;
        int gx1 = _x0 + _width - 1, gy1 = _y0 + _height - 1;
        if (x1 < _x0 || x0 > gx1 || y1 < _y0 || y0 > gy1) return false;
        cells = new CellRange((int)Math.Max(x0, _x0), (int)Math.Max(y0, _y0), (int)Math.Min(x1, gx1), (int)Math.Min(y1, gy1));
        return true;
    }

    /// <summary>
    /// The land cells a landblock-relative bound covers, padded; null when it is not finite, wider than
    /// <see cref="MaxSpan"/> cells or beyond <see cref="MaxReach"/> cells of the landblock.
    /// </summary>
    public static CellRange? Footprint(Vector3 center, float radius)
    {
        if (!float.IsFinite(center.X) || !float.IsFinite(center.Y) || !float.IsFinite(center.Z) || !float.IsFinite(radius) || radius < 0f) return null;
        var pad = Pad(radius);
        double x0 = Math.Floor((center.X - pad) / CellSize), x1 = Math.Floor((center.X + pad) / CellSize);
        double y0 = Math.Floor((center.Y - pad) / CellSize), y1 = Math.Floor((center.Y + pad) / CellSize);
        if (x1 - x0 >= MaxSpan || y1 - y0 >= MaxSpan) return null;
        if (x0 < -MaxReach || y0 < -MaxReach || x1 > 8 + MaxReach || y1 > 8 + MaxReach) return null;
        return new CellRange((int)x0, (int)y0, (int)x1, (int)y1);
    }

    /// <summary>
    /// A radius widened past every rounding the bound tests can make (float squares and sums: relative 1e-6;
    /// a BSP root's ε of 0.0002 on squared distances: under 0.015 m; an unnormalised cell rotation: under 1e-3
    /// of the distance) — 0.05 m and 1e-3 of the radius. Too wide only costs a cell; too narrow would drop an answer.
    /// </summary>
    private static double Pad(float radius) => radius * 1.001 + 0.05;

    /// <summary>Collects the entries a walk asks, in its order (the flat arrays' build).</summary>
    private readonly struct Listed(List<int> entries) : IEntryTest
    {
        public List<int> Entries => entries;

        public bool Test(int entry)
        {
            entries.Add(entry);
            return false;
        }

        public void Visit() { }
    }
}
