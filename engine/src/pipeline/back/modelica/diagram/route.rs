//! Orthogonal routing on the 5-unit grid. A wire first tries a straight line, an elbow or a Z
//! through a channel near its ends that stays out of every keep-out box and shares no cell with
//! another wire beyond a short trunk at its ends ([`direct`]); otherwise A* over grid points
//! outside every component's keep-out box, with a cost for each bend and for running over a
//! cell another wire already uses, so wires take few bends and spread out. Each end leaves its connector straight out of the
//! component first.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use super::{GridMap, Rect, Sheet, GRID};

type End = (((f64, f64), (i32, i32)), Rect);

const BEND: u32 = 4;
const SHARED: u32 = 3;
/// A* node expansions one wire may use, both windows together. A route that needs more is
/// drawn by [`fallback`] (a long wire: weighted A* expands at least one node per grid step of
/// its route, so a wire whose ends are farther apart than this goes there directly).
pub const WIRE_EXPANSIONS: u64 = 4_000;
/// A* node expansions a sheet may use per wire made (with [`SHEET_EXPANSIONS_START`]): wires
/// that need few leave some for the ones that need more; the total stays linear in the wires.
pub const SHEET_EXPANSIONS_PER_WIRE: u64 = 1_500;
const SHEET_EXPANSIONS_START: u64 = 20_000;
/// Search windows: the bounding box of the two ends grown by this many grid units, then once
/// more by the second.
const WINDOWS: [i32; 2] = [20, 80];
/// The fallback's channels: grid lines at most this far (grid units) from either end.
const REACH: i32 = 8;
/// Straight segments one fallback route may check.
const FALLBACK_CHECKS: u64 = 4_000;

type P = (i32, i32);

fn g(v: f64) -> i32 {
    (v / f64::from(GRID)).round() as i32
}

impl Sheet {
    /// True when grid point (ix, iy) lies strictly inside a component's keep-out box: its
    /// horizontal grid line's intervals (the open x extents of the boxes the line runs strictly
    /// inside) hold its x.
    fn blocked(&self, ix: i32, iy: i32) -> bool {
        super::meets(self.across_h.get(&iy), ix * GRID, ix * GRID)
    }
}

/// The points from a connector out of its component's keep-out box to a grid point.
fn stub(((px, py), (dx, dy)): ((f64, f64), (i32, i32)), rect: &Rect) -> Vec<(f64, f64)> {
    let k = Sheet::keep_out(rect);
    let gf = f64::from(GRID);
    let mut pts = vec![(px, py)];
    if dx != 0 {
        let edge = if dx < 0 { (px.min(f64::from(k.x1)) / gf).floor() * gf } else { (px.max(f64::from(k.x2)) / gf).ceil() * gf };
        pts.push((edge, py));
        pts.push((edge, (py / gf).round() * gf));
    } else {
        let edge = if dy < 0 { (py.min(f64::from(k.y1)) / gf).floor() * gf } else { (py.max(f64::from(k.y2)) / gf).ceil() * gf };
        pts.push((px, edge));
        pts.push(((px / gf).round() * gf, edge));
    }
    pts
}

const DIRS: [(i32, i32); 4] = [(1, 0), (-1, 0), (0, 1), (0, -1)];

/// A cell's state in a search (0: not looked at yet).
const FREE: u8 = 1;
const BLOCKED: u8 = 2;
/// Free, and used by a wire already.
const USED: u8 = 3;

/// Per-search state: dense arrays for a window of up to [`DENSE_CELLS`] cells, hash maps for a
/// larger one (a long wire's window is mostly never visited). The dense arrays are kept per
/// thread between searches and only the entries a search touched are reset after it (a fresh
/// array per wire cost more in clearing memory than the search itself on large sheets). They
/// are all zero when clean, so the memory a search never reaches is never written (the
/// allocator's zeroed pages): a large window costs what the search visits.
///
/// Cells are numbered by tiles of [`TILE`] × [`TILE`] ([`Window::cell`]), and a state's cost and
/// predecessor lie side by side, so the states a search reaches around a grid point share a few
/// pages: numbered row by row, a window 1,000 cells wide put every row of a search on pages of
/// its own, and the first touch of each page (the kernel's zeroing) was a third of the routing.
enum Cells {
    Dense(Dense),
    Sparse { state: GridMap<usize, u8>, nodes: GridMap<usize, [u32; 2]> },
}

