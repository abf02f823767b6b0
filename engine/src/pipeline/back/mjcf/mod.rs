//! MuJoCo back end: the assembly as an MJCF model (`<Pkg>/<Pkg>.mjcf.xml` in the package).
//!
//! - Bodies and joints carry their Modelica names (from the package's [`Layout`]); each MuJoCo
//!   body frame is the CAD part's CS1 frame, placed at the CAD pose relative to its parent in the
//!   spanning tree (grounds are the world).
//! - Mass properties are those of `Mechanics.mo` (`ir::Model::mass_properties_cs1`): `pos` of the
//!   CG and `fullinertia` about it, in the body frame; `inertiafromgeom="false"`, so meshes only
//!   draw.
//! - Each `Revolute`/`Prismatic` element becomes a `hinge`/`slide` joint of the child body with
//!   its CAD-pose axis and origin and `ref` = the Modelica start value: MuJoCo's `qpos0` is the
//!   CAD pose and its `qpos` *equals* the Modelica coordinate (`phi`, `s`), sign and zero
//!   included. A joint of several elements is several MuJoCo joints in one body, in chain order
//!   (reversed, axes negated, for a tree joint traversed from its follower side). Spherical
//!   elements become `ball` joints (identity at the CAD pose); free bodies get a `freejoint`.
//! - Loops: each closing joint whose chain is revolute/spherical only becomes a `connect`
//!   equality at its base frame's origin; other cuts (prismatic elements) are not expressed and
//!   are listed in a comment. Omitted cuts (`Cut::Omitted`) add nothing.
//! - Meshes: `Resources/Shapes/<body>.stl` (the package's own STL, metres, CS1), visual only
//!   (`contype=0 conaffinity=0`).
//! - Degenerate mass properties (virtual links of URDFs: a mass below [`MASS_FLOOR`], principal
//!   moments below [`INERTIA_FLOOR`] or breaking `A + B >= C`), which MuJoCo refuses, switch on
//!   its compiler's `boundmass`/`boundinertia`/`balanceinertia` at these floors, far below any
//!   real part (a 1 mm aluminium cube is 2.7e-6 kg and 4.5e-13 kg·m²), and each body they
//!   touch says so in a comment; models without such bodies are written without them.
//! - Couplings (URDF `mimic`) between single-element joints become `<equality><joint>` with
//!   `polycoef`: `q_f - q_f0 = a0 + m (q_l - q_l0)`, `a0 = m q_l0 - q_f0` (zero for URDF), so
//!   `q_f = m q_l` in Modelica coordinates.
//! - Gravity from the options; angles in radians; numbers printed shortest round-trip.

use std::fmt::Write as _;

use nalgebra::{Isometry3, Point3, UnitQuaternion, Vector3};

use crate::pipeline::back::modelica::Layout;
use crate::pipeline::ir::{FrameOwner, Model, PrimitiveKind};
use crate::pipeline::passes::hierarchy::LoopKind;
use crate::pipeline::passes::loops::Cut;
use crate::pipeline::valid::Validated;

/// Options of the MJCF back end.
#[derive(Clone, Debug)]
pub struct Options {
    /// The model's name (the Modelica package name).
    pub model_name: String,
    /// Gravity in world coordinates, m/s².
    pub gravity: [f64; 3],
    /// Reference the package's STL shapes (`Layout::shapes`).
    pub meshes: bool,
}

/// Deepest indentation level of the body tree; deeper bodies are written at this one.
const MAX_INDENT: usize = 32;
const INDENT: &str = "                                                                ";
const _: () = assert!(INDENT.len() == 2 * MAX_INDENT);

/// A number as MJCF gets it: the shortest round-trip decimal, `-0` as `0`.
pub(crate) fn n(x: f64) -> String {
    crate::numtext::dbg(x)
}

pub(crate) fn v3(v: &Vector3<f64>) -> String {
    format!("{} {} {}", n(v.x), n(v.y), n(v.z))
}

pub(crate) fn quat(q: &UnitQuaternion<f64>) -> String {
    format!("{} {} {} {}", n(q.w), n(q.i), n(q.j), n(q.k))
}

/// Text safe inside an XML comment.
fn comment(s: &str) -> String {
    attr(s).replace("--", "- -")
}

