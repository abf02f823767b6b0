//! Distances and penetrations between bodies: at one pose ([`contacts_at`]) and along a sampled
//! motion ([`sweep`]: BVH broad phase per block of samples, conservative skipping per pair).

use nalgebra::{Isometry3, Point3, Translation3};
use parry3d_f64::bounding_volume::{Aabb, BoundingVolume};
use parry3d_f64::partitioning::{Bvh, BvhBuildStrategy};
use parry3d_f64::query;
use parry3d_f64::shape::SharedShape;

use super::shape::BodyShape;
use super::ConvexPart;

/// One body's prepared shape: its convex parts (pose in the body frame, shape, AABB in the body
/// frame). Parts are queried pairwise here rather than through a parry `Compound`: parry 0.22's
/// composite-shape `contact` composes the relative pose wrongly (witness points and normal on
/// the far side).
struct Prepared {
    parts: Vec<(Isometry3<f64>, SharedShape, Aabb)>,
    /// AABB in the body frame.
    local_aabb: Aabb,
    /// Largest distance of a shape point from the frame origin (radius included).
    reach: f64,
}

/// The prepared parry shapes of every body (None: no shape, or no usable part).
pub struct World {
    bodies: Vec<Option<Prepared>>,
}

/// True when `faces` enclose `pts` with outward normals and a volume (the orientation parry's
/// own hulls have): then parry may take them as the part's hull as they are.
pub(crate) fn outward_faces(pts: &[Point3<f64>], faces: &[[u32; 3]]) -> bool {
    if faces.len() < 4 || faces.iter().flatten().any(|&i| i as usize >= pts.len()) {
        return false;
    }
    let c = pts[0].coords;
    let vol: f64 = faces
        .iter()
        .map(|t| {
            let (a, b, d) = (pts[t[0] as usize].coords - c, pts[t[1] as usize].coords - c, pts[t[2] as usize].coords - c);
            a.dot(&b.cross(&d))
        })
        .sum::<f64>()
        / 6.0;
    let (lo, hi) = pts.iter().fold((pts[0].coords, pts[0].coords), |(lo, hi), p| (lo.inf(&p.coords), hi.sup(&p.coords)));
    vol > 1e-9 * (hi - lo).norm().powi(3)
}

pub(crate) fn prepared_part(p: &ConvexPart) -> Option<(Isometry3<f64>, SharedShape)> {
    let r = p.radius.max(0.0);
    let pts: Vec<Point3<f64>> = p.vertices.iter().map(|v| Point3::from(*v)).collect();
    if !pts.iter().all(|q| q.coords.iter().all(|c| c.is_finite())) || !r.is_finite() {
        return None;
    }
    match pts.len() {
        0 => None,
        1 => (r > 0.0).then(|| (Isometry3::from(Translation3::from(pts[0].coords)), SharedShape::ball(r))),
        2 => (r > 0.0).then(|| (Isometry3::identity(), SharedShape::capsule(pts[0], pts[1], r))),
        // The part's hull faces are known: parry takes them as they are (no second quickhull,
        // which was most of the cost of preparing a 2,000-body world); hull again only where
        // parry does not accept them.
        _ if r > 0.0 => {
            let mesh = outward_faces(&pts, &p.faces).then(|| SharedShape::round_convex_mesh(pts.clone(), &p.faces, r)).flatten();
            Some((Isometry3::identity(), mesh.or_else(|| SharedShape::round_convex_hull(&pts, r))?))
        }
        _ => {
            let mesh = outward_faces(&pts, &p.faces).then(|| SharedShape::convex_mesh(pts.clone(), &p.faces)).flatten();
            Some((Isometry3::identity(), mesh.or_else(|| SharedShape::convex_hull(&pts))?))
        }
    }
}

/// One body's parry shapes (None: no usable part).
fn prepare(s: &BodyShape) -> Option<Prepared> {
    let parts: Vec<(Isometry3<f64>, SharedShape, Aabb)> = s
        .parts
        .iter()
        .filter_map(prepared_part)
        .map(|(iso, sh)| {
            let bb = sh.compute_aabb(&iso);
            (iso, sh, bb)
        })
        .collect();
    let reach = s
        .parts
        .iter()
        .flat_map(|p| p.vertices.iter().map(move |v| nalgebra::Vector3::from(*v).norm() + p.radius.max(0.0)))
        .fold(0.0, f64::max);
    let mut local_aabb = parts.first()?.2;
    for p in &parts[1..] {
        local_aabb.merge(&p.2);
    }
    Some(Prepared { parts, local_aabb, reach })
}

