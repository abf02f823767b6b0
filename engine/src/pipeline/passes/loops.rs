//! Loop analysis by rank: how each closed loop is cut so that Modelica gets exactly the
//! independent constraint equations, never a redundant one.
//!
//! At the CAD pose every movable element has a unit twist in world coordinates (a revolute about
//! its axis through its origin, a prismatic along its axis, a spherical as three revolutes). For
//! each loop the closing joint's constraint wrenches (the annihilator of its twists) act on the
//! relative twist of its two sides through the tree; their numerical rank, with what earlier loops
//! already impose taken out, is the number `k` of independent equations the cut must add. A plain
//! joint imposes `6 - dof` equations; when that is more than `k`, the cut is emitted as an MSL
//! construct that imposes exactly `k` (tried in a fixed order, each checked by the same rank test):
//! `RevolutePlanarLoopConstraint` for planar loops, then `Joints.Constraints.*` with the right
//! locked directions. The start values that stay fixed are the independent coordinates, nearest
//! the ground first.
//!
//! Tolerances come from the data: exports print 6 significant digits, so axes are known to about
//! 1e-5 rad and twists (lengths scaled by the loop's size) to about 1e-5; singular values below
//! [`RANK_TOL`] = 1e-4 are taken as zero, and axes within [`PARALLEL_TOL`] = 1e-4 rad as parallel.
//! The axes of a planar loop are then replaced by their common normal, so the emitted model is
//! planar to rounding (about 1e-12 rad), well within MSL's own checks.

use std::collections::BTreeSet;
use std::fmt::Write as _;

use nalgebra::{DMatrix, DVector, Matrix3, Rotation3, UnitQuaternion, Vector3, Vector6};

use super::hierarchy::{self, Hierarchy, LoopKind};
use super::kinematics::{self, Chain, Element};
use crate::pipeline::ir::{JointId, Model, PrimitiveKind, Warning};

/// Most independent kinematic loops analysed in one model. Real mechanisms have a few; an export
/// with thousands of overlapping loops is refused rather than analysed for minutes.
pub const MAX_LOOPS: usize = 256;

/// Most loop joints (summed over the loops) analysed in one model.
pub const MAX_LOOP_JOINTS: usize = 100_000;

/// A model beyond what the loop analysis takes.
#[derive(Debug, thiserror::Error, PartialEq)]
#[error("{file}: the joints form {loops} independent closed loops through {joints} joints in all; at most {MAX_LOOPS} loops and {MAX_LOOP_JOINTS} loop joints are supported (a real mechanism has a few loops: check the export for duplicated joints)")]
pub struct TooManyLoops {
    pub file: String,
    pub loops: usize,
    pub joints: usize,
}

/// Singular values below this (of twists with lengths scaled by the loops' size) count as zero.
pub const RANK_TOL: f64 = 1e-4;
/// Axes closer than this (rad) count as parallel; prismatic axes as perpendicular to a normal
/// when their cosine to it is below this.
pub const PARALLEL_TOL: f64 = 1e-4;

/// An MSL `Joints.Constraints` class.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ConstraintClass {
    Spherical,
    Revolute,
    Prismatic,
    Universal,
}

impl ConstraintClass {
    /// Rotational equations the class imposes (its translational ones are its locked axes).
    pub fn rotation_equations(self) -> usize {
        match self {
            ConstraintClass::Spherical => 0,
            ConstraintClass::Revolute => 2,
            ConstraintClass::Prismatic => 3,
            ConstraintClass::Universal => 1,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            ConstraintClass::Spherical => "Spherical",
            ConstraintClass::Revolute => "Revolute",
            ConstraintClass::Prismatic => "Prismatic",
            ConstraintClass::Universal => "Universal",
        }
    }
}

/// A cut emitted as `Joints.Constraints.<class>`.
#[derive(Clone, Debug, PartialEq)]
pub struct ConstraintCut {
    pub class: ConstraintClass,
    /// Orientation of the constraint's frame_a relative to the cut element's frame_a (a
    /// `FixedRotation` is emitted in between when it is not the identity).
    pub axes: UnitQuaternion<f64>,
    /// Locked translations along the constraint's frame_a x, y, z axes.
    pub locked: [bool; 3],
    /// Revolute: `n`; Universal: `n_a` (both in the constraint's frame_a).
    pub n: Vector3<f64>,
    /// Universal: `n_b` (in frame_b, which coincides with frame_a at the start).
    pub n_b: Vector3<f64>,
}

/// How the closing joint of a loop is emitted.
#[derive(Clone, Debug, PartialEq)]
pub enum Cut {
    /// The joint as it is: every equation it imposes is independent.
    Joint,
    /// `RevolutePlanarLoopConstraint` on the closing revolute (2 in-plane position equations).
    PlanarLoopConstraint,
    /// A `Joints.Constraints` element on the closing joint's single element.
    Constraint(ConstraintCut),
    /// The rest of the mechanism already implies every equation: not emitted.
    Omitted,
    /// No MSL construct imposes exactly the independent equations: emitted as it is, with a
    /// warning naming the redundant count.
    Redundant,
}

