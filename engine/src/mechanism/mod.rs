//! The numerical core of motion and drive sizing: a compact multibody model of a validated
//! assembly, with forward kinematics, Jacobians, loop assembly, inverse kinematics and inverse
//! dynamics. No IO, no HTTP, no SQL, no panics on input (the pipeline's rules).
//!
//! # Conventions
//! - **Coordinates** are exactly the emitted Modelica model's joint coordinates: one per
//!   `Revolute`/`Prismatic` element of a spanning-tree joint (`phi` in rad, `s` in m), with the
//!   same axis, sign and zero. The value that reproduces the CAD pose is the element's start
//!   value `q0` ([`Coordinate::q0`]). A tree joint traversed from its follower side (the
//!   hierarchy's `follower_is_child == false`) has its transform inverted; its coordinates keep
//!   their Modelica meaning. [`Mechanism::coordinates`] are in the hierarchy's breadth-first
//!   order: a coordinate's parent comes before it.
//! - **Closing joints** of loops emitted plainly (a loop cut that is a `Revolute`/`Prismatic`
//!   chain in Modelica) have coordinates too, kept apart as [`Mechanism::cut_coordinates`]: they
//!   are determined by the loop closure, like the dependent tree coordinates.
//! - **Frames**: every pose is an [`Isometry3`] mapping frame coordinates to world coordinates
//!   (`p_world = pose * p_frame`), as in the IR. A body's frame is its CAD `CS1` (the Modelica
//!   body's `frame_a`); grounds are fixed in the world.
//! - **Twists** (Jacobian columns, velocities) are `[angular; linear]`, world coordinates, the
//!   linear part being the velocity of the origin of the frame in question.
//! - **Units**: SI and radians throughout (m, kg, kg·m², N, N·m, rad, s).
//! - **Mass properties** are those the Modelica back end emits (`ir::Model::mass_properties_cs1`).
//!
//! # Limitations (for now)
//! - Free bodies (no path to a ground) and spherical joint elements are refused with an error
//!   naming the body or joint.
//! - Inverse dynamics ([`Mechanism::inverse_dynamics`]) is that of the spanning tree: loop
//!   closures contribute no constraint forces there. Mechanisms with loops driven at their
//!   independent coordinates are handled by [`Mechanism::close`] and
//!   [`Mechanism::driven_torques`] (`driven.rs`), which project the tree's torques onto the
//!   driven joints.
//! - Inverse kinematics of mechanisms with loops or mimic couplings moves the driven
//!   coordinates only (the closure kept at every iterate); the dependent coordinates are not
//!   clamped to their limits there.
//! - Mimic couplings ([`CoordCoupling`]) are those the Modelica back end emits (one revolute or
//!   prismatic element on each side, tree joints); the follower is dependent and its torque is
//!   carried by its leader (virtual work). A cycle of couplings is refused.
//! - Joint losses ([`Mechanism::passive_torques`]) are on tree coordinates; a loop's closing
//!   joint emitted plainly carries none here.
//! - Forward dynamics ([`Mechanism::forward_dynamics`], `forward.rs`): articulated bodies on the
//!   tree; loops by coordinate partitioning ([`Mechanism::closed_forward_dynamics`]).

mod closure;
mod driven;
mod dynamics;
mod forward;
mod ik;
mod kinematics;
mod passive;
mod rates;
mod rng;

use std::collections::BTreeMap;

use nalgebra::{Isometry3, Matrix3, Vector3};

use crate::pipeline::back::modelica::{assign_with_hints, Hints, Layout};
use crate::pipeline::ir::{BodyId, FrameId, FrameOwner, JointId, Model, PrimitiveKind};
use crate::pipeline::passes::hierarchy::LoopKind;
use crate::pipeline::passes::loops::{ConstraintClass, Cut};
use crate::pipeline::valid::Validated;

pub use closure::Assembly;
pub use driven::ClosedState;
pub use dynamics::Workspace;
pub use forward::ForwardWorkspace;
pub use ik::{IkOptions, IkResult, IkTarget};
pub use kinematics::Kinematics;
pub use passive::{friction_sign, REST_SPEED};
pub use rng::XorShift;

