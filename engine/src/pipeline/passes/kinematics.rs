//! Joint kinematics: how each joint's primitive chain reproduces the CAD pose.
//!
//! A joint runs from its base frame B to its follower frame F. Its primitives become a serial
//! chain of elements with no mass in between. Each element's axis is resolved in the element's
//! own `frame_a` at the CAD pose; its start coordinate is the CAD offset; whatever the chain cannot
//! express (CAD noise, frames that do not coincide where they should) goes into a fixed `residual`
//! transform between the last element and F. Forward kinematics of the chain at the start values,
//! followed by the residual, gives F exactly, by construction:
//!
//! - prismatic displacements `s` are the least-squares fit of `p_F - p_B` onto the prismatic axes;
//! - revolute angles are the twist (about the element axis) of the rotation still missing;
//! - spherical elements start at the identity; the rotation they would carry is in the residual;
//! - weld primitives add nothing.
//!
//! Axes are normalised, and components below 1e-9 (CAD noise) snapped to zero, *before* the start
//! values are computed, so the snapping never moves a frame. The loop pass may replace the world
//! axes of a planar loop's joints by the loop's common normal ([`chain_with_axes`]); those are
//! snapped only below 1e-12, so the emitted axes stay parallel to about 1e-12 rad.
//!
//! Where the prismatic axes cannot take all of `p_F - p_B` (frames written relative to other
//! frames and rounded to 6 digits leave gaps of ~1e-7 m) and every prismatic comes before every
//! rotational element, the gap goes in front of the chain ([`Chain::pre`]): a prismatic slides
//! the same along any parallel line, so moving its line costs nothing, and the revolute (or
//! spherical) after it keeps its XML joint point, the follower frame's origin, exactly.
//!
//! Every element whose emitted axis or origin differs from the source's by more than 1e-12
//! carries a [`Correction`] (angle, distance, why), which the report states.

use nalgebra::{DMatrix, DVector, Isometry3, Translation3, Unit, UnitQuaternion, Vector3};
use serde::Serialize;

use crate::pipeline::ir::{Joint, Model, PrimitiveKind, Warning};

/// One element of a joint chain.
#[derive(Clone, Debug)]
pub struct Element {
    pub kind: PrimitiveKind,
    /// Unit axis in the element's frame_a (zero vector for spherical).
    pub axis: Vector3<f64>,
    /// Start coordinate: rad (revolute) or m (prismatic); 0 for spherical.
    pub q0: f64,
    /// The axis in world coordinates at the CAD pose (zero vector for spherical).
    pub axis_world: Vector3<f64>,
    /// Where the element's frame_a is in the world at the CAD pose (m).
    pub origin_world: Vector3<f64>,
    /// Whether the start value is fixed (`fixed=true`): always outside loops; in a loop, for the
    /// independent coordinates the loop pass chooses.
    pub fixed: bool,
    /// How far the emitted axis and origin are from the source's, when more than
    /// [`CORRECTION_TOL`].
    pub correction: Option<Correction>,
}

/// A joint element emitted other than the source wrote it: the angle between the emitted and
/// the source axis, the distance of the emitted origin (a revolute's axis line, a spherical's
/// centre, a prismatic's line) from the source's joint point, and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Correction {
    pub axis_rad: f64,
    pub origin_m: f64,
    pub why: String,
}

/// Deviations from the source at or below this (rad, m) are exact and not stated.
pub const CORRECTION_TOL: f64 = 1e-12;

/// The emitted form of one joint.
#[derive(Clone, Debug)]
pub struct Chain {
    /// Movable elements in XML order (welds dropped). Empty for a rigid joint.
    pub elements: Vec<Element>,
    /// Fixed transform from the last element's frame_b (or B when there is none) to F, expressed
    /// in that frame.
    pub residual: Isometry3<f64>,
    /// Fixed translation from B to the first element's frame_a, in B's axes: the gap the
    /// prismatic axes cannot take, placed in front of them (see the module documentation);
    /// the identity almost always.
    pub pre: Isometry3<f64>,
}