/// Text safe inside an XML attribute.
pub(crate) fn attr(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// `(path, bytes)` of the package's MJCF file: `<Pkg>/<Pkg>.mjcf.xml`.
pub fn file(model: &Model, v: &Validated, layout: &Layout, package: &str, gravity: [f64; 3], meshes: bool) -> (String, Vec<u8>) {
    let text = write(model, v, layout, &Options { model_name: package.to_string(), gravity, meshes });
    (format!("{package}/{package}.mjcf.xml"), text.into_bytes())
}

/// One MuJoCo joint of a body.
struct MjJoint {
    name: String,
    kind: &'static str,
    pos: Vector3<f64>,
    axis: Vector3<f64>,
    reference: f64,
    /// `damping` and `frictionloss` (from the element's `ir::Losses`; MuJoCo's frictionloss is
    /// a soft dry-friction constraint, close to but not exactly a Coulomb sign law).
    losses: crate::pipeline::ir::Losses,
}

/// Smallest mass (kg) and principal moment (kg·m²) MuJoCo is given (its compiler's
/// `boundmass` and `boundinertia`, written only when some body is below them).
pub const MASS_FLOOR: f64 = 1e-9;
pub const INERTIA_FLOOR: f64 = 1e-14;

/// Why MuJoCo would refuse a body's mass properties as written, if it would.
fn degenerate(mass: f64, inertia: &nalgebra::Matrix3<f64>) -> Option<String> {
    let mut why = Vec::new();
    if mass < MASS_FLOOR {
        why.push(format!("mass {} kg below {MASS_FLOOR} kg", n(mass)));
    }
    let sym = (inertia + inertia.transpose()) * 0.5;
    let mut ev: Vec<f64> = sym.symmetric_eigenvalues().iter().copied().collect();
    ev.sort_by(f64::total_cmp);
    if ev[0] < INERTIA_FLOOR {
        why.push(format!("smallest principal moment {:.3e} kg·m² below {INERTIA_FLOOR} kg·m²", ev[0]));
    } else if ev[0] + ev[1] < ev[2] {
        why.push(format!("principal moments {:.3e}, {:.3e}, {:.3e} break A + B >= C", ev[0], ev[1], ev[2]));
    }
    (!why.is_empty()).then(|| why.join("; "))
}

/// Writes the MJCF model.
pub fn write(model: &Model, v: &Validated, layout: &Layout, opts: &Options) -> String {
    let a = &v.analysis;
    let h = &a.hierarchy;
    let names = layout.names_or_assign(model);
    let names = names.as_ref();
    let element_name = |j: usize, k: usize| layout.element_name(names, v, j, k);
    let nb = model.bodies.len();
    // Parent (None: world) and joints of every body reached by the tree.
    let mut parent: Vec<Option<Option<usize>>> = vec![None; nb];
    let mut joints: Vec<Vec<MjJoint>> = (0..nb).map(|_| Vec::new()).collect();
    let mut children: Vec<Vec<usize>> = vec![Vec::new(); nb + 1]; // index nb: the world
    for &j in &h.tree {
        let joint = model.joint(j);
        let forward = h.follower_is_child[j.index()];
        let (pf, cf) = if forward { (joint.base, joint.follower) } else { (joint.follower, joint.base) };
        let FrameOwner::Body(child) = model.frame(cf).owner else { continue };
        let p = match model.frame(pf).owner {
            FrameOwner::Body(b) => Some(b.index()),
            FrameOwner::Ground(_) => None,
        };
        parent[child.index()] = Some(p);
        children[p.unwrap_or(nb)].push(child.index());
        let c_inv = model.frame(model.body(child).cs1).pose.inverse();
        let mut cur = model.frame(joint.base).pose * a.chains[j.index()].pre;
        let mut list = Vec::new();
        for (k, e) in a.chains[j.index()].elements.iter().enumerate() {
            let origin = cur.translation.vector;
            let axis = cur.rotation * e.axis;
            let (kind, motion) = match e.kind {
                PrimitiveKind::Prismatic => ("slide", Isometry3::translation(e.axis.x * e.q0, e.axis.y * e.q0, e.axis.z * e.q0)),
                PrimitiveKind::Revolute => {
                    ("hinge", Isometry3::from_parts(nalgebra::Translation3::identity(), UnitQuaternion::from_scaled_axis(e.axis * e.q0)))
                }
                _ => ("ball", Isometry3::identity()),
            };
            cur *= motion;
            let sign = if forward { 1.0 } else { -1.0 };
            list.push(MjJoint {
                name: element_name(j.index(), k),
                kind,
                pos: (c_inv * Point3::from(origin)).coords,
                axis: c_inv.rotation * axis * sign,
                reference: e.q0,
                losses: joint.primitives.iter().filter(|p| p.kind != PrimitiveKind::Weld).nth(k).map(|p| p.losses).unwrap_or_default(),
            });
        }
        if !forward {
            list.reverse();
        }
        joints[child.index()] = list;
    }
    // Free bodies: children of the world with a free joint (their CAD pose at qpos0).
    for (i, p) in parent.iter_mut().enumerate() {
        if p.is_none() {
            *p = Some(None);
            children[nb].push(i);
        }
    }

    let mut out = String::new();
    let g = Vector3::from(opts.gravity);
    let _ = writeln!(out, "<mujoco model=\"{}\">", attr(&opts.model_name));
    let _ = writeln!(
        out,
        "  <!-- Generated by cad2mo from {}. Bodies and joints carry their Modelica names; qpos equals the Modelica joint coordinates (qpos0 = start values = CAD pose). SI units, radians. -->",
        attr(&model.source.file).replace("--", "- -")
    );
    // Only what MuJoCo refuses: a moving body (one with joints) lighter than the floor, or a
    // full inertia that is not positive definite or breaks the triangle inequality (a static
    // body's all-zero inertia is written as `diaginertia="0 0 0"`, which MuJoCo takes).
    let floored: Vec<Option<String>> = (0..nb)
        .map(|b| {
            let mp = model.mass_properties_cs1(crate::pipeline::ir::BodyId(b as u32));
            let moving = !joints[b].is_empty() || h.free_bodies.iter().any(|f| f.index() == b);
            if mp.inertia.amax() == 0.0 && !moving {
                return None;
            }
            let mass = if moving { mp.mass } else { f64::INFINITY };
            degenerate(mass, &mp.inertia)
        })
        .collect();
    let bounds = if floored.iter().any(Option::is_some) {
        format!(" boundmass=\"{}\" boundinertia=\"{}\" balanceinertia=\"true\"", n(MASS_FLOOR), n(INERTIA_FLOOR))
    } else {
        String::new()
    };
    let _ = writeln!(out, "  <compiler angle=\"radian\" inertiafromgeom=\"false\" meshdir=\"Resources/Shapes\"{bounds}/>");
    let _ = writeln!(out, "  <option gravity=\"{}\"/>", v3(&g));
    let shaped = |i: usize| opts.meshes && layout.shapes.get(i).is_some_and(|s| s.is_some()) && model.bodies[i].mesh.is_some();
    if (0..nb).any(shaped) {
        let _ = writeln!(out, "  <asset>");
        for i in (0..nb).filter(|&i| shaped(i)) {
            if let Some(Some(stem)) = layout.shapes.get(i) {
                let _ = writeln!(out, "    <mesh name=\"{}\" file=\"{}.stl\"/>", attr(stem), attr(stem));
            }
        }
        let _ = writeln!(out, "  </asset>");
    }
    let _ = writeln!(out, "  <worldbody>");
    // Depth-first emission with an explicit stack: (body, depth, closing?). Indentation stops
    // growing at MAX_INDENT levels: a chain of n bodies would otherwise write O(n²) spaces.
    let mut stack: Vec<(usize, usize, bool)> = children[nb].iter().rev().map(|&c| (c, 2, false)).collect();
    while let Some((b, depth, close)) = stack.pop() {
        let ind = &INDENT[..2 * depth.min(MAX_INDENT)];
        if close {
            let _ = writeln!(out, "{ind}</body>");
            continue;
        }
        let body = &model.bodies[b];
        let pose_c = model.frame(body.cs1).pose;
        let rel = match parent[b].flatten() {
            Some(p) => model.frame(model.bodies[p].cs1).pose.inverse() * pose_c,
            None => pose_c,
        };
        let _ = writeln!(
            out,
            "{ind}<body name=\"{}\" pos=\"{}\" quat=\"{}\">",
            attr(&names.bodies[b]),
            v3(&rel.translation.vector),
            quat(&rel.rotation)
        );
        let mp = model.mass_properties_cs1(crate::pipeline::ir::BodyId(b as u32));
        let i = &mp.inertia;
        let inertia = if i.amax() == 0.0 {
            "diaginertia=\"0 0 0\"".to_string()
        } else {
            format!("fullinertia=\"{} {} {} {} {} {}\"", n(i[(0, 0)]), n(i[(1, 1)]), n(i[(2, 2)]), n(i[(0, 1)]), n(i[(0, 2)]), n(i[(1, 2)]))
        };
        if let Some(why) = &floored[b] {
            let _ = writeln!(
                out,
                "{ind}  <!-- {}: raised by the compiler's boundmass/boundinertia/balanceinertia; Mechanics.mo keeps the source values -->",
                comment(why)
            );
        }
        let _ = writeln!(out, "{ind}  <inertial pos=\"{}\" mass=\"{}\" {inertia}/>", v3(&mp.r_cm), n(mp.mass));
        if h.free_bodies.iter().any(|f| f.index() == b) && h.free_roots.iter().any(|f| f.index() == b) {
            let _ = writeln!(out, "{ind}  <freejoint name=\"{}_free\"/>", attr(&names.bodies[b]));
        }
        for j in &joints[b] {
            let mut axis = if j.kind == "ball" { String::new() } else { format!(" axis=\"{}\" ref=\"{}\"", v3(&j.axis), n(j.reference)) };
            if j.losses.damping > 0.0 {
                let _ = write!(axis, " damping=\"{}\"", n(j.losses.damping));
            }
            if j.losses.friction > 0.0 {
                let _ = write!(axis, " frictionloss=\"{}\"", n(j.losses.friction));
            }
            let _ = writeln!(out, "{ind}  <joint name=\"{}\" type=\"{}\" pos=\"{}\"{axis}/>", attr(&j.name), j.kind, v3(&j.pos));
        }
        if shaped(b) {
            if let Some(Some(stem)) = layout.shapes.get(b) {
                let c = body.display_color();
                let _ = writeln!(
                    out,
                    "{ind}  <geom type=\"mesh\" mesh=\"{}\" contype=\"0\" conaffinity=\"0\" rgba=\"{} {} {} 1\"/>",
                    attr(stem),
                    n(c[0]),
                    n(c[1]),
                    n(c[2])
                );
            }
        }
        stack.push((b, depth, true));
        for &c in children[b].iter().rev() {
            stack.push((c, depth + 1, false));
        }
    }
    let _ = writeln!(out, "  </worldbody>");
    // Loop closures.
    let mut eq = String::new();
    let mut skipped = Vec::new();
    let mut skipped_couplings: Vec<String> = Vec::new();
    for (i, l) in h.loops.iter().enumerate() {
        if l.kind == LoopKind::Rigid || a.loops.loops.get(i).is_none_or(|info| info.cut == Cut::Omitted) {
            continue;
        }
        let joint = model.joint(l.closing);
        let side = |f| match model.frame(f).owner {
            FrameOwner::Body(b) => ("body", names.bodies[b.index()].clone(), model.frame(model.body(b).cs1).pose),
            FrameOwner::Ground(_) => ("world", "world".to_string(), Isometry3::identity()),
        };
        let rotational = a.chains[l.closing.index()].elements.iter().all(|e| e.kind != PrimitiveKind::Prismatic);
        if !rotational {
            skipped.push(names.joints[l.closing.index()].clone());
            continue;
        }
        let (_, b1, p1) = side(joint.base);
        let (_, b2, _) = side(joint.follower);
        let anchor = (p1.inverse() * Point3::from(model.frame(joint.base).pose.translation.vector)).coords;
        let _ = writeln!(
            eq,
            "    <connect name=\"{}\" body1=\"{}\" body2=\"{}\" anchor=\"{}\"/>",
            attr(&names.joints[l.closing.index()]),
            attr(&b1),
            attr(&b2),
            v3(&anchor)
        );
    }
    // Couplings (URDF mimic) between single-element joints.
    let single = |j: crate::pipeline::ir::JointId| match a.chains[j.index()].elements.as_slice() {
        [e] if matches!(e.kind, PrimitiveKind::Revolute | PrimitiveKind::Prismatic) && !h.loops.iter().any(|l| l.closing == j) => {
            Some(e.q0)
        }
        _ => None,
    };
    for c in &model.couplings {
        let (Some(qf0), Some(ql0)) = (single(c.follower), single(c.leader)) else {
            skipped_couplings.push(names.joints[c.follower.index()].clone());
            continue;
        };
        let a0 = c.multiplier * ql0 + c.offset - qf0;
        let _ = writeln!(
            eq,
            "    <joint name=\"{}_mimic\" joint1=\"{}\" joint2=\"{}\" polycoef=\"{} {} 0 0 0\"/>",
            attr(&names.joints[c.follower.index()]),
            attr(&element_name(c.follower.index(), 0)),
            attr(&element_name(c.leader.index(), 0)),
            n(a0),
            n(c.multiplier)
        );
    }
    if !eq.is_empty() {
        let _ = writeln!(out, "  <equality>\n{eq}  </equality>");
    }
    if !skipped_couplings.is_empty() {
        let _ = writeln!(
            out,
            "  <!-- Couplings whose sides are not single joints are not expressed: {} -->",
            comment(&skipped_couplings.join(", "))
        );
    }
    if !skipped.is_empty() {
        let _ = writeln!(out, "  <!-- Loop cuts with prismatic elements are not expressed: {} -->", attr(&skipped.join(", ")));
    }
    let _ = writeln!(out, "</mujoco>");
    out
}
