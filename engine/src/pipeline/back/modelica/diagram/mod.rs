//! The diagram of a generated model: where each component stands and how each `connect` is
//! drawn. A [`Sheet`] takes components with the spot the layout wants for them ([`Sheet::add`]),
//! moves a component that would overlap another to the nearest free spot, and routes every
//! connection orthogonally around the components ([`route`]). It knows the connector positions
//! of the classes the back end emits ([`port`]); everything is in diagram units on a 5-unit grid,
//! so the output is exact integers and the same input always gives the same file.

pub mod extend;
pub mod plan;
mod route;
pub mod svg;

use std::collections::{BTreeMap, HashMap};

pub use route::{SHEET_EXPANSIONS_PER_WIRE, WIRE_EXPANSIONS};

/// A fast hash for grid coordinates (the maps here are keyed by small integer pairs; SipHash's
/// protection against chosen keys is not needed for our own layout).
#[derive(Clone, Copy, Default)]
pub struct GridHasher(u64);

impl std::hash::Hasher for GridHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for b in bytes {
            self.0 = (self.0.rotate_left(5) ^ u64::from(*b)).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
        }
    }
    fn write_i32(&mut self, i: i32) {
        self.0 = (self.0.rotate_left(5) ^ u64::from(i as u32)).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
    fn write_u64(&mut self, i: u64) {
        self.0 = (self.0.rotate_left(5) ^ i).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
    fn write_usize(&mut self, i: usize) {
        self.write_u64(i as u64);
    }
}

pub type GridMap<K, V> = HashMap<K, V, std::hash::BuildHasherDefault<GridHasher>>;

/// The grid every origin, extent and route corner lies on.
pub const GRID: i32 = 5;

/// A rectangle, `x1 < x2`, `y1 < y2`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rect {
    pub x1: i32,
    pub y1: i32,
    pub x2: i32,
    pub y2: i32,
}

impl Rect {
    pub fn grow(&self, d: i32, top: i32) -> Rect {
        Rect { x1: self.x1 - d, y1: self.y1 - d, x2: self.x2 + d, y2: self.y2 + top }
    }
    pub fn overlaps(&self, o: &Rect) -> bool {
        self.x1 < o.x2 && o.x1 < self.x2 && self.y1 < o.y2 && o.y1 < self.y2
    }
    pub fn union(&self, o: &Rect) -> Rect {
        Rect { x1: self.x1.min(o.x1), y1: self.y1.min(o.y1), x2: self.x2.max(o.x2), y2: self.y2.max(o.y2) }
    }
}

/// What a connector is drawn like: the classes the back end instantiates, by their connectors.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Class {
    /// MSL World: `frame_b` on the right.
    World,
    /// Parts with `frame_a` on the left and `frame_b` on the right (bodies, fixed transforms,
    /// spherical joints, loop constraints, shapes), or 1-D parts with `flange_a`/`flange_b`,
    /// `flangeR`/`flangeT` at the same places.
    TwoPort,
    /// `Components.Revolute`/`Prismatic`: frames as [`Class::TwoPort`] and the `drive` flange at
    /// {-60, 100}.
    Joint,
    /// `Components.Drives.*Drive`: its `flange` on the right, {100, 0} (the centre of the
    /// connector's extent {{90, -10}, {110, 10}}, as for MSL's own connectors).
    Drive,
    /// MSL `Forces.WorldForceAndTorque`: `frame_b` right, inputs `force` {-120, 60} and
    /// `torque` {-120, -60}.
    WorldForce,
    /// `Components.Collision.World`: outputs `force` {110, 40} and `torque` {110, -40}.
    CollisionWorld,
    /// A block with no connection drawn (motion tables, the live viewer).
    Other,
}

/// The connector `name` of a component of class `class`, in the component's icon coordinates
/// ({-100, -100} to {100, 100}).
pub fn port(class: Class, name: &str) -> Option<(f64, f64)> {
    Some(match (class, name) {
        (Class::World, "frame_b") => (100.0, 0.0),
        (Class::TwoPort | Class::Joint, "frame_a" | "flange_a" | "flangeR") => (-100.0, 0.0),
        (Class::TwoPort | Class::Joint, "frame_b" | "flange_b" | "flangeT") => (100.0, 0.0),
        (Class::Joint, "drive") => (-60.0, 100.0),
        (Class::Drive, "flange") => (100.0, 0.0),
        (Class::WorldForce, "frame_b") => (100.0, 0.0),
        (Class::WorldForce, "force") => (-120.0, 60.0),
        (Class::WorldForce, "torque") => (-120.0, -60.0),
        (Class::CollisionWorld, "force") => (110.0, 40.0),
        (Class::CollisionWorld, "torque") => (110.0, -40.0),
        _ => return None,
    })
}