/// A box in the body frame holding every part [`prepare`] would make of `s` (their vertices,
/// each grown by the part's radius, and a little more for rounding), without making them: None
/// where no part can be made. A part whose faces and hull parry both refuse is in it all the
/// same (a larger box than [`World::new`]'s costs only a pair the narrow phase rejects).
fn bound(s: &BodyShape) -> Option<Aabb> {
    let mut out: Option<Aabb> = None;
    for p in &s.parts {
        let r = p.radius.max(0.0);
        let finite = p.vertices.iter().all(|v| v.iter().all(|c| c.is_finite())) && r.is_finite();
        // The parts `prepared_part` leaves out.
        if !finite || p.vertices.is_empty() || (p.vertices.len() <= 2 && r <= 0.0) {
            continue;
        }
        let pts: Vec<Point3<f64>> = p.vertices.iter().map(|v| Point3::from(*v)).collect();
        let bb = Aabb::from_points(pts.iter().copied()).loosened(r);
        match &mut out {
            Some(o) => o.merge(&bb),
            None => out = Some(bb),
        }
    }
    let o = out?;
    Some(o.loosened(1e-9 * (1.0 + (o.maxs - o.mins).norm() + o.maxs.coords.amax().max(o.mins.coords.amax()))))
}

impl World {
    pub fn new(shapes: &[Option<BodyShape>]) -> World {
        World { bodies: shapes.iter().map(|s| prepare(s.as_ref()?)).collect() }
    }

    /// Number of bodies (with or without shapes).
    pub fn len(&self) -> usize {
        self.bodies.len()
    }

    pub fn is_empty(&self) -> bool {
        self.bodies.is_empty()
    }

    /// Whether body `i` has a collision shape.
    pub fn has_shape(&self, i: usize) -> bool {
        self.bodies.get(i).is_some_and(|b| b.is_some())
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Contact {
    pub a: usize,
    pub b: usize,
    /// Metres; < 0: penetration depth.
    pub distance: f64,
    /// Witness points, world.
    pub point_a: [f64; 3],
    pub point_b: [f64; 3],
    /// Unit, from a to b (for a penetration: the direction to move b out of a).
    pub normal: [f64; 3],
}

fn arr(p: &Point3<f64>) -> [f64; 3] {
    [p.x, p.y, p.z]
}

/// Pairs of bodies whose world AABBs, each grown by `grow`, overlap (a < b, both with shapes),
/// sorted. Work and memory grow with the bodies and the overlapping pairs, not with n².
fn broad_pairs(aabbs: &[Option<Aabb>], grow: f64, out: &mut Vec<(usize, usize)>) {
    out.clear();
    let ids: Vec<usize> = (0..aabbs.len()).filter(|&i| aabbs[i].is_some()).collect();
    let leaves: Vec<Aabb> = ids.iter().filter_map(|&i| aabbs[i].map(|b| b.loosened(grow))).collect();
    if leaves.len() < 2 {
        return;
    }
    let bvh = Bvh::from_leaves(BvhBuildStrategy::Binned, &leaves);
    for (i, j) in bvh.leaf_pairs(&bvh, |x, y| x.aabb().intersects(&y.aabb())) {
        let (i, j) = (ids[i as usize], ids[j as usize]);
        if i == j {
            continue;
        }
        let (a, b) = (i.min(j), i.max(j));
        if leaves_overlap(&aabbs[a], &aabbs[b], grow) {
            out.push((a, b));
        }
    }
    // A pair may be met in both orders.
    out.sort_unstable();
    out.dedup();
}

fn leaves_overlap(a: &Option<Aabb>, b: &Option<Aabb>, grow: f64) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => a.loosened(grow).intersects(&b.loosened(grow)),
        _ => false,
    }
}

/// Pairs (a < b, `checked(a, b)` true, both with shapes) whose distance is ≤ `margin` (0.0:
/// touching or intersecting) at the world poses of the bodies' frame_a. Broad phase: a BVH over
/// the bodies' world AABBs grown by margin/2. Distance < 0 is the penetration depth (EPA).
pub fn contacts_at(world: &World, poses: &[Isometry3<f64>], checked: &dyn Fn(usize, usize) -> bool, margin: f64) -> Vec<Contact> {
    let margin = if margin.is_finite() { margin.max(0.0) } else { 0.0 };
    let pairs = posed_pairs(world.bodies.iter().map(|b| b.as_ref().map(|b| b.local_aabb)), poses, margin);
    let mut out = Vec::new();
    for (a, b) in pairs {
        if !checked(a, b) {
            continue;
        }
        let (Some(Some(sa)), Some(Some(sb))) = (world.bodies.get(a), world.bodies.get(b)) else { continue };
        out.extend(contact_within(a, sa, &poses[a], b, sb, &poses[b], margin));
    }
    out
}