/// Dense search state of [`DENSE_CELLS`] cells, zero outside `touched_*`: per cell 0 unknown,
/// 1 free, 2 blocked; per state (cell × 5 + arriving direction) its cost plus one and its
/// predecessor plus one (0: none yet).
struct Dense {
    state: Vec<u8>,
    nodes: Vec<[u32; 2]>,
    touched_cells: Vec<u32>,
    touched_nodes: Vec<u32>,
}

impl Dense {
    fn fresh() -> Dense {
        Dense { state: vec![0; DENSE_CELLS], nodes: vec![[0, 0]; DENSE_CELLS * 5], touched_cells: Vec::new(), touched_nodes: Vec::new() }
    }
}

thread_local! {
    static DENSE_POOL: std::cell::RefCell<Vec<Dense>> = const { std::cell::RefCell::new(Vec::new()) };
}

impl Drop for Cells {
    fn drop(&mut self) {
        if let Cells::Dense(d) = self {
            for &c in &d.touched_cells {
                d.state[c as usize] = 0;
            }
            for &n in &d.touched_nodes {
                d.nodes[n as usize] = [0, 0];
            }
            d.touched_cells.clear();
            d.touched_nodes.clear();
            let clean =
                std::mem::replace(d, Dense { state: Vec::new(), nodes: Vec::new(), touched_cells: Vec::new(), touched_nodes: Vec::new() });
            DENSE_POOL.with(|p| p.borrow_mut().push(clean));
        }
    }
}

/// Cells of the largest dense window: 2^20 (1,024 × 1,024 grid units; 41 MB of address space
/// per routing thread, of which only the pages a search reaches are ever written).
const DENSE_CELLS: usize = 1 << 20;

/// The side of a tile of cells numbered together (a power of two).
const TILE: i32 = 16;
const TILE_BITS: u32 = TILE.trailing_zeros();

/// A search window and the numbering of its cells: tile by tile (tiles row by row), each
/// tile's cells row by row.
#[derive(Clone, Copy)]
struct Window {
    x1: i32,
    y1: i32,
    x2: i32,
    y2: i32,
    /// Tiles per row.
    tiles_x: usize,
    /// Cells per row.
    width: usize,
}

impl Window {
    fn new(win: Rect) -> Window {
        let w = (win.x2 - win.x1 + 1) as usize;
        Window { x1: win.x1, y1: win.y1, x2: win.x2, y2: win.y2, tiles_x: w.div_ceil(TILE as usize), width: w }
    }
    /// Cells the numbering spans (whole tiles).
    fn cells(&self) -> usize {
        let rows = ((self.y2 - self.y1 + 1) as usize).div_ceil(TILE as usize);
        self.tiles_x * rows * (TILE * TILE) as usize
    }
    fn contains(&self, p: P) -> bool {
        self.x1 <= p.0 && p.0 <= self.x2 && self.y1 <= p.1 && p.1 <= self.y2
    }
    fn cell(&self, p: P) -> usize {
        let (lx, ly) = ((p.0 - self.x1) as usize, (p.1 - self.y1) as usize);
        let tile = (ly >> TILE_BITS) * self.tiles_x + (lx >> TILE_BITS);
        let mask = TILE as usize - 1;
        (tile << (2 * TILE_BITS)) + ((ly & mask) << TILE_BITS) + (lx & mask)
    }
    /// The cell's place in the window row by row: what breaks ties between states of equal
    /// cost (the order the search took before the cells were numbered by tiles, so the routes
    /// stay the same).
    fn rank(&self, p: P) -> usize {
        (p.0 - self.x1) as usize + (p.1 - self.y1) as usize * self.width
    }
    fn point(&self, c: usize) -> P {
        let (tile, inside) = (c >> (2 * TILE_BITS), c & ((TILE * TILE) as usize - 1));
        let mask = TILE as usize - 1;
        let lx = ((tile % self.tiles_x) << TILE_BITS) + (inside & mask);
        let ly = ((tile / self.tiles_x) << TILE_BITS) + (inside >> TILE_BITS);
        (self.x1 + lx as i32, self.y1 + ly as i32)
    }
}