/// Why a mechanism cannot be built or a computation failed.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum MechanismError {
    #[error("body \"{body}\" (nodeID \"{node_id}\") has no path to a ground (a free body): free bodies are not supported yet by the motion analysis")]
    FreeBody { body: String, node_id: String },
    #[error(
        "joint \"{joint}\" (nodeID \"{node_id}\") has a spherical element: spherical joints are not supported yet by the motion analysis"
    )]
    Spherical { joint: String, node_id: String },
    #[error("{what}: expected {expected} values, got {got}")]
    Length { what: &'static str, expected: usize, got: usize },
    #[error("the pose cannot be assembled: residual {residual:.3e} after {iterations} iterations")]
    NotAssembled { residual: f64, iterations: usize },
    #[error("no CAD frame with nodeID \"{0}\"")]
    UnknownFrame(String),
    #[error("mimic coupling of joint \"{joint}\": {why}")]
    Coupling { joint: String, why: String },
    #[error("inverse kinematics target not supported: {0}")]
    IkUnsupported(String),
    #[error("coordinate \"{coordinate}\" moves no mass (singular mass matrix): its acceleration is undetermined")]
    Singular { coordinate: String },
    #[error("internal inconsistency: {0}")]
    Internal(String),
}

/// Revolute (`phi`, rad) or prismatic (`s`, m).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CoordKind {
    Revolute,
    Prismatic,
}

/// One joint coordinate: a Modelica `Revolute.phi` or `Prismatic.s`.
#[derive(Clone, Debug, PartialEq)]
pub struct Coordinate {
    /// The Modelica component of the element (`J1`, or `J1_2` for the second element of a joint).
    pub name: String,
    pub joint: JointId,
    /// Index of the element in the joint's chain.
    pub element: usize,
    pub kind: CoordKind,
    /// The value at the CAD pose (the emitted start value).
    pub q0: f64,
    /// Independent: its start value is `fixed=true` in Modelica (always, outside loops; in a loop,
    /// the independent coordinates the loop pass chose). Dependent ones are solved by assembly.
    pub independent: bool,
    /// The limits the source states for the joint (URDF), when the joint has this one element.
    pub source_limits: Option<crate::pipeline::ir::JointLimits>,
    /// The element's passive losses (see [`Mechanism::passive_torques`]).
    pub losses: crate::pipeline::ir::Losses,
}

/// A mimic coupling as the mechanism honours it: tree coordinate `follower` =
/// `multiplier` × tree coordinate `leader` + `offset` (Modelica coordinates; the `IdealGear` /
/// `IdealGearR2T` the Modelica back end writes between the two drive flanges).
#[derive(Clone, Debug, PartialEq)]
pub struct CoordCoupling {
    pub follower: usize,
    pub leader: usize,
    pub multiplier: f64,
    pub offset: f64,
}

/// Where something sits: a fixed transform from a link frame (or the world) to it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Attachment {
    /// The link it moves with; `None` for the world.
    pub link: Option<usize>,
    /// Link frame (or world) -> the thing's frame.
    pub offset: Isometry3<f64>,
}

/// One degree of freedom: an element's frame_b, moving relative to its parent.
#[derive(Clone, Debug)]
pub(crate) struct Link {
    pub parent: Option<usize>,
    /// Parent link frame (or world) -> this element's frame_a.
    pub x_tree: Isometry3<f64>,
    /// Unit axis in frame_a (= in frame_b); negated for an element traversed backwards.
    pub axis: Vector3<f64>,
    pub prismatic: bool,
    /// Mass of the bodies rigidly attached to this link's frame, kg.
    pub mass: f64,
    /// First moment `m * c` in the link frame, kg·m.
    pub h: Vector3<f64>,
    /// Inertia about the link frame's origin, link axes, kg·m².
    pub inertia_o: Matrix3<f64>,
}

/// How a loop's closing joint constrains the tree (the equations the loop pass chose).
#[derive(Clone, Debug)]
pub(crate) enum ClosureForm {
    /// The closing joint's chain: `B * E1(c1)...En(cn) * residual = F` (6 equations), with the
    /// chain's coordinates in `cut_coordinates`.
    Plain { elements: Vec<(bool, Vector3<f64>, usize)>, residual: Isometry3<f64> },
    /// `RevolutePlanarLoopConstraint` with axis `n` in frame_a: the 2 in-plane components of
    /// frame_b's origin in frame_a vanish.
    Planar { n: Vector3<f64> },
    /// `Joints.Constraints.<class>` between frame_a and frame_b.
    Constraint { class: ConstraintClass, locked: [bool; 3], n: Vector3<f64>, n_b: Vector3<f64> },
}