/// The broad phase at `poses`: the pairs (a < b) whose local boxes, placed at their body's pose
/// (none for a missing box or a non-finite pose), come within `margin`.
fn posed_pairs(local: impl Iterator<Item = Option<Aabb>>, poses: &[Isometry3<f64>], margin: f64) -> Vec<(usize, usize)> {
    let aabbs: Vec<Option<Aabb>> = local
        .enumerate()
        .map(|(i, bb)| {
            let x = poses.get(i).filter(|x| x.translation.vector.iter().chain(x.rotation.coords.iter()).all(|c| c.is_finite()))?;
            Some(bb?.transform_by(x))
        })
        .collect();
    let mut pairs = Vec::new();
    broad_pairs(&aabbs, margin / 2.0 + 1e-12, &mut pairs);
    pairs
}

/// The contact of bodies `a` and `b` at their poses when they are within `margin`.
fn contact_within(
    a: usize,
    sa: &Prepared,
    pa: &Isometry3<f64>,
    b: usize,
    sb: &Prepared,
    pb: &Isometry3<f64>,
    margin: f64,
) -> Option<Contact> {
    let c = pair_contact(sa, pa, sb, pb, margin)?;
    (c.dist <= margin).then(|| Contact {
        a,
        b,
        distance: c.dist,
        point_a: arr(&c.point1),
        point_b: arr(&c.point2),
        normal: [c.normal1.x, c.normal1.y, c.normal1.z],
    })
}

/// [`contacts_at`] of `World::new(shapes)` (the same contacts), making the parry shapes of only
/// the bodies in the pairs the broad phase finds and `checked` keeps: a conversion's check at
/// the CAD pose meets few of its thousands of bodies (issue 23; preparing every body's parts was
/// most of that check). The broad phase takes each body's [`bound`], which holds the box
/// `World::new` gives it: a pair it adds is one whose parts' boxes are apart by more than
/// `margin`, which the narrow phase rejects before any query.
pub fn contacts_of(
    shapes: &[Option<BodyShape>],
    poses: &[Isometry3<f64>],
    checked: &dyn Fn(usize, usize) -> bool,
    margin: f64,
) -> Vec<Contact> {
    let margin = if margin.is_finite() { margin.max(0.0) } else { 0.0 };
    let pairs = posed_pairs(shapes.iter().map(|s| s.as_ref().and_then(bound)), poses, margin);
    let mut prepared: Vec<Option<Option<Prepared>>> = (0..shapes.len()).map(|_| None).collect();
    let mut out = Vec::new();
    for (a, b) in pairs {
        if !checked(a, b) {
            continue;
        }
        for i in [a, b] {
            if prepared[i].is_none() {
                prepared[i] = Some(shapes[i].as_ref().and_then(prepare));
            }
        }
        let (Some(Some(sa)), Some(Some(sb))) = (&prepared[a], &prepared[b]) else { continue };
        out.extend(contact_within(a, sa, &poses[a], b, sb, &poses[b], margin));
    }
    out
}

#[cfg(test)]
thread_local! {
    /// Body pairs this thread gave to the narrow phase of [`contacts_at`] (tests count them).
    pub(crate) static NARROW_PHASE: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

/// Options of [`sweep`].
#[derive(Clone, Debug, PartialEq)]
pub struct SweepOptions {
    /// `min_distance` is computed to within `max(abs_tolerance, rel_tolerance × d)` when it is
    /// below `near_distance` (defaults 1 mm, 5 %, 0.05 m). Pairs never nearer than
    /// `near_distance` (by their AABBs) report a distance ≥ `near_distance` that need not be
    /// the minimum.
    pub abs_tolerance: f64,
    pub rel_tolerance: f64,
    pub near_distance: f64,
    /// Samples per broad-phase block (default 32).
    pub block: usize,
}

impl Default for SweepOptions {
    fn default() -> Self {
        SweepOptions { abs_tolerance: 1e-3, rel_tolerance: 0.05, near_distance: 0.05, block: 32 }
    }
}

/// Serialised without its body indices (the service names the bodies).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct PairSweep {
    #[serde(skip)]
    pub a: usize,
    #[serde(skip)]
    pub b: usize,
    /// Smallest distance found (< 0: penetration), at time `at`, witness points in world.
    pub min_distance: f64,
    pub at: f64,
    /// First sample time with distance ≤ 0.
    pub first_contact: Option<f64>,
    /// Largest penetration depth over the samples (≥ 0).
    pub max_depth: f64,
    pub point_a: [f64; 3],
    pub point_b: [f64; 3],
}