/// The motion of one element at coordinate `q`: a rotation about its unit `axis` by `q` rad
/// (revolute) or a translation along it by `q` m (prismatic); the identity for the others.
pub fn element_motion(kind: PrimitiveKind, axis: &Vector3<f64>, q: f64) -> Isometry3<f64> {
    match kind {
        PrimitiveKind::Revolute => {
            Isometry3::from_parts(Translation3::identity(), UnitQuaternion::from_axis_angle(&Unit::new_unchecked(*axis), q))
        }
        PrimitiveKind::Prismatic => Isometry3::translation(axis.x * q, axis.y * q, axis.z * q),
        PrimitiveKind::Spherical | PrimitiveKind::Weld => Isometry3::identity(),
    }
}

impl Element {
    /// This element's motion at coordinate `q` ([`element_motion`]).
    pub fn motion(&self, q: f64) -> Isometry3<f64> {
        element_motion(self.kind, &self.axis, q)
    }
}

/// Smallest residual translation (m) and rotation (rad) still emitted; below this the chain
/// connects straight to the follower frame.
pub const IDENTITY_TOL: f64 = 1e-12;

/// Tolerance for "frames coincide" warnings: 10 µm and 1e-4 rad (CAD prints 6 digits).
pub const COINCIDE_TOL_M: f64 = 1e-5;
pub const COINCIDE_TOL_RAD: f64 = 1e-4;

pub fn is_identity(iso: &Isometry3<f64>) -> bool {
    iso.translation.vector.norm() <= IDENTITY_TOL && rotation_angle(&iso.rotation) <= IDENTITY_TOL
}

/// Rotation angle in [0, pi], accurate near zero (`UnitQuaternion::angle` uses `acos` and cannot
/// see angles below about 3e-8 rad).
pub fn rotation_angle(q: &UnitQuaternion<f64>) -> f64 {
    2.0 * q.imag().norm().atan2(q.w.abs())
}

/// Axis components below this are CAD noise and snapped to zero.
pub const AXIS_SNAP: f64 = 1e-9;

/// Normalises and snaps CAD noise; `None` for a zero or non-finite axis.
pub fn clean_axis(v: &Vector3<f64>) -> Option<Vector3<f64>> {
    snap_axis(v, AXIS_SNAP)
}

/// Normalises and snaps components below `snap` to zero; `None` for a zero or non-finite axis.
fn snap_axis(v: &Vector3<f64>, snap: f64) -> Option<Vector3<f64>> {
    let n = v.try_normalize(1e-12)?;
    let snapped = n.map(|c| if c.abs() < snap { 0.0 } else { c });
    snapped.try_normalize(1e-12).filter(|n| n.iter().all(|c| c.is_finite()))
}

/// Twist angle of `r` about unit axis `n`, in (-pi, pi].
pub fn twist_angle(r: &UnitQuaternion<f64>, n: &Vector3<f64>) -> f64 {
    let q = r.quaternion();
    let a = 2.0 * q.imag().dot(n).atan2(q.w);
    // atan2 gives (-pi, pi] for the half angle; the full angle may leave the range.
    let two_pi = std::f64::consts::TAU;
    let mut a = a % two_pi;
    if a > std::f64::consts::PI {
        a -= two_pi;
    } else if a <= -std::f64::consts::PI {
        a += two_pi;
    }
    a
}

/// Computes the chain of `joint`. Primitives whose axis is zero are treated as welds; the caller
/// (validation) reports them.
pub fn chain(model: &Model, joint: &Joint) -> Chain {
    chain_with_axes(model, joint, &[])
}

