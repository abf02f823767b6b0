//! URDF back end: the assembly as a URDF robot (`<Pkg>/<Pkg>.urdf` in the package).
//!
//! - **Links** carry the Modelica body names (from the package's [`Layout`]); each link frame is
//!   the body's CS1 frame. `<inertial>`: `<origin>` = the CG frame's pose in CS1, `<inertia>` =
//!   the IR's tensor about the CG in CG axes (symmetrised `(I + Iᵀ)/2`, which is the tensor
//!   itself when it is symmetric), mass. A `world` link is the CAD world frame: grounds are fixed
//!   in it, free bodies hang from it by `floating` joints at their CAD pose.
//! - **Joints** follow a spanning tree of the writer's own (`spanning_tree`: the hierarchy's
//!   joints, preferring those URDF writes without helper links, so that a model read from URDF
//!   keeps the source's tree and loop joints) and the passes' joint chains. URDF's
//!   zero configuration is the CAD pose: every element's start value `q0` is folded into the
//!   joint `<origin>`, so **URDF q = Modelica q − q0** (for a tree joint traversed from its
//!   follower side the URDF axis is negated, and the same relation holds). Limits
//!   (`Joint::limits`, in the source's coordinate = the Modelica q) are shifted by −q0 (a URDF
//!   whose loops the front end had to assemble starts off its own zero); a loop joint keeps them
//!   as they are (its frames are the IR's, so its zero is the source's). A revolute without
//!   position limits is
//!   `continuous`; a prismatic without them gets ±[`DEFAULT_TRAVEL`], and missing effort and
//!   velocity get [`DEFAULT_EFFORT`] and [`DEFAULT_VELOCITY`] (URDF requires both), each said in
//!   a comment.
//! - A joint of several movable elements (composite, spherical) becomes a serial chain of URDF
//!   joints through massless links `<joint>__<k>`; a spherical element is three revolutes about
//!   x, y and z of its frame through its centre (`<element>_x`, `_y`, `_z`). A
//!   prismatic+prismatic+revolute chain with orthonormal right-handed axes becomes one `planar`
//!   joint (axis = the revolute's). Where the child's CS1 frame is off a revolute's axis, the
//!   revolute ends in a massless link `<joint>__<k>` and a fixed joint `<joint>__offset` carries
//!   the offset (URDF rotates a child about its own origin).
//! - **Loops**: URDF has no loops. Each joint left out of the tree is written as Drake's
//!   `<loop_joint>` (link frames = the IR joint's base and follower frames in
//!   their links' CS1 frames, axis in the base frame) with a comment; omitted cuts and redundant
//!   welds only as comments.
//! - **Mimic**: `Model::couplings` between joints written as one URDF joint each become
//!   `<mimic joint multiplier offset>`, the offset moved to URDF's coordinates
//!   (`o + m·q0_leader − q0_follower`); others are listed in a comment.
//! - **Meshes** (when shapes are written): `package://<Pkg>/Resources/Shapes/<stem>.stl` (the
//!   package's STL, metres, CS1), so visual and collision origins are the identity; colour as
//!   `<material>` rgba.
//! - Numbers print as the shortest decimal that reads back to the same `f64`; `rpy` is URDF's
//!   fixed-axis X-Y-Z (R = Rz(yaw)·Ry(pitch)·Rx(roll)).

use std::collections::{BTreeMap, HashSet};
use std::fmt::Write as _;

use nalgebra::{Isometry3, Matrix3, Rotation3, UnitQuaternion, Vector3};

use crate::pipeline::back::modelica::Layout;
use crate::pipeline::ir::{FrameOwner, JointId, JointLimits, Model, PrimitiveKind};
use crate::pipeline::passes::hierarchy::LoopKind;
use crate::pipeline::passes::kinematics::{element_motion, is_identity, IDENTITY_TOL};
use crate::pipeline::passes::loops::Cut;
use crate::pipeline::valid::Validated;