/// A placed component: origin, half size (square extent) and whether it is mirrored
/// horizontally (extent written right to left, so `frame_a` is on the right).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Placed {
    pub x: i32,
    pub y: i32,
    pub half: i32,
    pub flip: bool,
    pub class: Class,
}

impl Placed {
    pub fn rect(&self) -> Rect {
        Rect { x1: self.x - self.half, y1: self.y - self.half, x2: self.x + self.half, y2: self.y + self.half }
    }

    /// The `Placement` annotation.
    pub fn annotation(&self) -> String {
        let h = self.half;
        let (a, b) = if self.flip { (h, -h) } else { (-h, h) };
        format!("annotation (Placement(transformation(extent={{{{{a},{}}},{{{b},{h}}}}}, origin={{{},{}}})))", -h, self.x, self.y)
    }

    /// A connector's position in the diagram and the direction a line leaves it in.
    pub fn port(&self, name: &str) -> Option<((f64, f64), (i32, i32))> {
        let (px, py) = port(self.class, name)?;
        let sx = if self.flip { -1.0 } else { 1.0 };
        let h = f64::from(self.half) / 100.0;
        let at = (f64::from(self.x) + sx * px * h, f64::from(self.y) + py * h);
        let out = if px.abs() >= py.abs() { ((sx * px).signum() as i32, 0) } else { (0, py.signum() as i32) };
        Some((at, out))
    }
}

/// Where the layout wants a component.
#[derive(Clone, Copy, Debug)]
pub struct Want {
    pub x: i32,
    pub y: i32,
    pub half: i32,
    pub flip: bool,
}

/// How a connection is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// A MultiBody frame connection (grey, thick).
    Frame,
    /// The connection that closes a kinematic loop (red, dashed), so the loops stand out.
    Loop,
    /// A 1-D flange (black).
    Flange,
    /// A signal (blue).
    Signal,
}

impl Style {
    fn annotation(self) -> &'static str {
        match self {
            Style::Frame => "color={95,95,95}, thickness=0.5",
            Style::Loop => "color={238,46,47}, pattern=LinePattern.Dash, thickness=0.5",
            Style::Flange => "color={0,0,0}",
            Style::Signal => "color={0,0,127}",
        }
    }
}

/// One `connect` with its route.
#[derive(Clone, Debug)]
pub struct Wire {
    pub a: String,
    pub b: String,
    pub style: Style,
    pub points: Vec<(f64, f64)>,
}

/// A set of grid cells in tiles of 16 × 16 bits: a wire's cells are neighbours, so marking a
/// route and looking cells up during a search touch few tiles (a hash map of single cells was
/// most of the routing time on large sheets: a cache miss per cell).
#[derive(Clone, Debug, Default)]
struct UsedCells {
    tiles: GridMap<(i32, i32), [u64; 4]>,
}

impl UsedCells {
    fn at(p: (i32, i32)) -> ((i32, i32), usize, u64) {
        let bit = ((p.0 & 15) + 16 * (p.1 & 15)) as usize;
        ((p.0 >> 4, p.1 >> 4), bit / 64, 1u64 << (bit % 64))
    }
    fn insert(&mut self, p: (i32, i32)) {
        let (tile, word, mask) = Self::at(p);
        self.tiles.entry(tile).or_default()[word] |= mask;
    }
    fn contains(&self, p: (i32, i32)) -> bool {
        let (tile, word, mask) = Self::at(p);
        self.tiles.get(&tile).is_some_and(|t| t[word] & mask != 0)
    }

    /// Marks every cell of the straight grid segment from `a` to `b` (one axis), both ends
    /// included: one map lookup per tile the segment crosses.
    fn insert_segment(&mut self, a: (i32, i32), b: (i32, i32)) {
        for (tile, cells) in tile_runs(a, b) {
            let bits = self.tiles.entry(tile).or_default();
            for p in cells {
                let (_, word, mask) = Self::at(p);
                bits[word] |= mask;
            }
        }
    }