#[derive(Clone, Debug, PartialEq)]
pub struct Sweep {
    /// Every checked pair with shapes, a < b, in order.
    pub pairs: Vec<PairSweep>,
    pub samples: usize,
    pub guarantee: String,
}

/// Per-pair sweep state.
struct PairState {
    out: PairSweep,
    /// Next sample that must be evaluated (earlier ones are proven to be > threshold).
    next: usize,
    evaluated: bool,
}

/// Along a motion: body poses `poses(k)` at `times[k]`.
///
/// Guarantee (stated in [`Sweep::guarantee`] with the numbers of the run): let D_i(k) = |Δr| +
/// θ·reach_i bound how far any point of body i moves from sample k to k+1 (Δr: frame origin
/// displacement, θ: rotation angle, reach_i: the shape's largest distance from the frame
/// origin). A pair is evaluated (parry GJK/EPA) at sample k; later samples j are skipped while
/// d_k − Σ_{k≤m<j}(D_a(m) + D_b(m)) stays above a threshold ≥ 0, so every sample where a checked
/// pair touches or penetrates is evaluated: `first_contact` and `max_depth` are exact over the
/// samples. Blocks of samples where the pair's AABBs (swept over the block, grown by the step
/// bounds and near_distance/2) do not overlap are skipped whole. Between samples, if each body
/// moves by at most its step bound, no penetration deeper than δ = max_k (D_a(k) + D_b(k)) / 2
/// is missed.
pub fn sweep(
    world: &World,
    times: &[f64],
    poses: &dyn Fn(usize) -> Vec<Isometry3<f64>>,
    checked: &dyn Fn(usize, usize) -> bool,
    opts: &SweepOptions,
) -> Sweep {
    let n = times.len();
    let nb = world.bodies.len();
    // All poses (missing bodies: identity). Bodies with a non-finite pose at any sample are
    // left out (named in the guarantee), never checked with garbage.
    let all: Vec<Vec<Isometry3<f64>>> = (0..n)
        .map(|k| {
            let mut p = poses(k);
            p.resize(nb, Isometry3::identity());
            p
        })
        .collect();
    let mut bad = vec![false; nb];
    for p in &all {
        for (i, x) in p.iter().enumerate() {
            if !(x.translation.vector.iter().all(|c| c.is_finite()) && x.rotation.coords.iter().all(|c| c.is_finite())) {
                bad[i] = true;
            }
        }
    }
    let usable = |i: usize| world.has_shape(i) && !bad[i];
    let mut states: Vec<PairState> = Vec::new();
    let mut index = vec![usize::MAX; nb * nb];
    for a in 0..nb {
        for b in a + 1..nb {
            if usable(a) && usable(b) && checked(a, b) {
                index[a * nb + b] = states.len();
                states.push(PairState {
                    out: PairSweep {
                        a,
                        b,
                        min_distance: f64::INFINITY,
                        at: times.first().copied().unwrap_or(0.0),
                        first_contact: None,
                        max_depth: 0.0,
                        point_a: [0.0; 3],
                        point_b: [0.0; 3],
                    },
                    next: 0,
                    evaluated: false,
                });
            }
        }
    }
    if n == 0 || states.is_empty() {
        return Sweep {
            pairs: states.into_iter().map(|s| s.out).collect(),
            samples: n,
            guarantee: format!("{n} samples; nothing to check"),
        };
    }
    // Per body the prefix sums of the step bounds.
    let reach: Vec<f64> = world.bodies.iter().map(|b| b.as_ref().map_or(0.0, |p| p.reach)).collect();
    // step[i * n + k] = D_i(k) (k < n-1); prefix[i * (n) + k] = Σ_{m<k} D_i(m).
    let mut step = vec![0.0; nb * n];
    let mut prefix = vec![0.0; nb * n];
    let mut delta = 0.0f64;
    for k in 0..n.saturating_sub(1) {
        let (mut d1, mut d2) = (0.0f64, 0.0f64);
        for i in 0..nb {
            if !usable(i) {
                continue;
            }
            let (p, q) = (&all[k][i], &all[k + 1][i]);
            let dr = (q.translation.vector - p.translation.vector).norm();
            let th = (p.rotation.inverse() * q.rotation).angle();
            let d = dr + th * reach[i];
            step[i * n + k] = d;
            prefix[i * n + k + 1] = prefix[i * n + k] + d;
            if d > d1 {
                d2 = d1;
                d1 = d;
            } else if d > d2 {
                d2 = d;
            }
        }
        delta = delta.max((d1 + d2) / 2.0);
    }
    let near = opts.near_distance.max(0.0);
    let block = opts.block.max(1);
    let mut aabbs: Vec<Option<Aabb>> = vec![None; nb];
    let mut pairs = Vec::new();
    let mut evaluations = 0usize;
    let mut s0 = 0usize;
    loop {
        let s1 = (s0 + block).min(n - 1);
        // Swept AABBs over [s0, s1], grown by the largest step bound in the block.
        for (i, slot) in aabbs.iter_mut().enumerate() {
            *slot = world.bodies[i].as_ref().filter(|_| !bad[i]).map(|b| {
                let mut bb = b.local_aabb.transform_by(&all[s0][i]);
                let mut grow = 0.0f64;
                for k in s0 + 1..=s1 {
                    bb.merge(&b.local_aabb.transform_by(&all[k][i]));
                    grow = grow.max(step[i * n + k - 1]);
                }
                bb.loosened(grow)
            });
        }
        broad_pairs(&aabbs, near / 2.0 + 1e-12, &mut pairs);
        for &(a, b) in &pairs {
            let si = index[a * nb + b];
            if si == usize::MAX {
                continue;
            }
            let (Some(pa), Some(pb)) = (&world.bodies[a], &world.bodies[b]) else { continue };
            let st = &mut states[si];
            let mut k = st.next.max(s0);
            while k <= s1 {
                let d = evaluate(&mut st.out, pa, pb, &all[k][a], &all[k][b], times[k]);
                evaluations += 1;
                st.evaluated = true;
                // Skip while the lower bound stays above thr.
                let m = st.out.min_distance.min(near);
                let thr = (m - opts.abs_tolerance.max(opts.rel_tolerance * m)).max(0.0);
                let need = d - thr; // skip j while B(k, j) < need
                let base = prefix[a * n + k] + prefix[b * n + k];
                let bound = |j: usize| prefix[a * n + j] + prefix[b * n + j] - base;
                k = if need <= 0.0 { k + 1 } else { first_reaching(&bound, k + 1, n, need) };
            }
            st.next = k;
        }
        if s1 >= n - 1 {
            break;
        }
        s0 = s1;
    }
    // Pairs never near: one evaluation at the first sample (a distance ≥ near_distance).
    for st in states.iter_mut().filter(|s| !s.evaluated) {
        let (Some(pa), Some(pb)) = (&world.bodies[st.out.a], &world.bodies[st.out.b]) else { continue };
        let (a, b) = (st.out.a, st.out.b);
        evaluate(&mut st.out, pa, pb, &all[0][a], &all[0][b], times[0]);
        evaluations += 1;
    }
    let guarantee = format!(
        "{n} samples, {evaluations} pair evaluations. Conservative sampling: a pair is skipped at a sample only while its last exact distance minus the bound on the relative motion since (per body: frame displacement + rotation angle × the shape's reach) stays positive, so every sample where a checked pair touches or penetrates is found (first_contact, max_depth exact over the samples); between samples no penetration deeper than {delta:.3e} m (half the largest relative step bound) is missed. min_distance below {near} m is the minimum over the samples to within max({} m, {} × d); larger values are only known to be ≥ {near} m.",
        opts.abs_tolerance, opts.rel_tolerance
    );
    let skipped: Vec<usize> = (0..nb).filter(|&i| bad[i] && world.has_shape(i)).collect();
    let guarantee =
        if skipped.is_empty() { guarantee } else { format!("{guarantee} Bodies with non-finite poses, not checked: {skipped:?}.") };
    Sweep { pairs: states.into_iter().map(|s| s.out).collect(), samples: n, guarantee }
}