impl Cells {
    fn new(cells: usize) -> Cells {
        if cells <= DENSE_CELLS {
            Cells::Dense(DENSE_POOL.with(|p| p.borrow_mut().pop()).unwrap_or_else(Dense::fresh))
        } else {
            Cells::Sparse { state: GridMap::default(), nodes: GridMap::default() }
        }
    }
    fn state(&mut self, c: usize, f: impl FnOnce() -> u8) -> u8 {
        match self {
            Cells::Dense(d) => {
                if d.state[c] == 0 {
                    d.state[c] = f();
                    d.touched_cells.push(c as u32);
                }
                d.state[c]
            }
            Cells::Sparse { state, .. } => *state.entry(c).or_insert_with(f),
        }
    }
    fn best(&self, n: usize) -> u32 {
        match self {
            Cells::Dense(d) => d.nodes[n][0].wrapping_sub(1),
            Cells::Sparse { nodes, .. } => nodes.get(&n).map_or(u32::MAX, |e| e[0]),
        }
    }
    fn from(&self, n: usize) -> u32 {
        match self {
            Cells::Dense(d) => d.nodes[n][1].wrapping_sub(1),
            Cells::Sparse { nodes, .. } => nodes.get(&n).map_or(u32::MAX, |e| e[1]),
        }
    }
    fn set(&mut self, n: usize, cost: u32, prev: u32) {
        match self {
            Cells::Dense(d) => {
                let e = &mut d.nodes[n];
                if *e == [0, 0] {
                    d.touched_nodes.push(n as u32);
                }
                *e = [cost.wrapping_add(1), prev.wrapping_add(1)];
            }
            Cells::Sparse { nodes, .. } => {
                nodes.insert(n, [cost, prev]);
            }
        }
    }
}

/// Weighted A* (the heuristic counts twice: routes are found fast and are short enough) from
/// grid point `s` to `t` within `win` (grid units), expanding at most `limit` nodes; the grid
/// points of the path, and the nodes expanded.
fn search(sheet: &Sheet, s: P, t: P, win: Rect, limit: u64) -> (Option<Vec<P>>, u64) {
    let win = Window::new(win);
    let h = |p: P| 2 * ((p.0 - t.0).abs() + (p.1 - t.1).abs()) as u32;
    // Per cell: 0 unknown, 1 free, 2 blocked. Per state (cell, arriving direction 0..5): best
    // cost and the state it came from.
    let mut cells = Cells::new(win.cells());
    let mut heap = BinaryHeap::new();
    let start = win.cell(s) * 5 + 4;
    cells.set(start, 0, u32::MAX);
    heap.push(Reverse((h(s), 0u32, (win.rank(s) * 5 + 4) as u32, start as u32)));
    let mut expansions = 0u64;
    let goal = win.cell(t);
    while let Some(Reverse((_, cost, _, node))) = heap.pop() {
        let node = node as usize;
        if cells.best(node) < cost {
            continue;
        }
        let (c, dir) = (node / 5, (node % 5) as u8);
        if c == goal {
            let mut path = Vec::new();
            let mut cur = node;
            loop {
                path.push(win.point(cur / 5));
                let prev = cells.from(cur);
                if prev == u32::MAX {
                    break;
                }
                cur = prev as usize;
            }
            path.reverse();
            return (Some(path), expansions);
        }
        if expansions >= limit {
            return (None, expansions);
        }
        expansions += 1;
        let (x, y) = win.point(c);
        for (d, (dx, dy)) in DIRS.iter().enumerate() {
            let d = d as u8;
            // No U-turns.
            if dir != 4 && dir ^ 1 == d {
                continue;
            }
            let (nx, ny) = (x + dx, y + dy);
            if !win.contains((nx, ny)) {
                continue;
            }
            let nc = win.cell((nx, ny));
            // Looked up once per cell and search (wires are marked after it): blocked, or free
            // and whether a wire already uses it.
            let state = cells.state(nc, || {
                if sheet.blocked(nx, ny) {
                    BLOCKED
                } else if sheet.used.contains((nx, ny)) {
                    USED
                } else {
                    FREE
                }
            });
            if state == BLOCKED && nc != goal {
                continue;
            }
            let mut step = 1 + if dir != 4 && dir != d { BEND } else { 0 };
            if state == USED {
                step += SHARED;
            }
            let next = nc * 5 + d as usize;
            let cst = cost + step;
            if cst < cells.best(next) {
                cells.set(next, cst, node as u32);
                heap.push(Reverse((cst + h((nx, ny)), cst, (win.rank((nx, ny)) * 5 + d as usize) as u32, next as u32)));
            }
        }
    }
    (None, expansions)
}