/// What the analysis found for one loop (indexed like `Hierarchy::loops`).
#[derive(Clone, Debug)]
pub struct LoopInfo {
    /// Joint coordinates of the loop's joints (closing joint included).
    pub coordinates: usize,
    /// Numerical rank of the loop's twists at the CAD pose.
    pub rank: usize,
    /// `coordinates - rank`: the loop's instantaneous mobility on its own.
    pub mobility: usize,
    /// Equations the closing joint imposes when emitted plainly (`6 - its dof`).
    pub closing_equations: usize,
    /// Equations that are independent of the tree and of earlier loops' cuts.
    pub independent: usize,
    /// The common normal of a planar loop.
    pub planar_normal: Option<Vector3<f64>>,
    pub cut: Cut,
    /// Why the cut was emitted this way.
    pub why: String,
}

/// The loop pass's side table.
#[derive(Clone, Debug, Default)]
pub struct LoopAnalysis {
    pub loops: Vec<LoopInfo>,
}

/// The hierarchy, the chains and the loop analysis of a model.
pub struct Planned {
    pub hierarchy: Hierarchy,
    pub chains: Vec<Chain>,
    pub loops: LoopAnalysis,
    pub warnings: Vec<Warning>,
}

/// Builds the tree, moves cuts to joints that can take an exact cut, makes planar loops exactly
/// planar, and chooses every cut and every fixed start value.
pub fn plan(model: &Model) -> Result<Planned, TooManyLoops> {
    let mut cut_last = BTreeSet::new();
    let mut hierarchy = hierarchy::build(model);
    let kinematic = || hierarchy.loops.iter().filter(|l| l.kind == LoopKind::Kinematic);
    let (loops, joints) = (kinematic().count(), kinematic().map(|l| l.path.len() + 1).sum::<usize>());
    if loops > MAX_LOOPS || joints > MAX_LOOP_JOINTS {
        return Err(TooManyLoops { file: model.source.file.clone(), loops, joints });
    }
    let mut chains: Vec<Chain> = model.joints.iter().map(|j| kinematics::chain(model, j)).collect();
    // Each pass only adds joints to `cut_last`, so this ends; three passes suffice in practice.
    for _ in 0..4 {
        let before = cut_last.len();
        for l in hierarchy.loops.iter().filter(|l| l.kind == LoopKind::Kinematic) {
            if let Some(j) = better_cut(model, &chains, l) {
                cut_last.insert(j);
            }
        }
        if cut_last.len() == before {
            break;
        }
        hierarchy = hierarchy::build_with(model, &cut_last);
    }
    let normals = snap_planar(model, &hierarchy, &mut chains);
    let (loops, warnings) = choose_cuts(model, &hierarchy, &mut chains, &normals);
    Ok(Planned { hierarchy, chains, loops: LoopAnalysis { loops }, warnings })
}

/// Movable elements of a joint's chain.
fn dof(chain: &Chain) -> usize {
    chain.elements.iter().map(|e| if e.kind == PrimitiveKind::Spherical { 3 } else { 1 }).sum()
}

fn single(chain: &Chain, kind: PrimitiveKind) -> bool {
    chain.elements.len() == 1 && chain.elements[0].kind == kind
}

/// The common normal when every revolute of the loop is parallel (within [`PARALLEL_TOL`]) and
/// every prismatic perpendicular to it, with no spherical element.
fn planar_normal(loop_joints: &[JointId], chains: &[Chain]) -> Option<Vector3<f64>> {
    let elements: Vec<&Element> = loop_joints.iter().flat_map(|j| &chains[j.index()].elements).collect();
    let first = elements.iter().find(|e| e.kind == PrimitiveKind::Revolute)?.axis_world;
    let mut sum = Vector3::zeros();
    for e in &elements {
        match e.kind {
            PrimitiveKind::Revolute => {
                let a = if e.axis_world.dot(&first) < 0.0 { -e.axis_world } else { e.axis_world };
                if a.cross(&first).norm() > PARALLEL_TOL {
                    return None;
                }
                sum += a;
            }
            PrimitiveKind::Prismatic if e.axis_world.dot(&first).abs() <= PARALLEL_TOL => {}
            _ => return None,
        }
    }
    sum.try_normalize(1e-12)
}

fn loop_joints(l: &hierarchy::Loop) -> Vec<JointId> {
    std::iter::once(l.closing).chain(l.path.iter().copied()).collect()
}

/// A joint of the loop that takes an exact cut better than the current closing joint: a single
/// revolute for a planar loop closed elsewhere, or any single-element joint for a loop closed by
/// a joint of several elements. The highest `node_id` wins (stable across re-exports).
fn better_cut(model: &Model, chains: &[Chain], l: &hierarchy::Loop) -> Option<JointId> {
    let closing = &chains[l.closing.index()];
    let pick = |want: &dyn Fn(&Chain) -> bool| {
        l.path.iter().copied().filter(|j| want(&chains[j.index()])).max_by(|a, b| model.joint(*a).node_id.cmp(&model.joint(*b).node_id))
    };
    let planar = planar_normal(&loop_joints(l), chains).is_some();
    if planar && !single(closing, PrimitiveKind::Revolute) {
        return pick(&|c| single(c, PrimitiveKind::Revolute));
    }
    if closing.elements.len() > 1 {
        return pick(&|c| single(c, PrimitiveKind::Revolute)).or_else(|| pick(&|c| c.elements.len() == 1));
    }
    None
}