/// The smallest j in [from, n) with bound(j) ≥ need (n if none); bound is nondecreasing.
fn first_reaching(bound: &dyn Fn(usize) -> f64, from: usize, n: usize, need: f64) -> usize {
    if from >= n || bound(from) >= need {
        return from;
    }
    // Gallop, then bisect: bound(lo) < need.
    let mut lo = from;
    let mut step = 1usize;
    let mut hi = loop {
        let j = lo + step;
        if j >= n {
            break n;
        }
        if bound(j) >= need {
            break j;
        }
        lo = j;
        step *= 2;
    };
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if mid < n && bound(mid) >= need {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

/// One exact evaluation at a sample; updates the pair's record; returns the distance (0 when
/// touching or penetrating: the lower bound used for skipping).
fn evaluate(out: &mut PairSweep, pa: &Prepared, pb: &Prepared, xa: &Isometry3<f64>, xb: &Isometry3<f64>, t: f64) -> f64 {
    let d = pair_distance(pa, xa, pb, xb);
    if d > 0.0 && d >= out.min_distance {
        return d;
    }
    // New minimum or contact: witness points (EPA depth when penetrating).
    let (dist, p1, p2) = match pair_contact(pa, xa, pb, xb, d.max(0.0) + 1e-9) {
        Some(c) => (c.dist, arr(&c.point1), arr(&c.point2)),
        _ => (d, out.point_a, out.point_b),
    };
    if dist <= 0.0 {
        if out.first_contact.is_none() {
            out.first_contact = Some(t);
        }
        out.max_depth = out.max_depth.max(-dist);
    }
    if dist < out.min_distance {
        out.min_distance = dist;
        out.at = t;
        out.point_a = p1;
        out.point_b = p2;
    }
    d.max(0.0)
}

/// Distance between two AABBs (0 when they overlap).
fn aabb_gap(a: &Aabb, b: &Aabb) -> f64 {
    let g = (a.mins - b.maxs).sup(&(b.mins - a.maxs)).sup(&nalgebra::Vector3::zeros());
    g.norm()
}

/// Part pairs of two bodies at their poses, nearest AABBs first, with the AABB gap.
fn part_pairs(pa: &Prepared, xa: &Isometry3<f64>, pb: &Prepared, xb: &Isometry3<f64>) -> Vec<(f64, usize, usize)> {
    let wa: Vec<Aabb> = pa.parts.iter().map(|p| p.2.transform_by(xa)).collect();
    let wb: Vec<Aabb> = pb.parts.iter().map(|p| p.2.transform_by(xb)).collect();
    let mut v = Vec::with_capacity(wa.len() * wb.len());
    for (i, a) in wa.iter().enumerate() {
        for (j, b) in wb.iter().enumerate() {
            v.push((aabb_gap(a, b), i, j));
        }
    }
    v.sort_by(|x, y| x.0.total_cmp(&y.0));
    v
}

/// Distance between two bodies (0 when touching or intersecting).
fn pair_distance(pa: &Prepared, xa: &Isometry3<f64>, pb: &Prepared, xb: &Isometry3<f64>) -> f64 {
    if let ([a], [b]) = (&pa.parts[..], &pb.parts[..]) {
        return query::distance(&(xa * a.0), &*a.1, &(xb * b.0), &*b.1).unwrap_or(0.0);
    }
    let mut best = f64::INFINITY;
    for (gap, i, j) in part_pairs(pa, xa, pb, xb) {
        if gap >= best {
            break;
        }
        let (a, b) = (&pa.parts[i], &pb.parts[j]);
        best = best.min(query::distance(&(xa * a.0), &*a.1, &(xb * b.0), &*b.1).unwrap_or(0.0));
        if best <= 0.0 {
            break;
        }
    }
    best
}

/// The contact (deepest or nearest part pair) of two bodies if their distance ≤ `prediction`.
fn pair_contact(pa: &Prepared, xa: &Isometry3<f64>, pb: &Prepared, xb: &Isometry3<f64>, prediction: f64) -> Option<query::Contact> {
    #[cfg(test)]
    NARROW_PHASE.with(|n| n.set(n.get() + 1));
    let mut best: Option<query::Contact> = None;
    for (gap, i, j) in part_pairs(pa, xa, pb, xb) {
        // Sorted by gap: nothing further can be within prediction, or nearer/deeper than best.
        if gap > prediction || best.as_ref().is_some_and(|c| gap > c.dist.max(0.0)) {
            break;
        }
        let (a, b) = (&pa.parts[i], &pb.parts[j]);
        if let Ok(Some(c)) = query::contact(&(xa * a.0), &*a.1, &(xb * b.0), &*b.1, prediction) {
            if best.as_ref().is_none_or(|x| c.dist < x.dist) {
                best = Some(c);
            }
        }
    }
    best
}