/// Whether every segment of the corner list `pts` is clear (one unit of work per segment
/// checked; the checks stop at the first blocked one).
fn clear_path(sheet: &mut Sheet, pts: &[P]) -> bool {
    pts.windows(2).all(|w| sheet.clear(w[0], w[1]))
}

/// Grid lines near `v`, nearest first: v, v - 1, v + 1, v - 2, ...
fn near(v: i32) -> impl Iterator<Item = i32> + Clone {
    (0..=2 * REACH).map(move |k| if k % 2 == 0 { v + k / 2 } else { v - (k + 1) / 2 })
}

/// A route from `s` to `t` (grid units) that needs no search: the corners of the first clear
/// one of a few orthogonal shapes: an elbow; a Z through a channel (a grid line near one of the
/// ends); five segments through a column near each end and a row near one of them. Each
/// straight segment is checked against the components' keep-out boxes in log time, at most
/// [`FALLBACK_CHECKS`] of them, so its work does not depend on the wire's length.
fn fallback(sheet: &mut Sheet, s: P, t: P) -> Option<Vec<P>> {
    let start = sheet.work;
    let spent = |sheet: &Sheet| sheet.work - start > FALLBACK_CHECKS;
    for corner in [(t.0, s.1), (s.0, t.1)] {
        let pts = vec![s, corner, t];
        if clear_path(sheet, &pts) {
            return Some(pts);
        }
    }
    for c in near(t.0).chain(near(s.0)) {
        let pts = vec![s, (c, s.1), (c, t.1), t];
        if clear_path(sheet, &pts) {
            return Some(pts);
        }
    }
    for r in near(t.1).chain(near(s.1)) {
        let pts = vec![s, (s.0, r), (t.0, r), t];
        if clear_path(sheet, &pts) {
            return Some(pts);
        }
    }
    // Leave along s's row to a column near s, run along it to a row, along that to a column
    // near t, then to t's row; and the same turned by a right angle.
    let firsts: Vec<i32> = near(s.0).filter(|&c| sheet.clear(s, (c, s.1))).collect();
    let lasts: Vec<i32> = near(t.0).filter(|&c| sheet.clear((c, t.1), t)).collect();
    for &c1 in &firsts {
        for r in near(t.1).chain(near(s.1)) {
            if spent(sheet) {
                return None;
            }
            if !sheet.clear((c1, s.1), (c1, r)) {
                continue;
            }
            for &c2 in &lasts {
                let pts = vec![s, (c1, s.1), (c1, r), (c2, r), (c2, t.1), t];
                if clear_path(sheet, &pts[2..5]) {
                    return Some(pts);
                }
            }
        }
    }
    let firsts: Vec<i32> = near(s.1).filter(|&r| sheet.clear(s, (s.0, r))).collect();
    let lasts: Vec<i32> = near(t.1).filter(|&r| sheet.clear((t.0, r), t)).collect();
    for &r1 in &firsts {
        for c in near(t.0).chain(near(s.0)) {
            if spent(sheet) {
                return None;
            }
            if !sheet.clear((s.0, r1), (c, r1)) {
                continue;
            }
            for &r2 in &lasts {
                let pts = vec![s, (s.0, r1), (c, r1), (c, r2), (t.0, r2), t];
                if clear_path(sheet, &pts[2..5]) {
                    return Some(pts);
                }
            }
        }
    }
    None
}

/// Longest direct route (grid units) [`direct`] tries: as long as a search may go
/// ([`WIRE_EXPANSIONS`]; a longer wire goes to [`fallback`]). Its checks cost a unit of work per
/// tile of 16 × 16 cells a candidate passes, at most [`DIRECT_WORK`] per wire.
const DIRECT_CELLS: i32 = WIRE_EXPANSIONS as i32;
/// Work [`direct`] may spend on one wire's candidates before it leaves the wire to the search.
const DIRECT_WORK: u64 = 2_000;
/// Cells a wire may share with other wires next to each of its ends (a trunk: wires fanning out
/// of one connector run side by side out of it, as the search routes them too).
pub(super) const TRUNK: i32 = 8;