/// Replaces the axes of every planar loop's joints by the loop's common normal (loops that share
/// joints share one normal) and recomputes their chains. Returns each loop's normal.
fn snap_planar(model: &Model, h: &Hierarchy, chains: &mut [Chain]) -> Vec<Option<Vector3<f64>>> {
    let normals: Vec<Option<Vector3<f64>>> =
        h.loops.iter().map(|l| if l.kind == LoopKind::Kinematic { planar_normal(&loop_joints(l), chains) } else { None }).collect();
    // Groups of planar loops sharing a joint, merged by union-find over loop indices.
    let mut group = hierarchy::Dsu::new(normals.len());
    let mut owner = vec![None; model.joints.len()];
    for (i, l) in h.loops.iter().enumerate() {
        let Some(n) = normals[i] else { continue };
        for j in loop_joints(l) {
            match owner[j.index()] {
                None => owner[j.index()] = Some(i),
                Some(o) if normals[o].is_some_and(|m: Vector3<f64>| m.cross(&n).norm() <= PARALLEL_TOL) => {
                    group.union(o, i);
                }
                Some(_) => {}
            }
        }
    }
    let mut common: Vec<Vector3<f64>> = vec![Vector3::zeros(); normals.len()];
    for (i, normal) in normals.iter().enumerate() {
        if let Some(n) = *normal {
            let r = group.find(i);
            let n = if common[r].dot(&n) < 0.0 { -n } else { n };
            common[r] += n;
        }
    }
    let mut out = vec![None; normals.len()];
    for (i, l) in h.loops.iter().enumerate() {
        if normals[i].is_none() {
            continue;
        }
        let Some(n) = common[group.find(i)].try_normalize(1e-12) else { continue };
        out[i] = Some(n);
        for j in loop_joints(l) {
            if owner[j.index()] != Some(i) {
                continue;
            }
            let joint = model.joint(j);
            let axes: Vec<Option<Vector3<f64>>> = joint
                .primitives
                .iter()
                .map(|p| {
                    let a = kinematics::clean_axis(&p.axis_world)?;
                    match p.kind {
                        PrimitiveKind::Revolute => Some(if a.dot(&n) < 0.0 { -n } else { n }),
                        PrimitiveKind::Prismatic => (a - n * a.dot(&n)).try_normalize(1e-12),
                        _ => None,
                    }
                })
                .collect();
            chains[j.index()] = kinematics::chain_with_axes(model, joint, &axes);
        }
    }
    out
}

/// Twists of a chain's elements at the CAD pose, lengths relative to `c` and scaled by `1/len`:
/// `[omega; v]` with `v` the velocity of the point at `c`.
fn twists(chain: &Chain, c: &Vector3<f64>, len: f64) -> Vec<Vector6<f64>> {
    element_twists(chain, c, len).into_iter().map(|(_, t)| t).collect()
}

/// [`twists`], each with the index of the chain element it belongs to (a spherical element has
/// three).
fn element_twists(chain: &Chain, c: &Vector3<f64>, len: f64) -> Vec<(usize, Vector6<f64>)> {
    let mut out = Vec::new();
    for (k, e) in chain.elements.iter().enumerate() {
        let p = (e.origin_world - c) / len;
        match e.kind {
            PrimitiveKind::Revolute => out.push((k, stack(&e.axis_world, &p.cross(&e.axis_world)))),
            PrimitiveKind::Prismatic => out.push((k, stack(&Vector3::zeros(), &e.axis_world))),
            PrimitiveKind::Spherical => {
                for u in [Vector3::x(), Vector3::y(), Vector3::z()] {
                    out.push((k, stack(&u, &p.cross(&u))));
                }
            }
            PrimitiveKind::Weld => {}
        }
    }
    out
}

fn stack(a: &Vector3<f64>, b: &Vector3<f64>) -> Vector6<f64> {
    Vector6::new(a.x, a.y, a.z, b.x, b.y, b.z)
}

/// A unit force along `f` through `p` (scaled like the twists): `[p x f; f]`, so that a row is
/// `wrench . twist` (power).
fn force(p: &Vector3<f64>, f: &Vector3<f64>) -> Vector6<f64> {
    stack(&p.cross(f), f)
}

fn moment(m: &Vector3<f64>) -> Vector6<f64> {
    stack(m, &Vector3::zeros())
}

/// Numerical rank (singular values above [`RANK_TOL`]).
fn rank(m: &DMatrix<f64>) -> usize {
    if m.nrows() == 0 || m.ncols() == 0 {
        return 0;
    }
    m.clone().svd(false, false).singular_values.iter().filter(|s| **s > RANK_TOL).count()
}