/// Travel (m or rad) written either side of zero for a prismatic (or a one-sided revolute)
/// whose source states no position limit: URDF requires one.
pub const DEFAULT_TRAVEL: f64 = 1000.0;
/// Effort (N or N·m) written when the source states none and URDF needs a `<limit>`.
pub const DEFAULT_EFFORT: f64 = 1.0e6;
/// Speed (m/s or rad/s) written when the source states none and URDF needs a `<limit>`.
pub const DEFAULT_VELOCITY: f64 = 1000.0;

/// `(path, bytes)` of the package's URDF file: `<Pkg>/<Pkg>.urdf`.
pub fn file(model: &Model, v: &Validated, layout: &Layout, package: &str, write_shapes: bool) -> (String, Vec<u8>) {
    let text = write(model, v, layout, package, write_shapes);
    (format!("{package}/{package}.urdf"), text.into_bytes())
}

/// `(path, bytes)` of the same robot for tools without ROS packages (MuJoCo, PyBullet,
/// Drake without a package map): `<Pkg>/<Pkg>.mujoco.urdf`, whose mesh paths are relative to
/// the file (`Resources/Shapes/<stem>.stl`) instead of `package://<Pkg>/...`.
pub fn relative_file(ros: &(String, Vec<u8>), package: &str) -> (String, Vec<u8>) {
    let text = String::from_utf8_lossy(&ros.1).replace(&format!("filename=\"package://{}/", attr(package)), "filename=\"");
    (format!("{package}/{package}.mujoco.urdf"), text.into_bytes())
}

/// A number, shortest round-trip decimal; `-0` prints as `0`.
fn n(x: f64) -> String {
    crate::numtext::dbg(x)
}

fn v3(v: &Vector3<f64>) -> String {
    format!("{} {} {}", n(v.x), n(v.y), n(v.z))
}

fn attr(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// Text safe inside an XML comment.
fn comment(s: &str) -> String {
    let mut s = s.replace("--", "- -");
    if s.ends_with('-') {
        s.push(' ');
    }
    s
}

/// URDF's `rpy` of a rotation: fixed axes X, Y, Z, R = Rz(yaw)·Ry(pitch)·Rx(roll). Pitch from
/// `atan2` (well conditioned near ±90°), roll from what yaw and pitch leave, so that the angles
/// reproduce the rotation to rounding even at gimbal lock.
pub fn rpy(q: &UnitQuaternion<f64>) -> [f64; 3] {
    let m = q.to_rotation_matrix().into_inner();
    let yaw = m[(1, 0)].atan2(m[(0, 0)]);
    let pitch = (-m[(2, 0)]).atan2(m[(0, 0)].hypot(m[(1, 0)]));
    let rest = Rotation3::from_euler_angles(0.0, pitch, yaw).into_inner().transpose() * m;
    let roll = rest[(2, 1)].atan2(rest[(1, 1)]);
    [roll, pitch, yaw]
}

fn origin(pose: &Isometry3<f64>) -> String {
    let [r, p, y] = rpy(&pose.rotation);
    format!("<origin xyz=\"{}\" rpy=\"{} {} {}\"/>", v3(&pose.translation.vector), n(r), n(p), n(y))
}

/// Kind of one URDF joint.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Fixed,
    Revolute,
    Prismatic,
    Planar,
    Floating,
}

/// One URDF joint to be written.
struct UJoint {
    name: String,
    kind: Kind,
    parent: String,
    child: String,
    origin: Isometry3<f64>,
    axis: Vector3<f64>,
    /// The source's limits (single-element joints only).
    limits: Option<JointLimits>,
    /// `<dynamics damping friction>` (single-element joints only; zero: not written).
    losses: crate::pipeline::ir::Losses,
    mimic: Option<String>,
    note: Option<String>,
}

/// One movable step of a joint's chain, parent to child: motion about/along `axis` (in the
/// step's own frame) by `q0 + u`, URDF coordinate `u`.
#[derive(Clone, Debug)]
struct Step {
    kind: PrimitiveKind,
    axis: Vector3<f64>,
    q0: f64,
    name: String,
}

/// Unique names per URDF kind (links, joints): the Modelica names are unique already; helper
/// names get `_2`, `_3`, ... on a clash.
#[derive(Default)]
struct Unique(HashSet<String>);