/// One loop closure: its two frames and its equations.
#[derive(Clone, Debug)]
pub(crate) struct Closure {
    /// The closing joint.
    pub joint: JointId,
    /// The cut's frame_a (for `Plain`: the closing joint's base frame).
    pub a: Attachment,
    /// The cut's frame_b (for `Plain`: the closing joint's follower frame).
    pub b: Attachment,
    pub form: ClosureForm,
}

/// A compact multibody model of a validated assembly. See the module docs for conventions.
#[derive(Clone, Debug)]
pub struct Mechanism {
    coordinates: Vec<Coordinate>,
    cut_coordinates: Vec<Coordinate>,
    pub(crate) links: Vec<Link>,
    bodies: Vec<Attachment>,
    body_names: Vec<String>,
    frames: Vec<Attachment>,
    frame_ids: BTreeMap<String, FrameId>,
    pub(crate) closures: Vec<Closure>,
    /// Mimic couplings (their followers are dependent coordinates).
    pub(crate) couplings: Vec<CoordCoupling>,
}

/// A tree link's motion at coordinate `q` (see [`crate::pipeline::passes::kinematics::element_motion`]).
fn element_motion(prismatic: bool, axis: &Vector3<f64>, q: f64) -> Isometry3<f64> {
    let kind = if prismatic { PrimitiveKind::Prismatic } else { PrimitiveKind::Revolute };
    crate::pipeline::passes::kinematics::element_motion(kind, axis, q)
}

/// The mimic couplings the Modelica back end emits (leader and follower each one revolute or
/// prismatic element of a tree joint), as coordinate couplings; each follower becomes
/// dependent. A follower of two couplings, or a cycle of couplings, is refused.
fn couplings_of(model: &Model, v: &Validated, coords: &mut [Coordinate]) -> Result<Vec<CoordCoupling>, MechanismError> {
    let single = |j: JointId| -> Option<usize> {
        let chain = v.analysis.chains.get(j.index())?;
        if chain.elements.len() != 1 || !matches!(chain.elements[0].kind, PrimitiveKind::Revolute | PrimitiveKind::Prismatic) {
            return None;
        }
        coords.iter().position(|c| c.joint == j)
    };
    let mut out: Vec<CoordCoupling> = Vec::new();
    for c in &model.couplings {
        let (Some(f), Some(l)) = (single(c.follower), single(c.leader)) else { continue };
        if out.iter().any(|o| o.follower == f) {
            return Err(MechanismError::Coupling { joint: model.joint(c.follower).cad_name.clone(), why: "it follows two joints".into() });
        }
        out.push(CoordCoupling { follower: f, leader: l, multiplier: c.multiplier, offset: c.offset });
    }
    // Cycles: following the leaders from a follower must not come back to it.
    for start in &out {
        let mut cur = start.leader;
        for _ in 0..=out.len() {
            if cur == start.follower {
                return Err(MechanismError::Coupling {
                    joint: model.joint(coords[start.follower].joint).cad_name.clone(),
                    why: "the mimic couplings form a cycle (no joint of it is independent)".into(),
                });
            }
            match out.iter().find(|o| o.follower == cur) {
                Some(o) => cur = o.leader,
                None => break,
            }
        }
    }
    for o in &out {
        coords[o.follower].independent = false;
    }
    Ok(out)
}

/// The losses of element `k` of joint `j` (its `k`-th primitive that is not a weld: the
/// kinematics pass's chain elements).
fn element_losses(model: &Model, j: JointId, k: usize) -> crate::pipeline::ir::Losses {
    model.joint(j).primitives.iter().filter(|p| p.kind != PrimitiveKind::Weld).nth(k).map(|p| p.losses).unwrap_or_default()
}