/// A basis of the wrenches that do no work on any of `t` (its orthogonal complement).
fn annihilator(t: &[Vector6<f64>]) -> Vec<Vector6<f64>> {
    let mut m = DMatrix::<f64>::zeros(6, t.len().max(1));
    for (i, v) in t.iter().enumerate() {
        m.set_column(i, v);
    }
    let svd = nalgebra::linalg::SVD::new(m.clone() * m.transpose(), true, false);
    let Some(u) = svd.u else { return Vec::new() };
    (0..6).filter(|&i| svd.singular_values[i] <= RANK_TOL * RANK_TOL).map(|i| Vector6::from_iterator(u.column(i).iter().copied())).collect()
}

/// The rows `w . M` of constraint wrenches acting through the relative-twist map `m`.
fn rows_of(wrenches: &[Vector6<f64>], m: &DMatrix<f64>) -> Vec<DVector<f64>> {
    wrenches.iter().map(|w| (w.transpose() * m).transpose()).collect()
}

/// An orthonormal basis of the span of the rows accepted so far, grown one loop at a time, so that
/// testing a loop's rows costs a projection, not a decomposition of everything before it.
struct RowBasis {
    basis: Vec<DVector<f64>>,
    /// The accepted rows themselves (the cut equations on the tree coordinates).
    rows: Vec<DVector<f64>>,
}

impl RowBasis {
    /// The parts of `rows` independent of the basis, orthonormalised: as many as `rows` adds to
    /// the rank (singular values above [`RANK_TOL`]).
    fn gain(&self, rows: &[DVector<f64>]) -> Vec<DVector<f64>> {
        let Some(first) = rows.first() else { return Vec::new() };
        let mut m = DMatrix::<f64>::zeros(rows.len(), first.len());
        for (i, r) in rows.iter().enumerate() {
            let mut p = r.clone();
            for b in &self.basis {
                p -= b * b.dot(&p);
            }
            m.set_row(i, &p.transpose());
        }
        if m.ncols() == 0 {
            return Vec::new();
        }
        let svd = m.svd(false, true);
        let Some(v_t) = svd.v_t else { return Vec::new() };
        (0..svd.singular_values.len()).filter(|&i| svd.singular_values[i] > RANK_TOL).map(|i| v_t.row(i).transpose()).collect()
    }

    fn accept(&mut self, rows: Vec<DVector<f64>>) {
        let gained = self.gain(&rows);
        self.basis.extend(gained);
        self.rows.extend(rows);
    }
}

/// One tree coordinate on some loop: a column of the cut equations.
struct Column {
    joint: JointId,
    /// The chain element it moves.
    element: usize,
    /// Its place among the joint's columns (a spherical element has three).
    index: usize,
    /// Its unit twist (scaled like every twist here).
    twist: Vector6<f64>,
}

/// A candidate cut: the form and its constraint wrenches (world, scaled).
struct Candidate {
    cut: Cut,
    wrenches: Vec<Vector6<f64>>,
}

/// The orthonormal frame a constraint cut is written in: z along `axis`, x from the element
/// frame's axis most perpendicular to it, turned by `turn` about z.
fn cut_frame(frame: &Matrix3<f64>, axis: &Vector3<f64>, turn: f64) -> Matrix3<f64> {
    let z = *axis;
    let best = (0..3).map(|i| frame.column(i).into_owned()).min_by(|a, b| a.dot(&z).abs().total_cmp(&b.dot(&z).abs()));
    let x0 = best.map(|x| x - z * x.dot(&z)).and_then(|x| x.try_normalize(1e-9)).unwrap_or_else(|| perpendicular(&z));
    let x = Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(z), turn) * x0;
    Matrix3::from_columns(&[x, z.cross(&x), z])
}

/// A unit vector perpendicular to unit `z` (from world x, or y when `z` is near x).
pub(crate) fn perpendicular(z: &Vector3<f64>) -> Vector3<f64> {
    let t = if z.x.abs() < 0.9 { Vector3::x() } else { Vector3::y() };
    (t - z * t.dot(z)).normalize()
}

/// Moment options of a cut: the class, which cut-frame axes carry a moment, `n` and `n_b` as
/// cut-frame axis indices (0 = x, 1 = y, 2 = z).
type MomentOption = (ConstraintClass, [bool; 3], usize, usize);