    /// Whether a cell of the straight grid segment from `a` to `b` (one axis) other than
    /// `skip1` and `skip2` is used; `work` counts the tiles looked at.
    fn any_on(&self, a: (i32, i32), b: (i32, i32), skip1: (i32, i32), skip2: (i32, i32), work: &mut u64) -> bool {
        for (tile, mut cells) in tile_runs(a, b) {
            *work += 1;
            if let Some(t) = self.tiles.get(&tile) {
                if cells.any(|p| {
                    let (_, word, mask) = Self::at(p);
                    p != skip1 && p != skip2 && t[word] & mask != 0
                }) {
                    return true;
                }
            }
        }
        false
    }
}

/// The cells of the straight grid segment from `a` to `b` (one axis), both ends included, in
/// runs of one [`UsedCells`] tile each, from the lower end: the tile's key and its cells.
fn tile_runs(a: (i32, i32), b: (i32, i32)) -> impl Iterator<Item = ((i32, i32), impl Iterator<Item = (i32, i32)>)> {
    let horizontal = a.1 == b.1;
    let (lo, hi, fixed) = if horizontal { (a.0.min(b.0), a.0.max(b.0), a.1) } else { (a.1.min(b.1), a.1.max(b.1), a.0) };
    let at = move |k: i32| if horizontal { (k, fixed) } else { (fixed, k) };
    let mut v = lo;
    std::iter::from_fn(move || {
        (v <= hi).then(|| {
            // The last cell of this tile along the segment.
            let (start, end) = (v, (v | 15).min(hi));
            v = end + 1;
            (UsedCells::at(at(start)).0, (start..=end).map(at))
        })
    })
}

/// The components of a diagram and their wires.
#[derive(Clone, Debug, Default)]
pub struct Sheet {
    pub placed: BTreeMap<String, Placed>,
    /// Component names in the order they were added.
    pub order: Vec<String>,
    /// Spatial buckets of [`BUCKET`] units: the components whose extent (grown by the margin)
    /// touches each.
    buckets: GridMap<(i32, i32), Vec<usize>>,
    rects: Vec<Rect>,
    pub wires: Vec<Wire>,
    /// Cells wires already use (for spreading later wires apart).
    used: UsedCells,
    /// Per vertical grid line (x / GRID): the keep-out boxes the line runs strictly inside, as
    /// disjoint open y intervals (start to end); a straight segment is checked in log time.
    across_v: GridMap<i32, Intervals>,
    /// Per horizontal grid line (y / GRID): the same with x intervals.
    across_h: GridMap<i32, Intervals>,
    /// Routing work done so far: A* node expansions plus straight segments checked by the
    /// fallback routes (see [`Sheet::work`]).
    work: u64,
    /// A* expansions spent so far: with the wires made, this bounds the next searches.
    spent: u64,
    /// The lowest keep-out edge of the components placed (no component below it).
    bottom: i32,
}

/// Spots [`Sheet::add`] tries for one component before it takes the first spot under
/// everything placed (about 22 rings around the wanted spot).
pub const SPOTS_PER_ADD: u64 = 2_000;

/// Disjoint open intervals (start, end) in order: what a grid line runs strictly inside. A
/// deque: components are placed downwards and rightwards, so a new interval mostly goes first
/// (a vertical line's) or last (a horizontal line's), in constant time (a vector shifted a
/// whole column's intervals for each component placed under them).
type Intervals = std::collections::VecDeque<(i32, i32)>;

/// Adds the open interval (a, b) to disjoint open intervals, merging what it overlaps.
fn add_interval(list: &mut Intervals, a: i32, b: i32) {
    // The intervals it overlaps, (s, e) with s < b and a < e, are consecutive: ends rise with
    // starts.
    let first = list.partition_point(|&(_, e)| e <= a);
    let past = list.partition_point(|&(s, _)| s < b);
    if first >= past {
        list.insert(first, (a, b));
    } else {
        let merged = (a.min(list[first].0), b.max(list[past - 1].1));
        list.drain(first + 1..past);
        list[first] = merged;
    }
}

/// Whether the closed segment [a, b] meets one of the disjoint open intervals.
fn meets(list: Option<&Intervals>, a: i32, b: i32) -> bool {
    let (a, b) = (a.min(b), a.max(b));
    // [a, b] meets (s, e) when s < b and a < e; of the intervals starting before b, the last
    // ends last (they are disjoint).
    list.is_some_and(|l| {
        let before = l.partition_point(|&(s, _)| s < b);
        before > 0 && l[before - 1].1 > a
    })
}