impl Mechanism {
    /// Builds the mechanism of a validated model, with the Modelica names the back end assigns
    /// without hints (see [`Mechanism::use_layout_names`] for the names of an actual package).
    pub fn from_validated(model: &Model, v: &Validated) -> Result<Mechanism, MechanismError> {
        let a = &v.analysis;
        let h = &a.hierarchy;
        if let Some(b) = h.free_bodies.first() {
            let body = model.body(*b);
            return Err(MechanismError::FreeBody { body: body.cad_name.clone(), node_id: body.node_id.clone() });
        }
        let omitted = |j: JointId| {
            h.loops
                .iter()
                .position(|l| l.closing == j)
                .is_some_and(|i| h.loops[i].kind == LoopKind::Rigid || a.loops.loops.get(i).is_some_and(|info| info.cut == Cut::Omitted))
        };
        for (j, joint) in model.joints.iter().enumerate() {
            let spherical = joint.primitives.iter().any(|p| p.kind == PrimitiveKind::Spherical);
            if spherical && !omitted(JointId(j as u32)) {
                return Err(MechanismError::Spherical { joint: joint.cad_name.clone(), node_id: joint.node_id.clone() });
            }
        }
        let names = assign_with_hints(model, &Hints::default());
        let element_name = |j: JointId, k: usize| {
            let base = &names.joints[j.index()];
            if a.chains[j.index()].elements.len() == 1 {
                base.clone()
            } else {
                format!("{base}_{}", k + 1)
            }
        };
        let kind_of = |k: PrimitiveKind| if k == PrimitiveKind::Prismatic { CoordKind::Prismatic } else { CoordKind::Revolute };

        let mut links: Vec<Link> = Vec::new();
        let mut coordinates = Vec::new();
        let mut bodies: Vec<Option<Attachment>> = vec![None; model.bodies.len()];
        let rel_to_cs1 = |f: FrameId| -> Option<Isometry3<f64>> {
            match model.frame(f).owner {
                FrameOwner::Body(b) => Some(model.frame(model.body(b).cs1).pose.inverse() * model.frame(f).pose),
                FrameOwner::Ground(_) => None,
            }
        };
        let attachment_of = |bodies: &[Option<Attachment>], f: FrameId| -> Option<Attachment> {
            match model.frame(f).owner {
                FrameOwner::Ground(_) => Some(Attachment { link: None, offset: model.frame(f).pose }),
                FrameOwner::Body(b) => {
                    let at = bodies[b.index()]?;
                    Some(Attachment { link: at.link, offset: at.offset * rel_to_cs1(f)? })
                }
            }
        };
        for &j in &h.tree {
            let joint = model.joint(j);
            let forward = h.follower_is_child[j.index()];
            let (parent_frame, child_frame) = if forward { (joint.base, joint.follower) } else { (joint.follower, joint.base) };
            let parent = attachment_of(&bodies, parent_frame)
                .ok_or_else(|| MechanismError::Internal(format!("tree joint \"{}\" reached before its parent", joint.cad_name)))?;
            let FrameOwner::Body(child) = model.frame(child_frame).owner else {
                return Err(MechanismError::Internal(format!("tree joint \"{}\" has a ground as its child", joint.cad_name)));
            };
            let chain = &a.chains[j.index()];
            let (mut link, mut x) = (parent.link, parent.offset);
            let mut push = |k: usize,
                            e: &crate::pipeline::passes::kinematics::Element,
                            sign: f64,
                            link: &mut Option<usize>,
                            x: &mut Isometry3<f64>| {
                links.push(Link {
                    parent: *link,
                    x_tree: *x,
                    axis: e.axis * sign,
                    prismatic: e.kind == PrimitiveKind::Prismatic,
                    mass: 0.0,
                    h: Vector3::zeros(),
                    inertia_o: Matrix3::zeros(),
                });
                coordinates.push(Coordinate {
                    name: element_name(j, k),
                    joint: j,
                    element: k,
                    kind: kind_of(e.kind),
                    q0: e.q0,
                    independent: e.fixed,
                    source_limits: model.joint(j).limits.clone().filter(|_| chain.elements.len() == 1),
                    losses: element_losses(model, j, k),
                });
                *link = Some(links.len() - 1);
                *x = Isometry3::identity();
            };
            if forward {
                x *= chain.pre;
                for (k, e) in chain.elements.iter().enumerate() {
                    push(k, e, 1.0, &mut link, &mut x);
                }
                x *= chain.residual;
            } else {
                x *= chain.residual.inverse();
                for (k, e) in chain.elements.iter().enumerate().rev() {
                    push(k, e, -1.0, &mut link, &mut x);
                }
                x *= chain.pre.inverse();
            }
            let to_cs1 = rel_to_cs1(child_frame).map(|r| r.inverse()).unwrap_or_else(Isometry3::identity);
            bodies[child.index()] = Some(Attachment { link, offset: x * to_cs1 });
        }
        let mut body_att = Vec::with_capacity(bodies.len());
        for (i, b) in bodies.iter().enumerate() {
            let body = &model.bodies[i];
            body_att.push(b.ok_or_else(|| MechanismError::FreeBody { body: body.cad_name.clone(), node_id: body.node_id.clone() })?);
        }
        // Mass properties, gathered per link.
        for (i, at) in body_att.iter().enumerate() {
            let Some(l) = at.link else { continue };
            let mp = model.mass_properties_cs1(BodyId(i as u32));
            let c = at.offset * nalgebra::Point3::from(mp.r_cm);
            let r = at.offset.rotation.to_rotation_matrix().into_inner();
            let ic = r * mp.inertia * r.transpose();
            let c = c.coords;
            let link = &mut links[l];
            link.mass += mp.mass;
            link.h += c * mp.mass;
            link.inertia_o += ic + (Matrix3::identity() * c.dot(&c) - c * c.transpose()) * mp.mass;
        }
        let mut frames = Vec::with_capacity(model.frames.len());
        let mut frame_ids = BTreeMap::new();
        for (i, f) in model.frames.iter().enumerate() {
            let at = attachment_of(&bodies, FrameId(i as u32))
                .ok_or_else(|| MechanismError::Internal(format!("frame {} unplaced", f.node_id)))?;
            frames.push(at);
            frame_ids.insert(f.node_id.clone(), FrameId(i as u32));
        }

        // Loop closures.
        let mut closures = Vec::new();
        let mut cut_coordinates = Vec::new();
        for (i, l) in h.loops.iter().enumerate() {
            let Some(info) = a.loops.loops.get(i) else { continue };
            if l.kind == LoopKind::Rigid || info.cut == Cut::Omitted {
                continue;
            }
            let joint = model.joint(l.closing);
            let chain = &a.chains[l.closing.index()];
            let base = frames[joint.base.index()];
            let follower = frames[joint.follower.index()];
            let single = || {
                chain
                    .elements
                    .first()
                    .filter(|_| chain.elements.len() == 1)
                    .ok_or_else(|| MechanismError::Internal(format!("loop cut \"{}\" is not a single element", joint.cad_name)))
            };
            let closure = match &info.cut {
                Cut::Joint | Cut::Redundant => {
                    let mut elements = Vec::new();
                    for (k, e) in chain.elements.iter().enumerate() {
                        elements.push((e.kind == PrimitiveKind::Prismatic, e.axis, cut_coordinates.len()));
                        cut_coordinates.push(Coordinate {
                            name: element_name(l.closing, k),
                            joint: l.closing,
                            element: k,
                            kind: kind_of(e.kind),
                            q0: e.q0,
                            independent: false,
                            source_limits: None,
                            losses: element_losses(model, l.closing, k),
                        });
                    }
                    let a = Attachment { link: base.link, offset: base.offset * chain.pre };
                    Closure { joint: l.closing, a, b: follower, form: ClosureForm::Plain { elements, residual: chain.residual } }
                }
                Cut::PlanarLoopConstraint => {
                    let e = single()?;
                    let b = Attachment { link: follower.link, offset: follower.offset * chain.residual.inverse() };
                    Closure { joint: l.closing, a: base, b, form: ClosureForm::Planar { n: e.axis } }
                }
                Cut::Constraint(cc) => {
                    let e = single()?;
                    let axes = Isometry3::from_parts(nalgebra::Translation3::identity(), cc.axes);
                    let motion = e.motion(e.q0);
                    let offset = axes.inverse() * motion * chain.residual;
                    let a_at = Attachment { link: base.link, offset: base.offset * axes };
                    let b_at = Attachment { link: follower.link, offset: follower.offset * offset.inverse() };
                    Closure {
                        joint: l.closing,
                        a: a_at,
                        b: b_at,
                        form: ClosureForm::Constraint { class: cc.class, locked: cc.locked, n: cc.n, n_b: cc.n_b },
                    }
                }
                Cut::Omitted => continue,
            };
            closures.push(closure);
        }
        let couplings = couplings_of(model, v, &mut coordinates)?;
        Ok(Mechanism {
            coordinates,
            cut_coordinates,
            links,
            bodies: body_att,
            body_names: names.bodies.clone(),
            frames,
            frame_ids,
            closures,
            couplings,
        })
    }