/// [`chain`] with world axes replaced: `axes[i]`, when given, is primitive `i`'s unit world axis
/// (a planar loop's common normal), snapped in the element frame only below 1e-12.
pub fn chain_with_axes(model: &Model, joint: &Joint, axes: &[Option<Vector3<f64>>]) -> Chain {
    let b = model.frame(joint.base).pose;
    let f = model.frame(joint.follower).pose;
    let world = |i: usize, p: &crate::pipeline::ir::Primitive| match axes.get(i).copied().flatten() {
        Some(a) => (snap_axis(&a, 1e-15), 1e-12),
        None => (clean_axis(&p.axis_world), AXIS_SNAP),
    };

    // Least-squares prismatic displacements from the world axes.
    let prismatic_axes: Vec<Vector3<f64>> = joint
        .primitives
        .iter()
        .enumerate()
        .filter(|(_, p)| p.kind == PrimitiveKind::Prismatic)
        .filter_map(|(i, p)| world(i, p).0)
        .collect();
    let d = f.translation.vector - b.translation.vector;
    let s = least_squares(&prismatic_axes, &d);
    let gap = d - prismatic_axes.iter().zip(&s).map(|(a, s)| a * *s).sum::<Vector3<f64>>();

    // Movable primitives in order, and whether the prismatics all come first.
    let movable: Vec<(usize, PrimitiveKind)> =
        joint.primitives.iter().enumerate().filter(|(_, p)| p.kind != PrimitiveKind::Weld).map(|(i, p)| (i, p.kind)).collect();
    let first_rotational = movable.iter().position(|(_, k)| *k != PrimitiveKind::Prismatic).unwrap_or(movable.len());
    let prismatic_first = first_rotational > 0
        && first_rotational < movable.len()
        && movable[first_rotational..].iter().all(|(_, k)| *k != PrimitiveKind::Prismatic);
    let pre_world = if prismatic_first && gap.norm() > IDENTITY_TOL { gap } else { Vector3::zeros() };
    let pre = Isometry3::from_parts(Translation3::from(b.rotation.inverse() * pre_world), UnitQuaternion::identity());
    // The source's joint point for a rotational element: B before any prismatic, F after all
    // of them; none between prismatics.
    let last_prismatic = movable.iter().rposition(|(_, k)| *k == PrimitiveKind::Prismatic);
    let first_prismatic = movable.iter().position(|(_, k)| *k == PrimitiveKind::Prismatic);
    let source_point = |i: usize| match (first_prismatic, last_prismatic) {
        (Some(fp), _) if i < movable[fp].0 => Some(b.translation.vector),
        (_, Some(lp)) if i > movable[lp].0 => Some(f.translation.vector),
        (None, None) => Some(b.translation.vector),
        _ => None,
    };

    let mut cur = b;
    cur.translation.vector += pre_world;
    let mut elements = Vec::new();
    let mut k = 0;
    for (i, p) in joint.primitives.iter().enumerate() {
        match p.kind {
            PrimitiveKind::Weld => {}
            PrimitiveKind::Spherical => {
                let origin_world = cur.translation.vector;
                let origin_m = source_point(i).map_or(0.0, |c| (c - origin_world).norm());
                elements.push(Element {
                    kind: p.kind,
                    axis: Vector3::zeros(),
                    q0: 0.0,
                    axis_world: Vector3::zeros(),
                    origin_world,
                    fixed: true,
                    correction: correction(0.0, origin_m, || moved_point_why(gap.norm(), &pre_world)),
                });
            }
            PrimitiveKind::Revolute | PrimitiveKind::Prismatic => {
                let (Some(world_axis), snap) = world(i, p) else { continue };
                let Some(axis) = snap_axis(&(cur.rotation.inverse() * world_axis), snap) else { continue };
                let origin_world = cur.translation.vector;
                let emitted = cur.rotation * axis;
                let axis_rad = p.axis_world.try_normalize(0.0).map_or(0.0, |src| src.cross(&emitted).norm().atan2(src.dot(&emitted)));
                let axis_why = || {
                    if axes.get(i).copied().flatten().is_some() {
                        if p.kind == PrimitiveKind::Revolute {
                            "axis made exactly parallel to its planar loop's common normal (the loop's axes agree within 1e-4 rad), so that RevolutePlanarLoopConstraint closes the loop".to_string()
                        } else {
                            "axis made exactly perpendicular to its planar loop's common normal, so that the loop stays planar".to_string()
                        }
                    } else {
                        "axis components below 1e-9 (CAD noise) snapped to zero".to_string()
                    }
                };
                if p.kind == PrimitiveKind::Revolute {
                    let missing = cur.rotation.inverse() * f.rotation;
                    let q0 = twist_angle(&missing, &axis);
                    cur.rotation *= UnitQuaternion::from_axis_angle(&Unit::new_unchecked(axis), q0);
                    let origin_m = source_point(i).map_or(0.0, |c| (c - origin_world).cross(&emitted).norm());
                    let why = || join_why(axis_rad, axis_why, origin_m, || moved_point_why(gap.norm(), &pre_world));
                    let correction = correction(axis_rad, origin_m, why);
                    elements.push(Element { kind: p.kind, axis, q0, axis_world: world_axis, origin_world, fixed: true, correction });
                } else {
                    let q0 = s.get(k).copied().unwrap_or(0.0);
                    k += 1;
                    cur.translation.vector += cur.rotation * (axis * q0);
                    let origin_m = pre_world.norm();
                    let line_why = || {
                        format!(
                            "the {origin_m:.3e} m the prismatic axes cannot take between the base and follower frames (rounding of the source's frames) moves this prismatic's line, along which it slides the same; the start value takes the part along the axis, and the revolute or spherical after it keeps the follower frame's origin"
                        )
                    };
                    let correction = correction(axis_rad, origin_m, || join_why(axis_rad, axis_why, origin_m, line_why));
                    elements.push(Element { kind: p.kind, axis, q0, axis_world: world_axis, origin_world, fixed: true, correction });
                }
            }
        }
    }
    let mut residual = cur.inverse() * f;
    if residual.translation.vector.norm() <= IDENTITY_TOL {
        residual.translation = Translation3::identity();
    }
    if rotation_angle(&residual.rotation) <= IDENTITY_TOL {
        residual.rotation = UnitQuaternion::identity();
    }
    Chain { elements, residual, pre }
}