impl Unique {
    fn take(&mut self, base: &str) -> String {
        let mut name = base.to_string();
        let mut k = 2;
        while self.0.contains(&name) {
            name = format!("{base}_{k}");
            k += 1;
        }
        self.0.insert(name.clone());
        name
    }
}

/// The revolute/prismatic steps of a chain (spherical elements as three revolutes about x, y,
/// z), parent to child, with their names.
fn steps(a_chain: &crate::pipeline::passes::kinematics::Chain, element_name: &dyn Fn(usize) -> String, forward: bool) -> Vec<Step> {
    let mut out = Vec::new();
    for (k, e) in a_chain.elements.iter().enumerate() {
        match e.kind {
            PrimitiveKind::Revolute | PrimitiveKind::Prismatic => {
                out.push(Step { kind: e.kind, axis: e.axis, q0: e.q0, name: element_name(k) })
            }
            PrimitiveKind::Spherical => {
                for (axis, s) in [(Vector3::x(), "x"), (Vector3::y(), "y"), (Vector3::z(), "z")] {
                    out.push(Step { kind: PrimitiveKind::Revolute, axis, q0: 0.0, name: format!("{}_{s}", element_name(k)) });
                }
            }
            PrimitiveKind::Weld => {}
        }
    }
    if !forward {
        // M(q)⁻¹ = motion about −axis by q: the same coordinate, reversed order.
        out.reverse();
        for s in &mut out {
            s.axis = -s.axis;
        }
    }
    out
}