    /// Takes the element and body names of an emitted package (its [`Layout`]), so that
    /// coordinates are named exactly as in `Mechanics.mo` and the report.
    pub fn use_layout_names(&mut self, layout: &Layout) {
        for c in self.coordinates.iter_mut().chain(self.cut_coordinates.iter_mut()) {
            if let Some(n) = layout.joint_elements.get(c.joint.index()).and_then(|v| v.get(c.element)) {
                c.name = n.clone();
            }
        }
        if let Some(names) = &layout.names {
            self.body_names = names.bodies.clone();
        }
    }

    /// The tree coordinates (see the module docs).
    pub fn coordinates(&self) -> &[Coordinate] {
        &self.coordinates
    }

    /// Coordinates of closing joints emitted plainly (determined by the loop closures).
    pub fn cut_coordinates(&self) -> &[Coordinate] {
        &self.cut_coordinates
    }

    /// Number of tree coordinates.
    pub fn dof(&self) -> usize {
        self.coordinates.len()
    }

    /// The tree coordinates at the CAD pose.
    pub fn q0(&self) -> Vec<f64> {
        self.coordinates.iter().map(|c| c.q0).collect()
    }

    /// The cut coordinates at the CAD pose.
    pub fn cut_q0(&self) -> Vec<f64> {
        self.cut_coordinates.iter().map(|c| c.q0).collect()
    }