fn correction(axis_rad: f64, origin_m: f64, why: impl FnOnce() -> String) -> Option<Correction> {
    (axis_rad > CORRECTION_TOL || origin_m > CORRECTION_TOL).then(|| Correction { axis_rad, origin_m, why: why() })
}

fn join_why(axis_rad: f64, axis: impl FnOnce() -> String, origin_m: f64, origin: impl FnOnce() -> String) -> String {
    match (axis_rad > CORRECTION_TOL, origin_m > CORRECTION_TOL) {
        (true, true) => format!("{}; {}", axis(), origin()),
        (true, false) => axis(),
        _ => origin(),
    }
}

/// Why a rotational element's point is off the source's joint point: the frames' offset that no
/// prismatic takes stays behind the chain (`joint-frames-apart` when beyond 10 µm).
fn moved_point_why(gap: f64, pre: &Vector3<f64>) -> String {
    if pre.norm() > 0.0 {
        "the element's point follows the prismatic line moved by the frames' gap".to_string()
    } else {
        format!(
            "the base and follower frames are {gap:.3e} m apart beyond what the joint's prismatic axes take; the offset is kept as a fixed transform after the chain, so this element's point is the base-side one"
        )
    }
}

fn least_squares(axes: &[Vector3<f64>], d: &Vector3<f64>) -> Vec<f64> {
    if axes.is_empty() {
        return Vec::new();
    }
    let a = DMatrix::from_fn(3, axes.len(), |r, c| axes[c][r]);
    let rhs = DVector::from_column_slice(d.as_slice());
    match a.svd(true, true).solve(&rhs, 1e-12) {
        Ok(x) => x.iter().copied().collect(),
        Err(_) => vec![0.0; axes.len()],
    }
}

/// Warnings about a joint's CAD frames: they should coincide where the joint type requires it.
pub fn check(model: &Model, joint: &Joint, chain: &Chain, location: &str) -> Vec<Warning> {
    let mut out = Vec::new();
    let kinds: Vec<PrimitiveKind> = joint.primitives.iter().map(|p| p.kind).collect();
    let has_prismatic = kinds.contains(&PrimitiveKind::Prismatic);
    let has_spherical = kinds.contains(&PrimitiveKind::Spherical);
    let gap = chain.residual.translation.vector.norm().max(chain.pre.translation.vector.norm());
    if gap > COINCIDE_TOL_M {
        let what = if has_prismatic { "off the prismatic axes" } else { "apart" };
        out.push(Warning::new(
            "joint-frames-apart",
            format!(
                "{} joint: base and follower frames are {:.6} mm {what}; the CAD offset is kept as a fixed translation",
                describe(&kinds),
                gap * 1e3
            ),
            location,
        ));
    }
    let angle = rotation_angle(&chain.residual.rotation);
    if !has_spherical && angle > COINCIDE_TOL_RAD {
        let base = model.frame(joint.base);
        let fol = model.frame(joint.follower);
        out.push(Warning::new(
            "joint-frames-misaligned",
            format!(
                "{} joint: follower frame {} is rotated {:.6} deg from base frame {} beyond what the joint's axes allow; the CAD orientation is kept as a fixed rotation",
                describe(&kinds),
                fol.name,
                angle.to_degrees(),
                base.name
            ),
            location,
        ));
    }
    out
}