const BUCKET: i32 = 100;
/// Free space kept around every component (the name is drawn above it: more room on top).
const MARGIN: i32 = 5;
const MARGIN_TOP: i32 = 10;

fn floor_div(a: i32, b: i32) -> i32 {
    a.div_euclid(b)
}

impl Sheet {
    fn keep_out(r: &Rect) -> Rect {
        r.grow(MARGIN, MARGIN_TOP)
    }

    fn free(&self, r: &Rect) -> bool {
        let g = Self::keep_out(r);
        for bx in floor_div(g.x1, BUCKET)..=floor_div(g.x2, BUCKET) {
            for by in floor_div(g.y1, BUCKET)..=floor_div(g.y2, BUCKET) {
                if let Some(list) = self.buckets.get(&(bx, by)) {
                    if list.iter().any(|&i| Self::keep_out(&self.rects[i]).overlaps(&g)) {
                        return false;
                    }
                }
            }
        }
        true
    }

    /// Places `name` at `want`, or where it is nearest to it and overlaps nothing (searching
    /// rings of grid spots outwards, the same order every time).
    pub fn add(&mut self, name: &str, class: Class, want: Want) -> Placed {
        let snap = |v: i32| v.div_euclid(GRID) * GRID;
        let (wx, wy) = (snap(want.x), snap(want.y));
        let at = |x: i32, y: i32| Placed { x, y, half: want.half, flip: want.flip, class };
        let mut p = at(wx, wy);
        let step = 2 * GRID;
        let mut tried = 0u64;
        'search: for ring in 0..10_000 {
            if ring == 0 {
                tried += 1;
                self.work += 1;
                if self.free(&p.rect()) {
                    break;
                }
                continue;
            }
            if tried >= SPOTS_PER_ADD {
                // Past the budget: under everything placed so far, which is free by construction.
                let y = (self.bottom - MARGIN - want.half - MARGIN_TOP).div_euclid(GRID) * GRID;
                p = at(wx, y.min(wy));
                break;
            }
            // Down first (layouts grow downwards), then right, then up, then left.
            let r = ring * step;
            let mut spots = Vec::with_capacity(8 * ring as usize);
            for k in -ring..=ring {
                spots.push((wx + k * step, wy - r));
            }
            for k in -ring..=ring {
                spots.push((wx + r, wy - k * step));
            }
            for k in -ring..=ring {
                spots.push((wx + k * step, wy + r));
            }
            for k in -ring..=ring {
                spots.push((wx - r, wy - k * step));
            }
            spots.sort_by_key(|(x, y)| ((x - wx).abs() + (y - wy).abs(), *y, *x));
            for (x, y) in spots {
                let q = at(x, y);
                tried += 1;
                self.work += 1;
                if self.free(&q.rect()) {
                    p = q;
                    break 'search;
                }
            }
        }
        let r = p.rect();
        let i = self.rects.len();
        self.rects.push(r);
        let g = Self::keep_out(&r);
        self.bottom = if i == 0 { g.y1 } else { self.bottom.min(g.y1) };
        for gx in floor_div(g.x1, GRID) + 1..=-floor_div(-g.x2, GRID) - 1 {
            add_interval(self.across_v.entry(gx).or_default(), g.y1, g.y2);
        }
        for gy in floor_div(g.y1, GRID) + 1..=-floor_div(-g.y2, GRID) - 1 {
            add_interval(self.across_h.entry(gy).or_default(), g.x1, g.x2);
        }
        for bx in floor_div(g.x1 - BUCKET, BUCKET)..=floor_div(g.x2 + BUCKET, BUCKET) {
            for by in floor_div(g.y1 - BUCKET, BUCKET)..=floor_div(g.y2 + BUCKET, BUCKET) {
                self.buckets.entry((bx, by)).or_default().push(i);
            }
        }
        self.placed.insert(name.to_string(), p);
        self.order.push(name.to_string());
        p
    }

    /// The layout work done on this sheet so far (a sheet cloned from another starts with its
    /// count): spots tried for components (at most [`SPOTS_PER_ADD`] each), A* node expansions
    /// and straight segments checked by fallback routes. Bounded by [`SHEET_EXPANSIONS_PER_WIRE`]
    /// per wire plus a constant per wire for the fallbacks, so it grows linearly with the
    /// components and wires whatever their lengths.
    pub fn work(&self) -> u64 {
        self.work
    }

    /// Whether the straight grid segment from `a` to `b` (grid units, one axis) stays out of
    /// every keep-out box's interior. One unit of work.
    fn clear(&mut self, a: (i32, i32), b: (i32, i32)) -> bool {
        self.work += 1;
        if a.0 == b.0 {
            !meets(self.across_v.get(&a.0), a.1 * GRID, b.1 * GRID)
        } else if a.1 == b.1 {
            !meets(self.across_h.get(&a.1), a.0 * GRID, b.0 * GRID)
        } else {
            false
        }
    }

    /// The bounding box of every component and wire, grown by `margin` and rounded out to 20.
    pub fn extent(&self, margin: i32) -> Rect {
        let mut b: Option<Rect> = None;
        for r in &self.rects {
            b = Some(b.map_or(*r, |b| b.union(r)));
        }
        for w in &self.wires {
            for &(x, y) in &w.points {
                let r = Rect { x1: x.floor() as i32, y1: y.floor() as i32, x2: x.ceil() as i32, y2: y.ceil() as i32 };
                b = Some(b.map_or(r, |b| b.union(&r)));
            }
        }
        let b = b.unwrap_or(Rect { x1: -100, y1: -100, x2: 100, y2: 100 });
        let down = |v: i32| (v - margin).div_euclid(20) * 20;
        let up = |v: i32| -((-(v + margin)).div_euclid(20) * 20);
        Rect { x1: down(b.x1), y1: down(b.y1), x2: up(b.x2), y2: up(b.y2) }
    }

    /// The component and connector of a `connect` argument (`a.frame_b`, `f.force[2, :]`).
    fn split(arg: &str) -> Option<(&str, &str)> {
        let (comp, conn) = arg.split_once('.')?;
        let conn = conn.split('[').next()?.trim();
        Some((comp, conn))
    }

    /// Records `connect(a, b)` and routes its line. A connector the sheet does not know
    /// (a component placed elsewhere) gets no line.
    pub fn connect(&mut self, a: &str, b: &str, style: Style) {
        let ends = Self::split(a).zip(Self::split(b)).and_then(|((ca, pa), (cb, pb))| {
            let (pa_, pb_) = (self.placed.get(ca)?, self.placed.get(cb)?);
            Some(((pa_.port(pa)?, pa_.rect()), (pb_.port(pb)?, pb_.rect())))
        });
        let points = match ends {
            Some((from, to)) => route::route(self, from, to),
            None => Vec::new(),
        };
        self.wires.push(Wire { a: a.to_string(), b: b.to_string(), style, points });
    }

    /// The `connect` equations with their `Line` annotations, in the order they were made.
    pub fn equations(&self, from: usize) -> String {
        self.wires[from..].iter().map(Wire::equation).collect()
    }
}