/// Every form a single-element cut can take, most natural first.
fn candidates(e: &Element, frame_a: &Matrix3<f64>, planar: Option<Vector3<f64>>, p: &Vector3<f64>) -> Vec<Candidate> {
    let mut out = Vec::new();
    let (axis, forces_allowed, moments): (Vector3<f64>, [bool; 3], Vec<MomentOption>) = match e.kind {
        PrimitiveKind::Revolute => (
            e.axis_world,
            [true; 3],
            vec![
                (ConstraintClass::Spherical, [false; 3], 2, 0),
                (ConstraintClass::Revolute, [true, true, false], 2, 0),
                (ConstraintClass::Universal, [false, true, false], 2, 0),
                (ConstraintClass::Universal, [true, false, false], 2, 1),
            ],
        ),
        PrimitiveKind::Prismatic => (
            e.axis_world,
            [true, true, false],
            vec![
                (ConstraintClass::Prismatic, [true; 3], 2, 0),
                (ConstraintClass::Revolute, [true, true, false], 2, 0),
                (ConstraintClass::Revolute, [false, true, true], 0, 0),
                (ConstraintClass::Revolute, [true, false, true], 1, 0),
                (ConstraintClass::Universal, [false, false, true], 0, 1),
                (ConstraintClass::Universal, [true, false, false], 1, 2),
                (ConstraintClass::Universal, [false, true, false], 2, 0),
                (ConstraintClass::Spherical, [false; 3], 2, 0),
            ],
        ),
        PrimitiveKind::Spherical => (frame_a.column(2).into_owned(), [true; 3], vec![(ConstraintClass::Spherical, [false; 3], 2, 0)]),
        PrimitiveKind::Weld => return out,
    };
    if let (PrimitiveKind::Revolute, Some(n)) = (e.kind, planar) {
        if n.cross(&axis).norm() <= PARALLEL_TOL {
            let f = cut_frame(frame_a, &axis, 0.0);
            out.push(Candidate {
                cut: Cut::PlanarLoopConstraint,
                wrenches: vec![force(p, &f.column(0).into_owned()), force(p, &f.column(1).into_owned())],
            });
        }
    }
    let subsets: [[bool; 3]; 8] = [
        [true, true, true],
        [true, true, false],
        [true, false, true],
        [false, true, true],
        [true, false, false],
        [false, true, false],
        [false, false, true],
        [false, false, false],
    ];
    for turn in [0.0, std::f64::consts::FRAC_PI_4] {
        let f = if e.kind == PrimitiveKind::Spherical { *frame_a } else { cut_frame(frame_a, &axis, turn) };
        let axes = [f.column(0).into_owned(), f.column(1).into_owned(), f.column(2).into_owned()];
        let rel = UnitQuaternion::from_matrix(&(frame_a.transpose() * f));
        for (class, m, n, n_b) in &moments {
            for locked in subsets.iter().filter(|s| (0..3).all(|i| !s[i] || forces_allowed[i])) {
                let mut w: Vec<Vector6<f64>> = (0..3).filter(|&i| locked[i]).map(|i| force(p, &axes[i])).collect();
                w.extend((0..3).filter(|&i| m[i]).map(|i| moment(&axes[i])));
                let unit = |i: usize| Vector3::from_fn(|r, _| if r == i { 1.0 } else { 0.0 });
                // Locking every translation (or none) without a moment does not depend on the
                // axes: keep the element's own frame, so no extra rotation is emitted.
                let any_axes = *class == ConstraintClass::Spherical && (locked.iter().all(|l| *l) || locked.iter().all(|l| !*l));
                let axes = if any_axes { UnitQuaternion::identity() } else { rel };
                out.push(Candidate {
                    cut: Cut::Constraint(ConstraintCut { class: *class, axes, locked: *locked, n: unit(*n), n_b: unit(*n_b) }),
                    wrenches: w,
                });
            }
        }
        if e.kind == PrimitiveKind::Spherical {
            break;
        }
    }
    out
}