/// Whether no wire uses a cell of the corner list `pts`, other than its two ends and the cells
/// of a trunk at either end: up to [`TRUNK`] used cells in a row along the first segment from
/// the first point, and along the last segment to the last; a straight route's trunks must not
/// meet (one unit of work per tile of 16 × 16 cells looked at). Wires from one connector all
/// start at its grid point, so the ends are shared by every route alike and the search charges
/// them alike.
fn unused(sheet: &mut Sheet, pts: &[P]) -> bool {
    let n = pts.len();
    let (s, t) = (pts[0], pts[n - 1]);
    // The end of a segment's trunk at `from`, going towards `to`: the last of the used cells
    // in a row after `from` (at most TRUNK), or `from` itself.
    let trunk = |sheet: &Sheet, from: P, to: P| {
        let (dx, dy) = ((to.0 - from.0).signum(), (to.1 - from.1).signum());
        let len = (to.0 - from.0).abs() + (to.1 - from.1).abs();
        let mut end = from;
        for k in 1..=TRUNK.min(len - 1) {
            let p = (from.0 + k * dx, from.1 + k * dy);
            if !sheet.used.contains(p) {
                break;
            }
            end = p;
        }
        end
    };
    let (first, last) = (trunk(sheet, s, pts[1]), trunk(sheet, t, pts[n - 2]));
    // A straight route whose trunks meet would run on other wires from end to end.
    if n == 2 && (first.0 - s.0).abs() + (first.1 - s.1).abs() + 1 >= (last.0 - s.0).abs() + (last.1 - s.1).abs() {
        return first == s && last == t;
    }
    let mut work = 2;
    // Each segment checked from corner to corner; a trunk's cells are skipped by starting the
    // first segment at its trunk's end (itself skipped), and the last likewise.
    let clear = (0..n - 1).all(|i| {
        let (a, skip_a) = if i == 0 { (first, first) } else { (pts[i], s) };
        let (b, skip_b) = if i == n - 2 { (last, last) } else { (pts[i + 1], t) };
        !sheet.used.any_on(a, b, skip_a, skip_b, &mut work)
    });
    sheet.work += work;
    clear
}

/// A route from `s` to `t` that needs no search: a straight line, one elbow, or two elbows (a Z
/// through a channel near one of the ends), the first that stays out of every keep-out box and
/// shares no cell with another wire but those of a trunk at its ends ([`unused`]), within
/// [`DIRECT_WORK`]. The straight line and the elbows (the only routes with at most one bend, as
/// short as any route) are tried first, then the Zs that go only towards
/// `t` (as short), then those that overshoot (around a component, or out and back where both
/// connectors face the same way). The elbow first leaves `s` along `first_x` (the stub's
/// direction). Only for ends at most [`DIRECT_CELLS`] apart.
fn direct(sheet: &mut Sheet, s: P, t: P, first_x: bool) -> Option<Vec<P>> {
    if (s.0 - t.0).abs() + (s.1 - t.1).abs() > DIRECT_CELLS {
        return None;
    }
    let start = sheet.work;
    let ok = |sheet: &mut Sheet, pts: &[P]| sheet.work - start <= DIRECT_WORK && clear_path(sheet, pts) && unused(sheet, pts);
    if s.0 == t.0 || s.1 == t.1 {
        if ok(sheet, &[s, t]) {
            return Some(vec![s, t]);
        }
    } else {
        let (h, v) = ([s, (t.0, s.1), t], [s, (s.0, t.1), t]);
        for pts in if first_x { [h, v] } else { [v, h] } {
            if ok(sheet, &pts) {
                return Some(pts.to_vec());
            }
        }
    }
    let between = |v: i32, a: i32, b: i32| a.min(b) < v && v < a.max(b);
    let columns = s.1 != t.1;
    let rows = s.0 != t.0;
    for inside in [true, false] {
        if columns || s.0 == t.0 {
            for c in near(t.0).chain(near(s.0)).filter(|&c| between(c, s.0, t.0) == inside) {
                let pts = [s, (c, s.1), (c, t.1), t];
                if ok(sheet, &pts) {
                    return Some(pts.to_vec());
                }
            }
        }
        if rows || s.1 == t.1 {
            for r in near(t.1).chain(near(s.1)).filter(|&r| between(r, s.1, t.1) == inside) {
                let pts = [s, (s.0, r), (t.0, r), t];
                if ok(sheet, &pts) {
                    return Some(pts.to_vec());
                }
            }
        }
    }
    None
}