fn describe(kinds: &[PrimitiveKind]) -> String {
    kinds.iter().map(|k| k.as_str()).collect::<Vec<_>>().join("+")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::ir::*;
    use nalgebra::{Rotation3, Vector3};

    fn frame(owner: FrameOwner, pose: Isometry3<f64>) -> Frame {
        Frame {
            name: "CS".into(),
            display_name: String::new(),
            node_id: String::new(),
            owner,
            ref_id: None,
            pose,
            loc: SourceLoc::default(),
        }
    }

    fn model_with(b: Isometry3<f64>, f: Isometry3<f64>, prims: &[(PrimitiveKind, [f64; 3])]) -> (Model, Joint) {
        let mut m = Model::default();
        m.frames.push(frame(FrameOwner::Body(BodyId(0)), b));
        m.frames.push(frame(FrameOwner::Body(BodyId(1)), f));
        let j = Joint {
            cad_name: "j".into(),
            node_id: "1:-:2".into(),
            subsystem_path: vec![],
            base: FrameId(0),
            follower: FrameId(1),
            primitives: prims
                .iter()
                .map(|(k, a)| Primitive { kind: *k, axis_world: Vector3::from(*a), losses: Default::default(), loc: SourceLoc::default() })
                .collect(),
            limits: None,
            loc: SourceLoc::default(),
        };
        (m, j)
    }

    fn fk(b: &Isometry3<f64>, c: &Chain) -> Isometry3<f64> {
        let mut cur = *b;
        for e in &c.elements {
            match e.kind {
                PrimitiveKind::Revolute => cur.rotation *= UnitQuaternion::from_axis_angle(&Unit::new_normalize(e.axis), e.q0),
                PrimitiveKind::Prismatic => cur.translation.vector += cur.rotation * (e.axis * e.q0),
                _ => {}
            }
        }
        cur * c.residual
    }

    #[test]
    fn revolute_offset_becomes_start_angle() {
        let rb = Rotation3::from_euler_angles(0.3, -0.2, 1.1);
        let b = Isometry3::from_parts(Translation3::new(0.1, 0.2, 0.3), rb.into());
        let axis_world = rb * Vector3::new(0.0, 0.0, 1.0);
        let f_rot = UnitQuaternion::from_rotation_matrix(&rb) * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.5);
        let f = Isometry3::from_parts(b.translation, f_rot);
        let (m, j) = model_with(b, f, &[(PrimitiveKind::Revolute, axis_world.into())]);
        let c = chain(&m, &j);
        assert_eq!(c.elements.len(), 1);
        assert!((c.elements[0].q0 - 0.5).abs() < 1e-12);
        assert!((c.elements[0].axis - Vector3::z()).norm() < 1e-12);
        assert!(is_identity(&c.residual), "{:?}", c.residual);
        assert!((fk(&b, &c).to_homogeneous() - f.to_homogeneous()).norm() < 1e-12);
    }

    #[test]
    fn six_dof_chain_reproduces_pose() {
        let b = Isometry3::translation(0.0, 0.0, 0.0);
        let f = Isometry3::from_parts(Translation3::new(0.01, -0.02, 0.03), UnitQuaternion::from_euler_angles(0.2, 0.1, -0.4));
        let (m, j) = model_with(
            b,
            f,
            &[
                (PrimitiveKind::Prismatic, [1.0, 0.0, 0.0]),
                (PrimitiveKind::Prismatic, [0.0, 1.0, 0.0]),
                (PrimitiveKind::Prismatic, [0.0, 0.0, 1.0]),
                (PrimitiveKind::Spherical, [0.0, 0.0, 0.0]),
            ],
        );
        let c = chain(&m, &j);
        let q: Vec<f64> = c.elements.iter().map(|e| e.q0).collect();
        assert!((q[0] - 0.01).abs() < 1e-15 && (q[1] + 0.02).abs() < 1e-15 && (q[2] - 0.03).abs() < 1e-15);
        assert!(c.residual.translation.vector.norm() < 1e-15);
        assert!((fk(&b, &c).to_homogeneous() - f.to_homogeneous()).norm() < 1e-12);
    }

    #[test]
    fn noisy_axis_is_snapped_without_moving_frames() {
        let b = Isometry3::identity();
        let f = Isometry3::from_parts(
            Translation3::identity(),
            UnitQuaternion::from_axis_angle(&Unit::new_normalize(Vector3::new(0.0, -1.61681e-10, -1.0)), 0.7),
        );
        let (m, j) = model_with(b, f, &[(PrimitiveKind::Revolute, [0.0, -1.61681e-10, -1.0])]);
        let c = chain(&m, &j);
        assert_eq!(c.elements[0].axis, Vector3::new(0.0, 0.0, -1.0));
        assert!((fk(&b, &c).to_homogeneous() - f.to_homogeneous()).norm() < 1e-12);
    }

    #[test]
    fn misplaced_revolute_frames_warn() {
        let b = Isometry3::identity();
        let f = Isometry3::translation(0.002, 0.0, 0.0);
        let (m, j) = model_with(b, f, &[(PrimitiveKind::Revolute, [0.0, 0.0, 1.0])]);
        let c = chain(&m, &j);
        let w = check(&m, &j, &c, "joint j");
        assert_eq!(w.len(), 1);
        assert_eq!(w[0].code, "joint-frames-apart");
        assert!(w[0].message.contains("2.000000 mm"), "{}", w[0].message);
        assert!((fk(&b, &c).to_homogeneous() - f.to_homogeneous()).norm() < 1e-12);
    }

    #[test]
    fn a_rounding_gap_moves_the_prismatic_line_not_the_hinge() {
        // Prismatic along a, then a revolute about n ⟂ a, through the follower frame F. Frames
        // written relative to others and rounded leave F 2e-7 m off the prismatic line (e) plus
        // 1e-7 m along it.
        let b = Isometry3::from_parts(Translation3::new(0.1, -0.2, 0.05), UnitQuaternion::from_euler_angles(0.3, -0.1, 0.7));
        let a = b.rotation * Vector3::x();
        let n = b.rotation * Vector3::z();
        let e = b.rotation * Vector3::new(0.0, 1.6e-7, 1.2e-7);
        let turn = UnitQuaternion::from_axis_angle(&Unit::new_normalize(n), 0.4);
        let f = Isometry3::from_parts(Translation3::from(b.translation.vector + a * (0.015 + 1e-7) + e), turn * b.rotation);
        let (m, j) = model_with(b, f, &[(PrimitiveKind::Prismatic, a.into()), (PrimitiveKind::Revolute, n.into())]);
        let c = chain(&m, &j);
        assert!((fk(&(b * c.pre), &c).to_homogeneous() - f.to_homogeneous()).norm() < 1e-12);
        // The prismatic takes the part along its axis; the hinge passes through F exactly.
        assert!((c.elements[0].q0 - (0.015 + 1e-7)).abs() < 1e-15, "{}", c.elements[0].q0);
        let hinge = &c.elements[1];
        let miss = (f.translation.vector - hinge.origin_world).cross(&hinge.axis_world).norm();
        assert!(miss < 1e-15, "the revolute axis misses the follower frame by {miss:e} m");
        assert!(hinge.correction.is_none(), "{:?}", hinge.correction);
        assert!(is_identity(&c.residual), "{:?}", c.residual);
        // The prismatic's line moved by the gap, and says so.
        let stated = c.elements[0].correction.as_ref().expect("the moved prismatic line is stated");
        assert!((stated.origin_m - 2e-7).abs() < 1e-15 && stated.axis_rad < 1e-15, "{stated:?}");
        assert!(stated.why.contains("prismatic") && stated.why.contains("follower frame"), "{}", stated.why);
        // No warning at the data's precision.
        assert!(check(&m, &j, &c, "j").is_empty());
    }

    #[test]
    fn twist_range() {
        let q = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 3.0);
        assert!((twist_angle(&q, &Vector3::z()) - 3.0).abs() < 1e-12);
        let q = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), -3.0);
        assert!((twist_angle(&q, &Vector3::z()) + 3.0).abs() < 1e-12);
        let q = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.25);
        assert!((twist_angle(&q, &-Vector3::z()) + 0.25).abs() < 1e-12);
    }
}