/// Chooses every loop's cut and the fixed start values.
fn choose_cuts(model: &Model, h: &Hierarchy, chains: &mut [Chain], normals: &[Option<Vector3<f64>>]) -> (Vec<LoopInfo>, Vec<Warning>) {
    let kinematic: Vec<usize> = (0..h.loops.len()).filter(|&i| h.loops[i].kind == LoopKind::Kinematic).collect();
    // Scale: the centroid and extent of every loop joint's element origins.
    let origins: Vec<Vector3<f64>> = kinematic
        .iter()
        .flat_map(|&i| loop_joints(&h.loops[i]))
        .flat_map(|j| chains[j.index()].elements.iter().map(|e| e.origin_world))
        .collect();
    let c = if origins.is_empty() { Vector3::zeros() } else { origins.iter().sum::<Vector3<f64>>() / origins.len() as f64 };
    let len = origins.iter().map(|o| (o - c).norm()).fold(1e-6, f64::max);

    // Columns: the elements of every tree joint on some loop.
    let mut column_of: Vec<Option<usize>> = vec![None; model.joints.len()];
    let mut columns: Vec<Column> = Vec::new();
    for &i in &kinematic {
        for &j in &h.loops[i].path {
            if column_of[j.index()].is_none() {
                column_of[j.index()] = Some(columns.len());
                for (k, (element, twist)) in element_twists(&chains[j.index()], &c, len).into_iter().enumerate() {
                    columns.push(Column { joint: j, element, index: k, twist });
                }
            }
        }
    }
    let ncols = columns.len();
    let mut a = RowBasis { basis: Vec::new(), rows: Vec::new() };
    let mut infos = Vec::new();
    let mut warnings = Vec::new();
    for (i, l) in h.loops.iter().enumerate() {
        let closing = model.joint(l.closing);
        let cchain = &chains[l.closing.index()];
        if l.kind == LoopKind::Rigid {
            warnings.push(omitted(
                closing,
                "redundant-weld",
                format!("weld \"{}\" closes a loop of welds only; it is redundant and not emitted", closing.cad_name),
            ));
            infos.push(LoopInfo {
                coordinates: 0,
                rank: 0,
                mobility: 0,
                closing_equations: 6,
                independent: 0,
                planar_normal: None,
                cut: Cut::Omitted,
                why: "a weld closing a loop of welds: its 6 equations repeat what the tree's welds impose".into(),
            });
            continue;
        }
        // Relative twist of the closing joint's follower side w.r.t. its base side through the tree.
        let mut m = DMatrix::<f64>::zeros(6, ncols);
        for (pos, j) in l.path.iter().enumerate() {
            let toward_follower = pos >= l.base_side;
            let sign = if toward_follower == h.follower_is_child[j.index()] { 1.0 } else { -1.0 };
            let Some(start) = column_of[j.index()] else { continue };
            let n = dof(&chains[j.index()]);
            for k in 0..n {
                m.set_column(start + k, &(columns[start + k].twist * sign));
            }
        }
        // The loop alone: its twists' rank and mobility.
        let mut own: Vec<Vector6<f64>> = twists(cchain, &c, len);
        for j in &l.path {
            own.extend(twists(&chains[j.index()], &c, len));
        }
        let coordinates = own.len();
        let loop_rank = rank(&DMatrix::from_fn(6, coordinates.max(1), |r, k| own.get(k).map_or(0.0, |t| t[r])));
        let closing_equations = 6 - dof(cchain).min(6);
        let plain = annihilator(&twists(cchain, &c, len));
        let independent = a.gain(&rows_of(&plain, &m)).len();
        let redundant = closing_equations.saturating_sub(independent);
        let plain_name = describe(cchain);
        let mut info = LoopInfo {
            coordinates,
            rank: loop_rank,
            mobility: coordinates - loop_rank,
            closing_equations,
            independent,
            planar_normal: normals[i],
            cut: Cut::Redundant,
            why: String::new(),
        };
        let chosen = if independent == 0 {
            if !closing.is_weld() {
                warnings.push(omitted(
                    closing,
                    "loop-joint-omitted",
                    format!(
                        "joint \"{}\" cannot move: the joints it closes a loop with already fix its two sides to each other, so it is not emitted",
                        closing.cad_name
                    ),
                ));
            }
            Some(Candidate { cut: Cut::Omitted, wrenches: Vec::new() })
        } else if redundant == 0 {
            Some(Candidate { cut: Cut::Joint, wrenches: plain.clone() })
        } else if cchain.elements.len() == 1 {
            let e = &cchain.elements[0];
            let frame_a = element_frame(model, closing, cchain);
            let p = (e.origin_world - c) / len;
            candidates(e, &frame_a, normals[i], &p)
                .into_iter()
                .filter(|cand| cand.wrenches.len() == independent)
                .find(|cand| a.gain(&rows_of(&cand.wrenches, &m)).len() == independent)
        } else {
            None
        };
        match chosen {
            Some(cand) => {
                info.why = explain(&cand.cut, &plain_name, closing_equations, independent, normals[i].is_some());
                a.accept(rows_of(&cand.wrenches, &m));
                info.cut = cand.cut;
            }
            None => {
                a.accept(rows_of(&plain, &m));
                let names: Vec<&str> = loop_joints(l).iter().map(|j| model.joint(*j).cad_name.as_str()).collect();
                info.why = format!(
                    "a plain {plain_name} would impose {closing_equations} equations of which only {independent} are independent, and no MSL cut imposes exactly those: emitted as it is, with {redundant} redundant"
                );
                warnings.push(Warning::new(
                    "loop-redundant",
                    format!(
                        "the loop through joints {} is closed by \"{}\" with {redundant} redundant constraint equations (rank {loop_rank} of {coordinates} coordinates): Modelica tools may report the model as structurally singular",
                        crate::pipeline::ir::bounded_list(&names.iter().map(|n| format!("\"{n}\"")).collect::<Vec<_>>(), 20),
                        closing.cad_name
                    ),
                    format!("{} (joint nodeID \"{}\")", closing.loc, closing.node_id),
                ));
            }
        }
        infos.push(info);
    }
    fix_independent(h, chains, &a.rows, &columns);
    (infos, warnings)
}

/// A warning about a closing joint that is not emitted, located at the joint.
fn omitted(joint: &crate::pipeline::ir::Joint, code: &'static str, message: String) -> Warning {
    Warning::new(code, message, format!("{} (joint nodeID \"{}\")", joint.loc, joint.node_id))
}

/// World orientation of the closing joint's last element frame_a at the CAD pose.
fn element_frame(model: &Model, joint: &crate::pipeline::ir::Joint, chain: &Chain) -> Matrix3<f64> {
    let mut r = model.frame(joint.base).pose.rotation;
    for e in chain.elements.iter().take(chain.elements.len().saturating_sub(1)) {
        r *= e.motion(e.q0).rotation;
    }
    r.to_rotation_matrix().into_inner()
}

