//! Orthogonal routing on the 5-unit grid: A* over grid points outside every component's
//! keep-out box, with a cost for each bend and for running over a cell another wire already
//! uses, so wires take few bends and spread out. Each end leaves its connector straight out of
//! the component first.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use super::{floor_div, GridMap, Rect, Sheet, BUCKET, GRID};

type End = (((f64, f64), (i32, i32)), Rect);

const BEND: u32 = 4;
const SHARED: u32 = 3;
/// Step limit of one search (a route that needs more is drawn by the wider search, or not at
/// all: the line is still valid Modelica, only without a route).
const MAX_EXPANSIONS: usize = 2_000_000;

fn g(v: f64) -> i32 {
    (v / f64::from(GRID)).round() as i32
}

impl Sheet {
    /// True when grid point (ix, iy) lies strictly inside a component's keep-out box.
    fn blocked(&self, ix: i32, iy: i32) -> bool {
        let (x, y) = (ix * GRID, iy * GRID);
        self.buckets.get(&(floor_div(x, BUCKET), floor_div(y, BUCKET))).is_some_and(|list| {
            list.iter().any(|&i| {
                let k = Sheet::keep_out(&self.rects[i]);
                k.x1 < x && x < k.x2 && k.y1 < y && y < k.y2
            })
        })
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

/// Per-search state: dense arrays for a small window, hash maps for a large one (a long wire's
/// window is mostly never visited).
enum Cells {
    Dense { state: Vec<u8>, best: Vec<u32>, from: Vec<u32> },
    Sparse { state: GridMap<usize, u8>, best: GridMap<usize, u32>, from: GridMap<usize, u32> },
}

const DENSE_CELLS: usize = 1 << 15;

impl Cells {
    fn new(cells: usize) -> Cells {
        if cells <= DENSE_CELLS {
            Cells::Dense { state: vec![0; cells], best: vec![u32::MAX; cells * 5], from: vec![u32::MAX; cells * 5] }
        } else {
            Cells::Sparse { state: GridMap::default(), best: GridMap::default(), from: GridMap::default() }
        }
    }
    fn state(&mut self, c: usize, f: impl FnOnce() -> u8) -> u8 {
        match self {
            Cells::Dense { state, .. } => {
                if state[c] == 0 {
                    state[c] = f();
                }
                state[c]
            }
            Cells::Sparse { state, .. } => *state.entry(c).or_insert_with(f),
        }
    }
    fn best(&self, n: usize) -> u32 {
        match self {
            Cells::Dense { best, .. } => best[n],
            Cells::Sparse { best, .. } => best.get(&n).copied().unwrap_or(u32::MAX),
        }
    }
    fn from(&self, n: usize) -> u32 {
        match self {
            Cells::Dense { from, .. } => from[n],
            Cells::Sparse { from, .. } => from.get(&n).copied().unwrap_or(u32::MAX),
        }
    }
    fn set(&mut self, n: usize, cost: u32, prev: u32) {
        match self {
            Cells::Dense { best, from, .. } => {
                best[n] = cost;
                from[n] = prev;
            }
            Cells::Sparse { best, from, .. } => {
                best.insert(n, cost);
                from.insert(n, prev);
            }
        }
    }
}

/// Weighted A* (the heuristic counts twice: routes are found fast and are short enough) from
/// grid point `s` to `t` within `win` (grid units); the grid points of the path.
fn search(sheet: &Sheet, s: (i32, i32), t: (i32, i32), win: Rect) -> Option<Vec<(i32, i32)>> {
    let w = (win.x2 - win.x1 + 1) as usize;
    let hgt = (win.y2 - win.y1 + 1) as usize;
    let cell = |p: (i32, i32)| (p.0 - win.x1) as usize + (p.1 - win.y1) as usize * w;
    let h = |p: (i32, i32)| 2 * ((p.0 - t.0).abs() + (p.1 - t.1).abs()) as u32;
    // Per cell: 0 unknown, 1 free, 2 blocked. Per state (cell, arriving direction 0..5): best
    // cost and the state it came from.
    let mut cells = Cells::new(w * hgt);
    let mut heap = BinaryHeap::new();
    let start = cell(s) * 5 + 4;
    cells.set(start, 0, u32::MAX);
    heap.push(Reverse((h(s), 0u32, start as u32)));
    let mut expansions = 0;
    let goal = cell(t);
    while let Some(Reverse((_, cost, node))) = heap.pop() {
        let node = node as usize;
        if cells.best(node) < cost {
            continue;
        }
        let (c, dir) = (node / 5, (node % 5) as u8);
        if c == goal {
            let mut path = Vec::new();
            let mut cur = node;
            loop {
                let cc = cur / 5;
                path.push((win.x1 + (cc % w) as i32, win.y1 + (cc / w) as i32));
                let prev = cells.from(cur);
                if prev == u32::MAX {
                    break;
                }
                cur = prev as usize;
            }
            path.reverse();
            return Some(path);
        }
        expansions += 1;
        if expansions > MAX_EXPANSIONS {
            return None;
        }
        let (x, y) = (win.x1 + (c % w) as i32, win.y1 + (c / w) as i32);
        for (d, (dx, dy)) in DIRS.iter().enumerate() {
            let d = d as u8;
            // No U-turns.
            if dir != 4 && dir ^ 1 == d {
                continue;
            }
            let (nx, ny) = (x + dx, y + dy);
            if nx < win.x1 || nx > win.x2 || ny < win.y1 || ny > win.y2 {
                continue;
            }
            let nc = cell((nx, ny));
            if cells.state(nc, || if sheet.blocked(nx, ny) { 2 } else { 1 }) == 2 && nc != goal {
                continue;
            }
            let mut step = 1 + if dir != 4 && dir != d { BEND } else { 0 };
            if sheet.used.contains_key(&(nx, ny)) {
                step += SHARED;
            }
            let next = nc * 5 + d as usize;
            let cst = cost + step;
            if cst < cells.best(next) {
                cells.set(next, cst, node as u32);
                heap.push(Reverse((cst + h((nx, ny)), cst, next as u32)));
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
    let mut sb = stub(b.0, &b.1);
    let s = sa.last().map(|p| (g(p.0), g(p.1))).unwrap_or_default();
    let t = sb.last().map(|p| (g(p.0), g(p.1))).unwrap_or_default();
    let bbox = Rect { x1: s.0.min(t.0), y1: s.1.min(t.1), x2: s.0.max(t.0), y2: s.1.max(t.1) };
    let mut path = None;
    for grow in [20, 80, 400] {
        path = search(sheet, s, t, bbox.grow(grow, grow));
        if path.is_some() {
            break;
        }
    }
    let Some(path) = path else {
        // No free route: a straight orthogonal elbow (the layout test reports it).
        let (pa, pb) = (a.0 .0, b.0 .0);
        return vec![pa, (pb.0, pa.1), pb];
    };
    for p in &path {
        let n = sheet.used.entry(*p).or_insert(0);
        *n = n.saturating_add(1);
    }
    let mut pts = sa;
    pts.extend(path.iter().map(|&(x, y)| (f64::from(x * GRID), f64::from(y * GRID))));
    sb.reverse();
    pts.extend(sb);
    simplify(pts)
}