/// Writes the URDF text.
pub fn write(model: &Model, v: &Validated, layout: &Layout, package: &str, write_shapes: bool) -> String {
    let a = &v.analysis;
    let h = &a.hierarchy;
    let names = layout.names_or_assign(model);
    let names = names.as_ref();
    let element_name = |j: usize, k: usize| layout.element_name(names, v, j, k);
    let nb = model.bodies.len();
    let mut links = Unique::default();
    let mut joint_names = Unique::default();
    links.take("world");
    for b in &names.bodies {
        links.take(b);
    }
    for j in &names.joints {
        joint_names.take(j);
    }
    // Helper links (massless) in the order they appear.
    let mut helper_links: Vec<String> = Vec::new();
    let mut ujoints: Vec<UJoint> = Vec::new();
    // Tree joints written as exactly one URDF joint with one coordinate: their URDF name (mimic).
    let mut single: BTreeMap<JointId, String> = BTreeMap::new();
    let mut reached = vec![false; nb];
    let cs1 = |b: usize| model.frame(model.bodies[b].cs1).pose;

    let tree = spanning_tree(model, v);
    for &(j, forward) in &tree.joints {
        let joint = model.joint(j);
        let ji = j.index();
        let (pf, cf) = if forward { (joint.base, joint.follower) } else { (joint.follower, joint.base) };
        let FrameOwner::Body(child) = model.frame(cf).owner else { continue };
        let child = child.index();
        reached[child] = true;
        let (parent_link, parent_pose) = match model.frame(pf).owner {
            FrameOwner::Body(b) => (names.bodies[b.index()].clone(), cs1(b.index())),
            FrameOwner::Ground(_) => ("world".to_string(), Isometry3::identity()),
        };
        let child_link = names.bodies[child].clone();
        let chain = &a.chains[ji];
        let jname = names.joints[ji].clone();
        let steps = steps(chain, &|k| element_name(ji, k), forward);
        let (b_pose, f_pose) = (model.frame(joint.base).pose, model.frame(joint.follower).pose);
        let (pre, post) = if forward {
            (parent_pose.inverse() * b_pose * chain.pre, chain.residual * f_pose.inverse() * cs1(child))
        } else {
            (parent_pose.inverse() * f_pose * chain.residual.inverse(), chain.pre.inverse() * b_pose.inverse() * cs1(child))
        };
        if steps.is_empty() {
            ujoints.push(UJoint {
                name: jname,
                kind: Kind::Fixed,
                parent: parent_link,
                child: child_link,
                origin: parent_pose.inverse() * cs1(child),
                axis: Vector3::x(),
                limits: None,
                losses: Default::default(),
                mimic: None,
                note: None,
            });
            continue;
        }
        // Planar: P(a1) P(a2) R(n), orthonormal, a1 × a2 = n, nothing after it.
        let e = &chain.elements;
        let planar = forward && is_planar(chain) && is_identity(&post);
        if planar {
            let mut o = pre;
            for s in &steps {
                o *= element_motion(s.kind, &s.axis, s.q0);
            }
            ujoints.push(UJoint {
                name: jname.clone(),
                kind: Kind::Planar,
                parent: parent_link,
                child: child_link,
                origin: o,
                axis: e[2].axis,
                limits: None,
                losses: Default::default(),
                mimic: None,
                note: {
                    // The start rotation is in the origin: the Modelica translations run along
                    // the plane axes turned back by it.
                    let back = element_motion(PrimitiveKind::Revolute, &e[2].axis, -e[2].q0).rotation;
                    Some(format!(
                        "planar (Modelica chain {}): translations along {} and {} of the joint frame, then rotation about the axis",
                        jname,
                        v3(&(back * e[0].axis)),
                        v3(&(back * e[1].axis))
                    ))
                },
            });
            continue;
        }
        let count = steps.len();
        let mut prev = parent_link;
        let mut o = pre;
        for (k, s) in steps.iter().enumerate() {
            o *= element_motion(s.kind, &s.axis, s.q0);
            let last = k + 1 == count;
            let mut axis = s.axis;
            // The fixed transform after the last step folds into it when URDF can express it:
            // always for a prismatic, for a revolute when the child's origin is on the axis.
            let folds = last && {
                let t = post.translation.vector;
                s.kind == PrimitiveKind::Prismatic || (t - s.axis * t.dot(&s.axis)).norm() <= IDENTITY_TOL
            };
            if folds {
                o *= post;
                axis = post.rotation.inverse() * s.axis;
            }
            let child = if last && folds {
                child_link.clone()
            } else {
                let l = links.take(&format!("{jname}__{}", k + 1));
                helper_links.push(l.clone());
                l
            };
            let name = if count == 1 { jname.clone() } else { joint_names.take(&s.name) };
            let kind = if s.kind == PrimitiveKind::Prismatic { Kind::Prismatic } else { Kind::Revolute };
            // The source's limits are in the Modelica coordinate q (zero where the joint's
            // frames coincide); URDF's is q − q0.
            let limits = if chain.elements.len() == 1 && count == 1 {
                joint.limits.clone().map(|l| JointLimits { lower: l.lower.map(|x| x - s.q0), upper: l.upper.map(|x| x - s.q0), ..l })
            } else {
                None
            };
            let note = (count > 1 && k == 0).then(|| {
                let mut s = format!("joint {jname}: {count} movable elements in series through massless links {jname}__k");
                if chain.elements.iter().any(|e| e.kind == PrimitiveKind::Spherical) {
                    s.push_str("; a spherical element is three revolutes about x, y, z of its frame through its centre");
                }
                if joint.limits.is_some() {
                    s.push_str("; the source's limits (one coordinate) are not written");
                }
                s
            });
            if count == 1 {
                single.insert(j, name.clone());
            }
            let losses = if chain.elements.len() == 1 && count == 1 {
                joint.primitives.iter().find(|p| p.kind != PrimitiveKind::Weld).map(|p| p.losses).unwrap_or_default()
            } else {
                Default::default()
            };
            ujoints.push(UJoint {
                name,
                kind,
                parent: prev.clone(),
                child: child.clone(),
                origin: o,
                axis,
                limits,
                losses,
                mimic: None,
                note,
            });
            o = Isometry3::identity();
            prev = child;
        }
        if prev != child_link {
            // The last revolute's child origin is off its axis: a fixed offset.
            ujoints.push(UJoint {
                name: joint_names.take(&format!("{jname}__offset")),
                kind: Kind::Fixed,
                parent: prev,
                child: child_link,
                origin: post,
                axis: Vector3::x(),
                limits: None,
                losses: Default::default(),
                mimic: None,
                note: Some(format!("CAD offset of joint {jname}: the body frame is off the revolute's axis")),
            });
        }
    }
    // Free bodies: floating joints from the world at the CAD pose.
    for &r in &h.free_roots {
        let b = r.index();
        if reached[b] {
            continue;
        }
        reached[b] = true;
        ujoints.push(UJoint {
            name: joint_names.take(&format!("{}_free", names.bodies[b])),
            kind: Kind::Floating,
            parent: "world".to_string(),
            child: names.bodies[b].clone(),
            origin: cs1(b),
            axis: Vector3::x(),
            limits: None,
            losses: Default::default(),
            mimic: None,
            note: None,
        });
    }
    // Mimic couplings between single URDF joints.
    let mut unexpressed = Vec::new();
    for c in &model.couplings {
        let (Some(f), Some(l)) = (single.get(&c.follower), single.get(&c.leader)) else {
            unexpressed.push(names.joints[c.follower.index()].clone());
            continue;
        };
        // q_f = m q_l + o with q = u + q0 on both sides: u_f = m u_l + (o + m q0_l − q0_f).
        let q0 = |j: JointId| a.chains[j.index()].elements.first().map_or(0.0, |e| e.q0);
        let offset = c.offset + c.multiplier * q0(c.leader) - q0(c.follower);
        let text = format!("<mimic joint=\"{}\" multiplier=\"{}\" offset=\"{}\"/>", attr(l), n(c.multiplier), n(offset));
        if let Some(u) = ujoints.iter_mut().find(|u| &u.name == f) {
            u.mimic = Some(text);
        }
    }

    let mut out = String::new();
    let _ = writeln!(out, "<?xml version=\"1.0\"?>");
    let _ = writeln!(
        out,
        "<!-- Generated by cad2mo from {}. Links and joints carry their Modelica names; each link frame is the body's CS1 frame. The zero configuration is the CAD pose: URDF q = Modelica q - start value (the start values are folded into the joint origins). SI units, radians. Joints of several elements run through massless links JOINT__k. Missing limits URDF requires: position +-{} (m or rad), effort {}, velocity {}. -->",
        comment(&model.source.file),
        n(DEFAULT_TRAVEL),
        n(DEFAULT_EFFORT),
        n(DEFAULT_VELOCITY)
    );
    let _ = writeln!(out, "<robot name=\"{}\">", attr(package));
    let _ = writeln!(out, "  <link name=\"world\"/>");
    for b in 0..nb {
        let body = &model.bodies[b];
        let _ = writeln!(out, "  <link name=\"{}\">", attr(&names.bodies[b]));
        let cg = cs1(b).inverse() * model.frame(body.cg).pose;
        let i: Matrix3<f64> = (body.inertia_cg + body.inertia_cg.transpose()) * 0.5;
        let _ = writeln!(out, "    <inertial>\n      {}\n      <mass value=\"{}\"/>", origin(&cg), n(body.mass));
        let _ = writeln!(
            out,
            "      <inertia ixx=\"{}\" ixy=\"{}\" ixz=\"{}\" iyy=\"{}\" iyz=\"{}\" izz=\"{}\"/>\n    </inertial>",
            n(i[(0, 0)]),
            n(i[(0, 1)]),
            n(i[(0, 2)]),
            n(i[(1, 1)]),
            n(i[(1, 2)]),
            n(i[(2, 2)])
        );
        let shape = layout.shapes.get(b).and_then(|s| s.as_ref()).filter(|_| write_shapes && body.mesh.is_some());
        if let Some(stem) = shape {
            let mesh = format!("<mesh filename=\"package://{}/Resources/Shapes/{}.stl\"/>", attr(package), attr(stem));
            let c = body.display_color();
            let alpha = body.material.as_ref().map_or(1.0, |m| (1.0 - m.transparency).clamp(0.0, 1.0));
            let _ = writeln!(
                out,
                "    <visual>\n      <origin xyz=\"0 0 0\" rpy=\"0 0 0\"/>\n      <geometry>{mesh}</geometry>\n      <material name=\"{}_color\"><color rgba=\"{} {} {} {}\"/></material>\n    </visual>",
                attr(&names.bodies[b]),
                n(c[0]),
                n(c[1]),
                n(c[2]),
                n(alpha)
            );
            let _ = writeln!(
                out,
                "    <collision>\n      <origin xyz=\"0 0 0\" rpy=\"0 0 0\"/>\n      <geometry>{mesh}</geometry>\n    </collision>"
            );
        }
        let _ = writeln!(out, "  </link>");
    }
    for l in &helper_links {
        let _ = writeln!(out, "  <link name=\"{}\"/>", attr(l));
    }
    for u in &ujoints {
        if let Some(note) = &u.note {
            let _ = writeln!(out, "  <!-- {} -->", comment(note));
        }
        let kind = match u.kind {
            Kind::Fixed => "fixed",
            Kind::Revolute if u.limits.as_ref().is_none_or(|l| l.lower.is_none() && l.upper.is_none()) => "continuous",
            Kind::Revolute => "revolute",
            Kind::Prismatic => "prismatic",
            Kind::Planar => "planar",
            Kind::Floating => "floating",
        };
        let _ = writeln!(out, "  <joint name=\"{}\" type=\"{kind}\">", attr(&u.name));
        let _ = writeln!(out, "    <parent link=\"{}\"/>\n    <child link=\"{}\"/>", attr(&u.parent), attr(&u.child));
        let _ = writeln!(out, "    {}", origin(&u.origin));
        if matches!(u.kind, Kind::Revolute | Kind::Prismatic | Kind::Planar) {
            let _ = writeln!(out, "    <axis xyz=\"{}\"/>", v3(&u.axis));
        }
        if let Some(limit) = limit_element(kind, u.limits.as_ref()) {
            let _ = writeln!(out, "    {limit}");
        }
        if !u.losses.is_zero() {
            let _ = writeln!(out, "    <dynamics damping=\"{}\" friction=\"{}\"/>", n(u.losses.damping), n(u.losses.friction));
        }
        if let Some(m) = &u.mimic {
            let _ = writeln!(out, "    {m}");
        }
        let _ = writeln!(out, "  </joint>");
    }
    // Loops: what the hierarchy drops (redundant welds, implied cuts) as comments; the joints
    // left out of our tree as Drake's <loop_joint>.
    for (i, l) in h.loops.iter().enumerate() {
        let jname = &names.joints[l.closing.index()];
        if l.kind == LoopKind::Rigid {
            let _ = writeln!(out, "  <!-- {} -->", comment(&format!("weld {jname} closes a rigid loop: redundant, not written")));
        } else if a.loops.loops.get(i).is_none_or(|info| info.cut == Cut::Omitted) {
            let _ = writeln!(
                out,
                "  <!-- {} -->",
                comment(&format!("joint {jname} closes a loop the rest of the mechanism already closes: not written"))
            );
        }
    }
    for &closing in &tree.cuts {
        let joint = model.joint(closing);
        let jname = &names.joints[closing.index()];
        let chain = &a.chains[closing.index()];
        let kind = match chain.elements.as_slice() {
            [] => "fixed",
            [e] if e.kind == PrimitiveKind::Revolute => {
                if joint.limits.as_ref().is_some_and(|l| l.lower.is_some() || l.upper.is_some()) {
                    "revolute"
                } else {
                    "continuous"
                }
            }
            [e] if e.kind == PrimitiveKind::Prismatic => "prismatic",
            _ => {
                let _ = writeln!(
                    out,
                    "  <!-- {} -->",
                    comment(&format!("joint {jname} closes a loop with a chain of several elements (or a spherical): not expressible as a loop_joint, not written"))
                );
                continue;
            }
        };
        let at_world = |f| matches!(model.frame(f).owner, FrameOwner::Ground(_));
        if at_world(joint.base) || at_world(joint.follower) {
            let _ = writeln!(
                out,
                "  <!-- {} -->",
                comment(&format!("joint {jname} closes a loop at the world (every joint of the loop is at a ground): a loop_joint cannot end on the world link, not written"))
            );
            continue;
        }
        let side = |f| match model.frame(f).owner {
            FrameOwner::Body(b) => (names.bodies[b.index()].clone(), cs1(b.index()).inverse() * model.frame(f).pose),
            FrameOwner::Ground(_) => ("world".to_string(), model.frame(f).pose),
        };
        let (l1, p1) = side(joint.base);
        let (l2, p2) = side(joint.follower);
        let _ = writeln!(
            out,
            "  <!-- {} -->",
            comment(&format!(
                "loop: joint {jname} closes a kinematic loop (URDF has no loops; Drake's loop_joint). link1 frame = its base frame, link2 frame = its follower frame, axis in the link1 frame; at the CAD pose the two frames differ by its start value"
            ))
        );
        let pose = |p: &Isometry3<f64>| {
            let [r, pi, y] = rpy(&p.rotation);
            format!("xyz=\"{}\" rpy=\"{} {} {}\"", v3(&p.translation.vector), n(r), n(pi), n(y))
        };
        let _ = writeln!(out, "  <loop_joint name=\"{}\" type=\"{kind}\">", attr(jname));
        if let [e] = chain.elements.as_slice() {
            let _ = writeln!(out, "    <axis xyz=\"{}\"/>", v3(&e.axis));
        }
        let _ = writeln!(out, "    <link1 link=\"{}\" {}/>\n    <link2 link=\"{}\" {}/>", attr(&l1), pose(&p1), attr(&l2), pose(&p2));
        if let Some(limit) = limit_element(kind, joint.limits.as_ref()) {
            let _ = writeln!(out, "    {limit}");
        }
        let _ = writeln!(out, "  </loop_joint>");
    }
    if !unexpressed.is_empty() {
        let _ = writeln!(
            out,
            "  <!-- {} -->",
            comment(&format!(
                "couplings not written as mimic (a side is not one URDF joint): {}",
                crate::pipeline::ir::bounded_list(&unexpressed, 20)
            ))
        );
    }
    let _ = writeln!(out, "</robot>");
    out
}