impl Wire {
    /// The `connect` equation, with its `Line` annotation when it has a route.
    pub fn equation(&self) -> String {
        if self.points.len() < 2 {
            return format!("  connect({}, {});\n", self.a, self.b);
        }
        // Pushed piece by piece: a large diagram has tens of thousands of route points.
        let mut s = String::with_capacity(64 + self.a.len() + self.b.len() + 12 * self.points.len());
        for part in ["  connect(", &self.a, ", ", &self.b, ")\n    annotation (Line(points={"] {
            s.push_str(part);
        }
        for (i, &(x, y)) in self.points.iter().enumerate() {
            s.push_str(if i == 0 { "{" } else { ",{" });
            push_coordinate(&mut s, x);
            s.push(',');
            push_coordinate(&mut s, y);
            s.push('}');
        }
        for part in ["}, ", self.style.annotation(), "));\n"] {
            s.push_str(part);
        }
        s
    }
}

/// Appends a coordinate: an integer when it is one, else one decimal (ports of small
/// components).
fn push_coordinate(s: &mut String, v: f64) {
    if (v - v.round()).abs() < 1e-9 {
        let n = v.round() as i64;
        if n < 0 {
            s.push('-');
        }
        crate::numtext::push_uint(s, n.unsigned_abs());
    } else {
        crate::numtext::push_disp(s, (v * 10.0).round() / 10.0);
    }
}

/// A `Diagram` and `Icon` coordinate system for extent `r`.
pub fn coordinate_system(r: &Rect) -> String {
    format!("coordinateSystem(preserveAspectRatio=false, extent={{{{{},{}}},{{{},{}}}}})", r.x1, r.y1, r.x2, r.y2)
}

#[cfg(test)]
mod tests;