/// Drops repeated points and the middle one of three collinear points.
fn simplify(pts: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::with_capacity(pts.len());
    for p in pts {
        if out.last().is_some_and(|q| (q.0 - p.0).abs() < 1e-9 && (q.1 - p.1).abs() < 1e-9) {
            continue;
        }
        if out.len() >= 2 {
            let (a, b) = (out[out.len() - 2], out[out.len() - 1]);
            let same_x = (a.0 - b.0).abs() < 1e-9 && (b.0 - p.0).abs() < 1e-9;
            let same_y = (a.1 - b.1).abs() < 1e-9 && (b.1 - p.1).abs() < 1e-9;
            if same_x || same_y {
                out.pop();
            }
        }
        out.push(p);
    }
    out
}

/// The route of a wire from end `a` to end `b` (its points, first and last on the connectors),
/// marking the cells it uses.
pub(super) fn route(sheet: &mut Sheet, a: End, b: End) -> Vec<(f64, f64)> {
    let sa = stub(a.0, &a.1);
    let sb = stub(b.0, &b.1);
    let s = sa.last().map(|p| (g(p.0), g(p.1))).unwrap_or_default();
    let t = sb.last().map(|p| (g(p.0), g(p.1))).unwrap_or_default();
    let bbox = Rect { x1: s.0.min(t.0), y1: s.1.min(t.1), x2: s.0.max(t.0), y2: s.1.max(t.1) };
    // This wire's share of the sheet's search budget: its own cap, and what the wires so far
    // left over.
    let pool = (SHEET_EXPANSIONS_START + SHEET_EXPANSIONS_PER_WIRE * (sheet.wires.len() as u64 + 1)).saturating_sub(sheet.spent);
    let mut allowance = WIRE_EXPANSIONS.min(pool);
    let distance = u64::from((s.0 - t.0).unsigned_abs() + (s.1 - t.1).unsigned_abs());
    // The stub of `a` leaves its connector along x when its first segment is horizontal.
    let first_x = sa.len() >= 2 && (sa[0].1 - sa[1].1).abs() < 1e-9 && (sa[0].0 - sa[1].0).abs() > 1e-9;
    // A direct route is marked and drawn by its corners (a long wire has thousands of cells).
    if let Some(corners) = direct(sheet, s, t, first_x) {
        for w in corners.windows(2) {
            sheet.used.insert_segment(w[0], w[1]);
        }
        return drawn(sa, &corners, sb);
    }
    let mut path = None;
    for grow in WINDOWS {
        if distance > allowance {
            break;
        }
        let (found, used) = search(sheet, s, t, bbox.grow(grow, grow), allowance);
        allowance -= used.min(allowance);
        sheet.spent += used;
        sheet.work += used;
        if found.is_some() {
            path = found;
            break;
        }
    }
    let Some(path) = path else {
        return match fallback(sheet, s, t) {
            // Not marked as used: that would cost the wire's length.
            Some(corners) => drawn(sa, &corners, sb),
            // No clear route: a straight orthogonal elbow (the layout test reports it).
            None => {
                let (pa, pb) = (a.0 .0, b.0 .0);
                vec![pa, (pb.0, pa.1), pb]
            }
        };
    };
    for p in &path {
        sheet.used.insert(*p);
    }
    drawn(sa, &path, sb)
}

/// A wire's points: the stub out of its first connector (`sa`), the grid points `via` (grid
/// units), then the stub `sb` back into its last connector, simplified.
fn drawn(mut pts: Vec<(f64, f64)>, via: &[P], mut sb: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    pts.extend(via.iter().map(|&(x, y)| (f64::from(x * GRID), f64::from(y * GRID))));
    sb.reverse();
    pts.extend(sb);
    simplify(pts)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every point of a window gets its own cell number below `cells()`, and the number gives the
    /// point back; windows narrower than a tile, a tile wide and wider, at negative coordinates.
    #[test]
    fn tile_numbering_is_one_to_one() {
        for (x1, y1, x2, y2) in [(-3, -7, 9, 4), (0, 0, 15, 15), (-40, 10, 17, 50), (5, -33, 5, -33)] {
            let win = Window::new(Rect { x1, y1, x2, y2 });
            let mut seen = std::collections::HashSet::new();
            for y in y1..=y2 {
                for x in x1..=x2 {
                    let c = win.cell((x, y));
                    assert!(c < win.cells(), "{c} of {} at ({x}, {y})", win.cells());
                    assert!(seen.insert(c), "cell {c} twice");
                    assert_eq!(win.point(c), (x, y));
                    assert_eq!(win.rank((x, y)), (x - x1) as usize + (y - y1) as usize * (x2 - x1 + 1) as usize);
                }
            }
        }
    }
}