/// The writer's spanning tree: tree joints (with their direction: true when the follower side
/// is the child) in breadth-first order from the world, then from each free root; and the
/// joints left out, written as loop joints.
struct Tree {
    joints: Vec<(JointId, bool)>,
    cuts: Vec<JointId>,
}

/// Whether URDF expresses joint `j` traversed in direction `forward` as one joint whose child
/// frame is the child's CS1 (no helper links): a weld, a planar chain, or one revolute or
/// prismatic element after which the child's CS1 can follow (a prismatic always, a revolute when
/// CS1 is on its axis). A ground cannot be a child.
fn clean(model: &Model, v: &Validated, j: JointId, forward: bool) -> bool {
    let joint = model.joint(j);
    let chain = &v.analysis.chains[j.index()];
    let (b, f) = (model.frame(joint.base), model.frame(joint.follower));
    let child = if forward { f } else { b };
    let FrameOwner::Body(c) = child.owner else { return false };
    let cs1 = model.frame(model.body(c).cs1).pose;
    let post = if forward { chain.residual * f.pose.inverse() * cs1 } else { chain.pre.inverse() * b.pose.inverse() * cs1 };
    let steps = steps(chain, &|_| String::new(), forward);
    match steps.as_slice() {
        [] => true,
        [s] => {
            let t = post.translation.vector;
            s.kind == PrimitiveKind::Prismatic || (t - s.axis * t.dot(&s.axis)).norm() <= IDENTITY_TOL
        }
        _ => forward && is_planar(chain) && is_identity(&post),
    }
}