fn describe(chain: &Chain) -> String {
    match chain.elements.as_slice() {
        [e] => e.kind.as_str().to_string(),
        [] => "rigid joint".to_string(),
        es => format!("{} joint", es.iter().map(|e| e.kind.as_str()).collect::<Vec<_>>().join("+")),
    }
}

fn explain(cut: &Cut, plain: &str, equations: usize, k: usize, planar: bool) -> String {
    let repeated = equations - k;
    let head = if repeated == 0 {
        format!("all {equations} equations of the {plain} are independent")
    } else {
        format!("a plain {plain} would repeat {repeated} of its {equations} equations ({k} independent)")
    };
    match cut {
        Cut::Joint | Cut::Redundant => head,
        Cut::Omitted => format!("the rest of the mechanism already implies all {equations} equations of the {plain}: not emitted"),
        Cut::PlanarLoopConstraint => format!(
            "{head}; the loop is planar{}, so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations",
            if planar {
                " (axes parallel within 1e-4 rad, emitted exactly parallel; a change beyond 1e-12 rad is in the joint's corrections)"
            } else {
                ""
            }
        ),
        Cut::Constraint(cc) => {
            let mut s = format!("{head}; Joints.Constraints.{} imposes exactly those", cc.class.name());
            let locks: Vec<&str> = ["x", "y", "z"].iter().zip(cc.locked).filter(|(_, l)| *l).map(|(a, _)| *a).collect();
            let _ = write!(s, " (translations locked: {})", if locks.is_empty() { "none".to_string() } else { locks.join(", ") });
            s
        }
    }
}