    /// Whether the model has loop closures.
    pub fn has_loops(&self) -> bool {
        !self.closures.is_empty()
    }

    /// Whether some tree coordinates are dependent (loop closures or mimic couplings): then only
    /// the [`Mechanism::driven`] coordinates are set, the others follow ([`Mechanism::close`]).
    pub fn has_dependent(&self) -> bool {
        !self.closures.is_empty() || !self.couplings.is_empty()
    }

    /// The mimic couplings the mechanism honours (see [`CoordCoupling`]).
    pub fn couplings(&self) -> &[CoordCoupling] {
        &self.couplings
    }

    /// The coupling whose follower is tree coordinate `i`, if any.
    pub fn coupling_of(&self, i: usize) -> Option<&CoordCoupling> {
        self.couplings.iter().find(|c| c.follower == i)
    }

    /// Sets every mimic follower of positions `q` from its leader (`q_f = m q_l + offset`).
    pub fn apply_couplings(&self, q: &mut [f64]) {
        self.propagate_couplings(q, true);
    }

    /// Sets every coupled follower of `q` from its leader: `q_f = m q_l + offset` (with
    /// `offsets == false`: `m q_l`, for speeds and accelerations). Chains of couplings are
    /// followed (a follower that leads another is set first).
    pub(crate) fn propagate_couplings(&self, q: &mut [f64], offsets: bool) {
        for _ in 0..self.couplings.len() {
            let mut changed = false;
            for c in &self.couplings {
                let v = c.multiplier * q[c.leader] + if offsets { c.offset } else { 0.0 };
                if q[c.follower] != v {
                    q[c.follower] = v;
                    changed = true;
                }
            }
            if !changed {
                break;
            }
        }
    }

    /// The closing joints whose loop closures constrain the coordinates.
    pub fn closing_joints(&self) -> Vec<JointId> {
        self.closures.iter().map(|c| c.joint).collect()
    }

    /// The Modelica name of each body, indexed like `Model::bodies`.
    pub fn body_names(&self) -> &[String] {
        &self.body_names
    }

    /// Where a body's CS1 frame sits.
    pub fn body_attachment(&self, b: BodyId) -> Option<&Attachment> {
        self.bodies.get(b.index())
    }

    /// Where a CAD frame sits.
    pub fn frame_attachment(&self, f: FrameId) -> Option<&Attachment> {
        self.frames.get(f.index())
    }

    /// The frame with CAD node ID `node_id`.
    pub fn frame_by_node_id(&self, node_id: &str) -> Result<FrameId, MechanismError> {
        self.frame_ids.get(node_id).copied().ok_or_else(|| MechanismError::UnknownFrame(node_id.to_string()))
    }

    /// The parent link of each link (`None`: the world), in order.
    pub fn link_parents(&self) -> Vec<Option<usize>> {
        self.links.iter().map(|l| l.parent).collect()
    }

    pub(crate) fn check_len(&self, what: &'static str, v: &[f64]) -> Result<(), MechanismError> {
        if v.len() == self.links.len() {
            Ok(())
        } else {
            Err(MechanismError::Length { what, expected: self.links.len(), got: v.len() })
        }
    }
}

#[cfg(test)]
mod tests;

#[cfg(test)]
mod loads_tests;