/// P(a1) P(a2) R(n) with orthonormal, right-handed axes (a1 × a2 = n).
fn is_planar(chain: &crate::pipeline::passes::kinematics::Chain) -> bool {
    let e = &chain.elements;
    e.len() == 3
        && e[0].kind == PrimitiveKind::Prismatic
        && e[1].kind == PrimitiveKind::Prismatic
        && e[2].kind == PrimitiveKind::Revolute
        && e[0].axis.dot(&e[1].axis).abs() <= IDENTITY_TOL
        && (e[0].axis.cross(&e[1].axis) - e[2].axis).norm() <= IDENTITY_TOL
}

/// A spanning tree over the joints the hierarchy keeps (its redundant welds and implied cuts
/// are left out), preferring (Kruskal) welds, then joints at a ground (a loop joint should not
/// end on the world), then joints URDF expresses without helper links ([`clean`]), then the
/// hierarchy's own order. For a model read from URDF this is the source's tree (its loop
/// joints end off their links' frames), so a URDF written back has the source's structure; for
/// CAD models it is the hierarchy's tree wherever that needs no more helper links.
fn spanning_tree(model: &Model, v: &Validated) -> Tree {
    let h = &v.analysis.hierarchy;
    let nb = model.bodies.len();
    let world = nb;
    let node = |f: crate::pipeline::ir::FrameId| match model.frame(f).owner {
        FrameOwner::Body(b) => b.index(),
        FrameOwner::Ground(_) => world,
    };
    let dropped = |j: JointId| {
        h.loops.iter().enumerate().any(|(i, l)| {
            l.closing == j && (l.kind == LoopKind::Rigid || v.analysis.loops.loops.get(i).is_none_or(|info| info.cut == Cut::Omitted))
        })
    };
    let rank: BTreeMap<JointId, usize> =
        h.tree.iter().chain(h.loops.iter().map(|l| &l.closing)).enumerate().map(|(i, &j)| (j, i)).collect();
    let at_ground = |j: JointId| {
        let joint = model.joint(j);
        node(joint.base) == world || node(joint.follower) == world
    };
    // Clean in the direction it would take: from the ground when it has one, else forward.
    let key = |j: JointId| {
        let joint = model.joint(j);
        let forward = node(joint.follower) != world;
        (!joint.is_weld(), !at_ground(j), !clean(model, v, j, forward), rank.get(&j).copied().unwrap_or(usize::MAX), j)
    };
    let mut order: Vec<JointId> = model.joint_ids().filter(|&j| !dropped(j)).collect();
    order.sort_by_cached_key(|&j| key(j));
    let mut dsu: Vec<usize> = (0..=nb).collect();
    fn find(d: &mut [usize], mut x: usize) -> usize {
        while d[x] != x {
            d[x] = d[d[x]];
            x = d[x];
        }
        x
    }
    let mut adjacency: Vec<Vec<JointId>> = vec![Vec::new(); nb + 1];
    let mut cuts = Vec::new();
    for j in order {
        let joint = model.joint(j);
        let (a, b) = (node(joint.base), node(joint.follower));
        let (ra, rb) = (find(&mut dsu, a), find(&mut dsu, b));
        if ra == rb {
            cuts.push(j);
        } else {
            dsu[ra.max(rb)] = ra.min(rb);
            adjacency[a].push(j);
            adjacency[b].push(j);
        }
    }
    let mut seen = vec![false; nb + 1];
    let mut joints = Vec::new();
    let roots = std::iter::once(world).chain(h.free_roots.iter().map(|b| b.index()));
    for root in roots {
        if seen[root] {
            continue;
        }
        seen[root] = true;
        let mut queue = std::collections::VecDeque::from([root]);
        while let Some(n) = queue.pop_front() {
            for &j in &adjacency[n] {
                let joint = model.joint(j);
                let (a, b) = (node(joint.base), node(joint.follower));
                let (other, forward) = if a == n { (b, true) } else { (a, false) };
                if !seen[other] {
                    seen[other] = true;
                    joints.push((j, forward));
                    queue.push_back(other);
                }
            }
        }
    }
    cuts.sort_by_key(|&j| rank.get(&j).copied().unwrap_or(usize::MAX));
    Tree { joints, cuts }
}

/// The `<limit>` element of a joint of URDF type `kind`, filling what URDF requires and the
/// source does not state with the documented defaults.
fn limit_element(kind: &str, l: Option<&JointLimits>) -> Option<String> {
    let l = l.cloned().unwrap_or_default();
    let effort = n(l.effort.unwrap_or(DEFAULT_EFFORT));
    let velocity = n(l.velocity.unwrap_or(DEFAULT_VELOCITY));
    match kind {
        "continuous" if l.effort.is_some() || l.velocity.is_some() => Some(format!("<limit effort=\"{effort}\" velocity=\"{velocity}\"/>")),
        "revolute" | "prismatic" => {
            let lower = n(l.lower.unwrap_or(-DEFAULT_TRAVEL));
            let upper = n(l.upper.unwrap_or(DEFAULT_TRAVEL));
            Some(format!("<limit lower=\"{lower}\" upper=\"{upper}\" effort=\"{effort}\" velocity=\"{velocity}\"/>"))
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests;