/// Marks the start values of loop coordinates: the dependent ones (a set of columns on which the
/// cut equations have full rank, chosen far from the ground first, spherical elements always) get
/// only a guess, the independent ones stay fixed. Closing joints are never fixed.
fn fix_independent(h: &Hierarchy, chains: &mut [Chain], rows: &[DVector<f64>], columns: &[Column]) {
    for l in h.loops.iter().filter(|l| l.kind == LoopKind::Kinematic) {
        for e in &mut chains[l.closing.index()].elements {
            e.fixed = false;
        }
        // Spherical elements in loops have no states to fix.
        for j in &l.path {
            for e in &mut chains[j.index()].elements {
                if e.kind == PrimitiveKind::Spherical {
                    e.fixed = false;
                }
            }
        }
    }
    let needed = RowBasis { basis: Vec::new(), rows: Vec::new() }.gain(rows).len();
    if needed == 0 {
        return;
    }
    // Column `c` of the equations.
    let column = |c: usize| DVector::from_iterator(rows.len(), rows.iter().map(|r| r[c]));
    let bfs_rank = |j: JointId| h.tree.iter().position(|t| *t == j).unwrap_or(usize::MAX);
    let spherical = |c: &Column| chains[c.joint.index()].elements[c.element].kind == PrimitiveKind::Spherical;
    let mut order: Vec<usize> = (0..columns.len()).collect();
    order.sort_by_key(|&c| (!spherical(&columns[c]), std::cmp::Reverse(bfs_rank(columns[c].joint)), std::cmp::Reverse(columns[c].index)));
    // Greedy: a column is dependent when it adds to the rank of the dependent columns so far.
    let mut basis: Vec<DVector<f64>> = Vec::new();
    let mut free = Vec::new();
    for c in order {
        if basis.len() == needed {
            break;
        }
        let mut p = column(c);
        for b in &basis {
            p -= b * b.dot(&p);
        }
        let norm = p.norm();
        if norm > RANK_TOL {
            basis.push(p / norm);
            free.push((columns[c].joint, columns[c].element));
        }
    }
    for (j, k) in free {
        chains[j.index()].elements[k].fixed = false;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::ir::{Joint, Primitive, SourceLoc};

    fn model(case: &str) -> Model {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/in").join(case);
        let bundle = crate::test_bundle_of_dir(&dir).expect("bundle");
        let xml = bundle.paths().find(|p| p.ends_with(".xml")).expect("xml").to_string();
        crate::pipeline::front::simmechanics::parse(&xml, bundle.get(&xml).unwrap_or_default()).expect("parses").0
    }

    fn joint_named<'a>(m: &'a mut Model, name: &str) -> &'a mut Joint {
        m.joints.iter_mut().find(|j| j.cad_name == name).expect("joint")
    }

    fn only_loop(p: &Planned) -> (&hierarchy::Loop, &LoopInfo) {
        let i = p.hierarchy.loops.iter().position(|l| l.kind == LoopKind::Kinematic).expect("a kinematic loop");
        (&p.hierarchy.loops[i], &p.loops.loops[i])
    }

    #[test]
    fn thousands_of_loops_are_refused_early() {
        // One body hinged to the ground by 300 parallel revolutes: 299 independent loops.
        let mut m = model("pendulum");
        let revolute = m.joints.iter().position(|j| !j.is_weld()).expect("revolute");
        for k in 0..299 {
            let mut j = m.joints[revolute].clone();
            j.node_id = format!("{}-{k:03}", j.node_id);
            m.joints.push(j);
        }
        let e = plan(&m).err().expect("refused");
        assert_eq!((e.loops, e.joints), (299, 598));
        assert!(e.to_string().contains("at most 256 loops"), "{e}");
    }

    #[test]
    fn planar_within_the_data_precision_only() {
        // 5e-5 rad off parallel: planar at 6-digit precision, and emitted exactly planar.
        let mut m = model("fourbar");
        joint_named(&mut m, "CRANK--COUPLER").primitives[0].axis_world = Vector3::new(5e-5, 0.0, 1.0);
        let p = plan(&m).expect("plan");
        let (l, info) = only_loop(&p);
        assert_eq!(info.cut, Cut::PlanarLoopConstraint);
        assert_eq!((info.rank, info.mobility, info.independent), (3, 1, 2));
        let n = info.planar_normal.expect("normal");
        let mut stated = 0;
        for j in std::iter::once(&l.closing).chain(&l.path) {
            let joint = m.joint(*j);
            for (e, prim) in p.chains[j.index()].elements.iter().zip(&joint.primitives) {
                assert!(e.axis_world.cross(&n).norm() < 1e-15, "{:?}", e.axis_world);
                // Every snapped axis states its angle from the source axis, and why.
                let src = prim.axis_world.normalize();
                let angle = src.cross(&e.axis_world).norm().atan2(src.dot(&e.axis_world));
                match &e.correction {
                    Some(c) => {
                        assert!((c.axis_rad - angle).abs() < 1e-15 && c.origin_m == 0.0, "{}: {c:?} vs {angle:e}", joint.cad_name);
                        assert!(c.why.contains("planar loop") && c.why.contains("RevolutePlanarLoopConstraint"), "{}", c.why);
                        stated += 1;
                    }
                    None => assert!(angle <= 1e-12, "{}: axis moved {angle:e} rad unreported", joint.cad_name),
                }
            }
        }
        // The common normal is the mean: the tilted axis moves 3/4 of its 5e-5 rad, the others 1/4.
        assert_eq!(stated, 4);
        // 1e-3 rad off: a spatial loop of four revolutes, immobile; the cut imposes 3 forces.
        let mut m = model("fourbar");
        joint_named(&mut m, "CRANK--COUPLER").primitives[0].axis_world = Vector3::new(1e-3, 0.0, 1.0);
        let p = plan(&m).expect("plan");
        let (_, info) = only_loop(&p);
        assert_eq!((info.rank, info.mobility, info.independent, info.planar_normal), (4, 0, 3, None));
        assert!(
            matches!(&info.cut, Cut::Constraint(c) if c.class == ConstraintClass::Spherical && c.locked == [true; 3]),
            "{:?}",
            info.cut
        );
    }

    #[test]
    fn a_cut_moves_off_a_joint_of_several_elements() {
        let mut m = model("fourbar");
        // The closing joint becomes a universal joint: the cut moves to a single revolute and the
        // universal joint joins the tree.
        let closing = plan(&m).expect("plan").hierarchy.loops[0].closing;
        m.joints[closing.index()].primitives.push(Primitive {
            kind: PrimitiveKind::Revolute,
            axis_world: Vector3::x(),
            losses: Default::default(),
            loc: SourceLoc::default(),
        });
        let p = plan(&m).expect("plan");
        let (l, info) = only_loop(&p);
        assert_ne!(l.closing, closing);
        assert!(l.path.contains(&closing));
        assert_eq!(p.chains[l.closing.index()].elements.len(), 1);
        // The universal's second axis leaves the plane, so the loop has rank 4 of 5 coordinates
        // (mobility 1: the planar motion) and the closing revolute adds 4 - 1 = 3 independent
        // equations of its 5: three forces, no moment.
        assert_eq!((info.coordinates, info.rank, info.mobility, info.independent), (5, 4, 1, 3), "{info:?}");
        assert!(matches!(&info.cut, Cut::Constraint(c) if c.class == ConstraintClass::Spherical), "{:?}", info.cut);
    }

    #[test]
    fn a_joint_the_rest_already_implies_is_omitted() {
        // A revolute doubled by a weld between the same two bodies: it can never move.
        let mut m = model("pendulum");
        let mut weld = m.joints[0].clone();
        weld.node_id = format!("{}-weld", weld.node_id);
        weld.primitives = vec![Primitive {
            kind: PrimitiveKind::Weld,
            axis_world: Vector3::zeros(),
            losses: Default::default(),
            loc: SourceLoc::default(),
        }];
        let revolute = m.joints.iter().position(|j| !j.is_weld()).expect("revolute");
        weld.base = m.joints[revolute].base;
        weld.follower = m.joints[revolute].follower;
        m.joints.push(weld);
        let p = plan(&m).expect("plan");
        let (l, info) = only_loop(&p);
        assert_eq!(l.closing.index(), revolute);
        assert_eq!((info.independent, info.cut.clone()), (0, Cut::Omitted));
        assert_eq!(p.warnings.len(), 1, "{:?}", p.warnings);
        assert_eq!(p.warnings[0].code, "loop-joint-omitted");
    }
}
