//! Writes the package's `.mo` files.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use nalgebra::{Isometry3, Matrix3, Translation3, Vector3};

use super::diagram::plan::{half_for, Plan};
use super::diagram::{Class, Sheet, Style, Want};
use super::names::{self, sanitize, Names, Scope};
use crate::pipeline::ir::{FrameId, FrameOwner, JointId, Model, PrimitiveKind};
use crate::pipeline::passes::kinematics::is_identity;
use crate::pipeline::passes::loops::{ConstraintClass, Cut};
use crate::pipeline::valid::{is_root_part, Validated};

const MB: &str = "Modelica.Mechanics.MultiBody";

/// Options of the Modelica back end.
#[derive(Clone, Debug)]
pub struct Options {
    /// A valid Modelica identifier (the caller sanitises user input with [`sanitize`]).
    pub package_name: String,
    /// Gravity vector in world coordinates, m/s².
    pub gravity: [f64; 3],
    pub converter_version: String,
    /// Names of an earlier version, kept for unchanged node IDs.
    pub name_hints: super::names::Hints,
}

/// Where each IR entity ended up in the Modelica model: what the report and tests need.
#[derive(Clone, Debug, Default)]
pub struct Layout {
    pub names: Option<Names>,
    /// Per frame: the connector that carries it (`LINK.frame_a`, `LINK_CS3.frame_b`,
    /// `world.frame_b`), for frames that appear in the model.
    pub connectors: BTreeMap<FrameId, String>,
    /// Per body: the shape component and file stem, when the body has a mesh.
    pub shapes: Vec<Option<String>>,
    /// Per joint: the Modelica components of its chain, in order (empty when it is a plain
    /// connect or omitted).
    pub joint_elements: Vec<Vec<String>>,
    /// Per joint: how it was emitted.
    pub emitted_as: Vec<&'static str>,
    /// Per coupling of the model (same order): the component(s) that couple the two drive
    /// flanges, or why none could.
    pub couplings: Vec<Result<String, String>>,
    /// The Mechanics diagram: every component's placement and every connect's route
    /// (`Mechatronics` places its own components around them).
    pub diagram: Sheet,
    /// Each group's (column, row) in the diagram by node ID (`world` for the world), kept by
    /// the next version of the model.
    pub diagram_groups: BTreeMap<String, (i32, i32)>,
}

impl Layout {
    /// The body and joint names, or (for a layout without them) those the naming rules give.
    pub fn names_or_assign(&self, model: &Model) -> std::borrow::Cow<'_, Names> {
        match &self.names {
            Some(n) => std::borrow::Cow::Borrowed(n),
            None => std::borrow::Cow::Owned(names::assign_with_hints(model, &names::Hints::default())),
        }
    }

    /// The Modelica component of element `k` of joint `j` (`J`, or `J_2` for the second element
    /// of a chain when the layout does not say).
    pub fn element_name(&self, names: &Names, v: &Validated, j: usize, k: usize) -> String {
        self.joint_elements.get(j).and_then(|e| e.get(k)).cloned().unwrap_or_else(|| {
            if v.analysis.chains[j].elements.len() == 1 {
                names.joints[j].clone()
            } else {
                format!("{}_{}", names.joints[j], k + 1)
            }
        })
    }
}

/// The package's text files, paths relative to the zip root (`<Pkg>/...`).
#[derive(Clone, Debug)]
pub struct Package {
    pub files: Vec<(String, Vec<u8>)>,
    pub layout: Layout,
}

/// A number as the data supports it: rounded to 15 significant digits (what survives unit
/// conversions and rotations of 17-digit doubles), then the shortest decimal that reads back to
/// that; `-0` prints as `0`.
fn num(x: f64) -> String {
    num_in(x, 0.0)
}

/// [`num`], with values below 1e-12 of `scale` (the size of the quantity they belong to) written
/// as 0: rounding noise such as `8.6e-24` in an inertia of 1e-3.
fn num_in(x: f64, scale: f64) -> String {
    if x == 0.0 || x.abs() < 1e-12 * scale {
        return "0.0".to_string();
    }
    // Most CAD numbers are short already: rounding to 15 digits would give the same value.
    let shortest = crate::numtext::dbg(x);
    if crate::numtext::digits_in(&shortest) <= 15 {
        return shortest;
    }
    let rounded: f64 = format!("{x:.14e}").parse().unwrap_or(x);
    let x = if rounded == 0.0 || rounded.abs() < 1e-12 * scale { 0.0 } else { rounded };
    crate::numtext::dbg(x)
}

/// A vector, components below 1e-12 of its length written as 0.
fn vec3(v: &Vector3<f64>) -> String {
    let scale = v.norm();
    format!("{{{}, {}, {}}}", num_in(v.x, scale), num_in(v.y, scale), num_in(v.z, scale))
}

/// Cardan angles {a, b, c} with R = Rx(a) * Ry(b) * Rz(c) (MSL `sequence_start={1,2,3}`:
/// rotations about the moving frame's x, then y, then z axis).
fn cardan_xyz(r: &Matrix3<f64>) -> Vector3<f64> {
    let b = r[(0, 2)].clamp(-1.0, 1.0).asin();
    if r[(0, 2)].abs() < 1.0 - 1e-12 {
        Vector3::new((-r[(1, 2)]).atan2(r[(2, 2)]), b, (-r[(0, 1)]).atan2(r[(0, 0)]))
    } else {
        // Gimbal lock: only a + c (or a - c) is defined; put it all in a.
        Vector3::new(r[(1, 0)].atan2(r[(1, 1)]), b, 0.0)
    }
}

/// Escapes text for a Modelica string literal.
pub(super) fn mstr(s: &str) -> String {
    escaped(s, &|c| match c {
        '\\' => Some("\\\\"),
        '"' => Some("\\\""),
        _ => None,
    })
}

/// HTML-escapes text (not yet escaped for a Modelica string: see [`mstr`]).
pub(super) fn html(s: &str) -> String {
    escaped(s, &|c| match c {
        '&' => Some("&amp;"),
        '<' => Some("&lt;"),
        '>' => Some("&gt;"),
        '"' => Some("&quot;"),
        _ => None,
    })
}

/// `s` with each character `escape` maps replaced, in one pass (a `replace` per character was a
/// string each, for every name of a large model).
fn escaped(s: &str, escape: &dyn Fn(char) -> Option<&'static str>) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match escape(c) {
            Some(e) => out.push_str(e),
            None => out.push(c),
        }
    }
    out
}

struct Writer<'a> {
    model: &'a Model,
    v: &'a Validated,
    pkg: &'a str,
    scope: Scope,
    decl: String,
    layout: Layout,
    plan: Plan,
    sheet: Sheet,
    /// The connects, in order, routed once every component stands.
    wires: Vec<(String, String, Style)>,
    /// How the connects being made are drawn.
    style: Style,
    /// Followers of couplings that can be emitted: their start values are not fixed (the
    /// coupling fixes them).
    coupled: Vec<bool>,
}

impl Writer<'_> {
    /// Places component `name` where the plan wants it (or the nearest free spot) and returns
    /// its `Placement` annotation.
    fn put(&mut self, name: &str, class: Class, want: Want) -> String {
        self.sheet.add(name, class, want).annotation()
    }

    fn connect(&mut self, a: &str, b: &str) {
        self.wires.push((a.to_string(), b.to_string(), self.style));
    }

    /// Declares a fixed transform `name` for `iso` (frame_b in frame_a coordinates).
    fn fixed(&mut self, name: &str, iso: &Isometry3<f64>, comment: &str, want: Want) {
        let r = iso.translation.vector;
        let rot = iso.rotation.to_rotation_matrix();
        let place = self.put(name, Class::TwoPort, Want { half: half_for(name), ..want });
        if crate::pipeline::passes::kinematics::rotation_angle(&iso.rotation) <= crate::pipeline::passes::kinematics::IDENTITY_TOL {
            let _ = writeln!(
                self.decl,
                "  {MB}.Parts.FixedTranslation {name}(r={}, animation=false)\n    \"{}\" {place};",
                vec3(&r),
                mstr(comment)
            );
        } else {
            let m = rot.matrix();
            let nx = m.column(0).into_owned();
            let ny = m.column(1).into_owned();
            let _ = writeln!(
                self.decl,
                "  {MB}.Parts.FixedRotation {name}(\n    r={},\n    rotationType={MB}.Types.RotationTypes.TwoAxesVectors,\n    n_x={},\n    n_y={},\n    animation=false)\n    \"{}\" {place};",
                vec3(&r),
                vec3(&nx),
                vec3(&ny),
                mstr(comment)
            );
        }
    }

    /// The connector of a frame, declaring the fixed transform that carries it on first use.
    fn frame_connector(&mut self, f: FrameId, body_names: &[String]) -> String {
        if let Some(c) = self.layout.connectors.get(&f) {
            return c.clone();
        }
        let frame = self.model.frame(f);
        let c = match frame.owner {
            FrameOwner::Body(b) => {
                let body = self.model.body(b);
                let bname = &body_names[b.index()];
                let cs1 = self.model.frame(body.cs1).pose;
                let rel = cs1.inverse() * frame.pose;
                if f == body.cs1 || is_identity(&rel) {
                    format!("{bname}.frame_a")
                } else {
                    let label = if frame.display_name.is_empty() { &frame.name } else { &frame.display_name };
                    let name = self.scope.take(&format!("{bname}_{}", sanitize(label, "f")));
                    let want = self.plan.frame(self.model, f, half_for(&name));
                    self.fixed(&name, &rel, &format!("Frame {} of {} (nodeID {})", frame.name, body.cad_name, frame.node_id), want);
                    self.connect(&format!("{bname}.frame_a"), &format!("{name}.frame_a"));
                    format!("{name}.frame_b")
                }
            }
            FrameOwner::Ground(g) => {
                let ground = self.model.ground(g);
                if is_identity(&frame.pose) {
                    "world.frame_b".to_string()
                } else {
                    let name = self.scope.take(&sanitize(&ground.name, "g"));
                    let want = self.plan.frame(self.model, f, half_for(&name));
                    self.fixed(&name, &frame.pose, &format!("Ground {} (nodeID {}) in the world frame", ground.name, ground.node_id), want);
                    self.connect("world.frame_b", &format!("{name}.frame_a"));
                    format!("{name}.frame_b")
                }
            }
        };
        self.layout.connectors.insert(f, c.clone());
        c
    }
}

impl Writer<'_> {
    /// Emits one joint: its chain of elements (the last one as the loop's cut when it closes a
    /// loop), then the CAD offset to the follower frame.
    fn joint(&mut self, jid: JointId, jname: &str) {
        let model = self.model;
        let analysis = &self.v.analysis;
        let joint = model.joint(jid);
        let chain = &analysis.chains[jid.index()];
        let cut = analysis.hierarchy.loops.iter().position(|l| l.closing == jid).map(|i| &analysis.loops.loops[i].cut);
        let in_loop = analysis.hierarchy.in_loop[jid.index()];
        let base = self.layout.connectors[&joint.base].clone();
        let follower = self.layout.connectors[&joint.follower].clone();
        let what = format!("{} (nodeID {})", joint.cad_name, joint.node_id);
        self.style = if cut.is_some() { Style::Loop } else { Style::Frame };
        // The chain's components in order (axes, elements, offset), for their places.
        let mut slot = 0usize;
        let mut at = |w: &Self, name: &str| {
            slot += 1;
            w.plan.element(jid, slot - 1, half_for(name))
        };
        if cut == Some(&Cut::Omitted) {
            let (why, kind) = if joint.is_weld() {
                ("redundant weld closing a rigid loop", "omitted-redundant-weld")
            } else {
                ("closes a loop whose equations the rest of the mechanism already implies", "omitted-implied")
            };
            let _ = writeln!(self.decl, "  // {}: {why}, not emitted", mstr(&what));
            self.layout.emitted_as[jid.index()] = kind;
            return;
        }
        if chain.elements.is_empty() {
            if is_identity(&chain.residual) {
                self.connect(&base, &follower);
                self.layout.emitted_as[jid.index()] = "connect";
            } else {
                let want = at(self, jname);
                self.fixed(jname, &chain.residual, &format!("Rigid joint {what}"), want);
                self.connect(&base, &format!("{jname}.frame_a"));
                self.connect(&format!("{jname}.frame_b"), &follower);
                self.layout.joint_elements[jid.index()].push(jname.to_string());
                self.layout.emitted_as[jid.index()] = "fixed";
            }
            return;
        }
        let count = chain.elements.len();
        let mut prev = base;
        // Helper components after the elements in `joint_elements` (whose first entries match
        // the chain's elements one to one).
        let mut extra = Vec::new();
        if !is_identity(&chain.pre) {
            let name = self.scope.take(&format!("{jname}_gap"));
            let want = at(self, &name);
            self.fixed(
                &name,
                &chain.pre,
                &format!("Gap between the frames of joint {what} that its prismatic axes cannot take (see report.json corrections)"),
                want,
            );
            self.connect(&prev, &format!("{name}.frame_a"));
            prev = format!("{name}.frame_b");
            extra.push(name);
        }
        // Fixed transform from the last element's frame_b to the follower frame.
        let mut offset = chain.residual;
        for (k, e) in chain.elements.iter().enumerate() {
            let name = if count == 1 { jname.to_string() } else { self.scope.take(&format!("{jname}_{}", k + 1)) };
            let fixed = if e.fixed && !self.coupled[jid.index()] { ", fixed=true" } else { "" };
            let desc = if count == 1 { format!("Joint {what}") } else { format!("Joint {what}, primitive {} of {count}", k + 1) };
            let last_cut = if k + 1 == count { cut } else { None };
            let kind = match (e.kind, last_cut) {
                (PrimitiveKind::Revolute, Some(Cut::PlanarLoopConstraint)) => {
                    let want = at(self, &name);
                    let place = self.put(&name, Class::TwoPort, want);
                    let _ = writeln!(
                        self.decl,
                        "  {MB}.Joints.RevolutePlanarLoopConstraint {name}(n={}, animation=false)\n    \"{}: closes a planar loop\" {place};",
                        vec3(&e.axis),
                        mstr(&desc)
                    );
                    "revolute-planar-loop-constraint"
                }
                (_, Some(Cut::Constraint(cc))) => {
                    let axes = Isometry3::from_parts(Translation3::identity(), cc.axes);
                    if !is_identity(&axes) {
                        let axes_name = self.scope.take(&format!("{name}_axes"));
                        let want = at(self, &axes_name);
                        self.fixed(&axes_name, &axes, &format!("Axes of the loop cut {name}"), want);
                        self.connect(&prev, &format!("{axes_name}.frame_a"));
                        prev = format!("{axes_name}.frame_b");
                        extra.push(axes_name);
                    }
                    let mut params = Vec::new();
                    match cc.class {
                        ConstraintClass::Revolute => params.push(format!("n={}", vec3(&cc.n))),
                        ConstraintClass::Universal => {
                            params.push(format!("n_a={}", vec3(&cc.n)));
                            params.push(format!("n_b={}", vec3(&cc.n_b)));
                        }
                        ConstraintClass::Spherical | ConstraintClass::Prismatic => {}
                    }
                    for (axis, locked) in ["x", "y", "z"].iter().zip(cc.locked) {
                        params.push(format!("{axis}_locked={locked}"));
                    }
                    params.push("animation=false".to_string());
                    let want = at(self, &name);
                    let place = self.put(&name, Class::TwoPort, want);
                    let _ = writeln!(
                        self.decl,
                        "  {MB}.Joints.Constraints.{} {name}({})\n    \"{}: closes a loop, imposing only its independent equations\" {place};",
                        cc.class.name(),
                        params.join(", "),
                        mstr(&desc)
                    );
                    // The constraint's frame_b starts where its frame_a is: the element's own
                    // start motion moves into the offset.
                    offset = axes.inverse() * e.motion(e.q0) * chain.residual;
                    match cc.class {
                        ConstraintClass::Spherical => "constraint-spherical",
                        ConstraintClass::Revolute => "constraint-revolute",
                        ConstraintClass::Prismatic => "constraint-prismatic",
                        ConstraintClass::Universal => "constraint-universal",
                    }
                }
                (PrimitiveKind::Revolute | PrimitiveKind::Prismatic, _) => {
                    // (class, coordinate, its speed)
                    let (class, q, qd, kind) = if e.kind == PrimitiveKind::Revolute {
                        ("Revolute", "phi", "w", "revolute")
                    } else {
                        ("Prismatic", "s", "v", "prismatic")
                    };
                    let want = at(self, &name);
                    let place = self.put(&name, Class::Joint, want);
                    let _ = writeln!(
                        self.decl,
                        "  {}.Components.{class} {name}(\n    n={},\n    {q}(start={}{fixed}),\n    {qd}(start=0{fixed}))\n    \"{}\" {place};",
                        self.pkg,
                        vec3(&e.axis),
                        num_in(e.q0, 1.0),
                        mstr(&desc)
                    );
                    kind
                }
                _ => {
                    let states = if in_loop || !e.fixed {
                        String::new()
                    } else {
                        "(\n    enforceStates=true,\n    useQuaternions=true,\n    angles_fixed=true,\n    w_rel_a_fixed=true)".to_string()
                    };
                    let want = at(self, &name);
                    let place = self.put(&name, Class::TwoPort, want);
                    let _ = writeln!(self.decl, "  {MB}.Joints.Spherical {name}{states}\n    \"{}\" {place};", mstr(&desc));
                    "spherical"
                }
            };
            self.connect(&prev, &format!("{name}.frame_a"));
            prev = format!("{name}.frame_b");
            let losses = joint.primitives.iter().filter(|p| p.kind != PrimitiveKind::Weld).nth(k).map(|p| p.losses).unwrap_or_default();
            if matches!(kind, "revolute" | "prismatic") && !losses.is_zero() {
                let style = self.style;
                self.losses(jid, k, &name, e.kind, losses);
                self.style = style;
            }
            self.layout.joint_elements[jid.index()].push(name);
            self.layout.emitted_as[jid.index()] = if count == 1 { kind } else { "chain" };
        }
        if is_identity(&offset) {
            self.connect(&prev, &follower);
        } else {
            let name = self.scope.take(&format!("{jname}_offset"));
            let want = at(self, &name);
            self.fixed(&name, &offset, &format!("CAD offset of joint {what} at its start values"), want);
            self.connect(&prev, &format!("{name}.frame_a"));
            self.connect(&format!("{name}.frame_b"), &follower);
            extra.push(name);
        }
        self.layout.joint_elements[jid.index()].extend(extra);
    }
}

impl Writer<'_> {
    /// The passive losses of element `name` (a `Components.Revolute`/`Prismatic`, element `k` of
    /// joint `jid`) on its drive flange: a `LinearSpeedDependentTorque` / `Force` (`-d * speed`,
    /// its support fixed in the world, as MSL's joint `support` flange, the joint's axis torque
    /// acting between frame_a and frame_b) and a `BearingFriction` / `SupportFriction` with the
    /// constant Coulomb friction (`tau_pos = [0, f]`, `peak = 1`: the static friction equals the
    /// sliding one).
    fn losses(&mut self, jid: JointId, k: usize, name: &str, kind: PrimitiveKind, l: crate::pipeline::ir::Losses) {
        let (lib, fric, table, what) = if kind == PrimitiveKind::Revolute {
            ("Modelica.Mechanics.Rotational.Components", "BearingFriction", "tau_pos", "torque")
        } else {
            ("Modelica.Mechanics.Translational.Components", "SupportFriction", "f_pos", "force")
        };
        self.style = Style::Flange;
        let drive = format!("{name}.drive");
        let at = |w: &mut Self, n: &str, slot: i32| {
            let mut want = w.plan.element(jid, k, half_for(n));
            want.y -= 20 * slot;
            want
        };
        if l.damping > 0.0 {
            // A one-flange source grounded in the world: accelerating torque (force) on the
            // flange = tau_nominal * w / w_nominal = -d * w (MSL: `tau = -flange.tau`).
            let damper = self.scope.take(&format!("{name}_damper"));
            let want = at(self, &damper, 1);
            let place = self.put(&damper, Class::Drive, want);
            let (class, params) = if kind == PrimitiveKind::Revolute {
                (
                    "Rotational.Sources.LinearSpeedDependentTorque",
                    format!("tau_nominal=-{}, w_nominal=1, TorqueDirection=false", num(l.damping)),
                )
            } else {
                (
                    "Translational.Sources.LinearSpeedDependentForce",
                    format!("f_nominal=-{}, v_nominal=1, ForceDirection=false", num(l.damping)),
                )
            };
            let _ = writeln!(
                self.decl,
                "  Modelica.Mechanics.{class} {damper}({params})\n    \"Viscous damping of {name}: {what} = -d * speed on the drive flange, housing fixed in the world (URDF <dynamics damping>)\" {place};"
            );
            self.connect(&format!("{damper}.flange"), &drive);
        }
        if l.friction > 0.0 {
            let f = self.scope.take(&format!("{name}_friction"));
            let want = at(self, &f, 3);
            let place = self.put(&f, Class::TwoPort, want);
            let _ = writeln!(
                self.decl,
                "  {lib}.{fric} {f}({table}=[0, {}], peak=1)\n    \"Coulomb friction of {name}: {what} = friction * sign(speed), sticking up to it at rest (URDF <dynamics friction>)\" {place};",
                num(l.friction)
            );
            self.connect(&drive, &format!("{f}.flange_a"));
        }
    }
}

/// Whether a joint's drive flange can take a coupling: one revolute or prismatic element, not a
/// loop-closing cut.
fn couplable(v: &Validated, j: crate::pipeline::ir::JointId) -> bool {
    let a = &v.analysis;
    let chain = &a.chains[j.index()];
    chain.elements.len() == 1
        && matches!(chain.elements[0].kind, PrimitiveKind::Revolute | PrimitiveKind::Prismatic)
        && !a.hierarchy.loops.iter().any(|l| l.closing == j)
}

impl Writer<'_> {
    /// Couples the follower's drive flange to the leader's: `q_f = multiplier * q_l` (the front
    /// end admits only zero offsets). Revolute-revolute is an `IdealGear` (`phi_a = ratio *
    /// phi_b`, so `ratio = 1/multiplier`); a prismatic side goes through `IdealGearR2T`
    /// (`phi = ratio * s`); prismatic-prismatic through two of them sharing a rotational node.
    fn coupling(&mut self, c: &crate::pipeline::ir::Coupling, jnames: &[String]) -> Result<String, String> {
        let (l, f) = (c.leader, c.follower);
        if !couplable(self.v, l) || !couplable(self.v, f) {
            return Err(format!(
                "joint {} or its leader {} is emitted as {} / {}, not as one revolute or prismatic joint with a drive flange",
                jnames[f.index()],
                jnames[l.index()],
                self.layout.emitted_as[f.index()],
                self.layout.emitted_as[l.index()]
            ));
        }
        let kind = |j: crate::pipeline::ir::JointId| self.v.analysis.chains[j.index()].elements[0].kind;
        let (lk, fk) = (kind(l), kind(f));
        let ld = format!("{}.drive", self.layout.joint_elements[l.index()][0]);
        let fd = format!("{}.drive", self.layout.joint_elements[f.index()][0]);
        let m = num(c.multiplier);
        let name = self.scope.take(&format!("{}_mimic", jnames[f.index()]));
        let desc = mstr(&format!("{} = {m} * {} (URDF mimic)", jnames[f.index()], jnames[l.index()]));
        let rot = "Modelica.Mechanics.Rotational.Components";
        self.style = Style::Flange;
        let mut k = 0;
        let mut put = |w: &mut Self, name: &str| {
            k += 1;
            let want = w.plan.coupling(f, k - 1, half_for(name));
            w.put(name, Class::TwoPort, want)
        };
        use PrimitiveKind::{Prismatic as P, Revolute as R};
        match (lk, fk) {
            (R, R) => {
                let place = put(self, &name);
                let _ = writeln!(self.decl, "  {rot}.IdealGear {name}(ratio=1/({m}))\n    \"{desc}\" {place};");
                self.connect(&ld, &format!("{name}.flange_a"));
                self.connect(&format!("{name}.flange_b"), &fd);
            }
            (R, P) => {
                let place = put(self, &name);
                let _ = writeln!(self.decl, "  {rot}.IdealGearR2T {name}(ratio=1/({m}))\n    \"{desc}\" {place};");
                self.connect(&ld, &format!("{name}.flangeR"));
                self.connect(&format!("{name}.flangeT"), &fd);
            }
            (P, R) => {
                let place = put(self, &name);
                let _ = writeln!(self.decl, "  {rot}.IdealGearR2T {name}(ratio={m})\n    \"{desc}\" {place};");
                self.connect(&fd, &format!("{name}.flangeR"));
                self.connect(&format!("{name}.flangeT"), &ld);
            }
            _ => {
                let second = self.scope.take(&format!("{name}_b"));
                let place = put(self, &name);
                let _ = writeln!(self.decl, "  {rot}.IdealGearR2T {name}(ratio=1)\n    \"{desc}: leader side\" {place};");
                let place2 = put(self, &second);
                let _ = writeln!(self.decl, "  {rot}.IdealGearR2T {second}(ratio=1/({m}))\n    \"{desc}: follower side\" {place2};");
                self.connect(&format!("{name}.flangeT"), &ld);
                self.connect(&format!("{second}.flangeT"), &fd);
                self.connect(&format!("{name}.flangeR"), &format!("{second}.flangeR"));
                return Ok(format!("{name}, {second}"));
            }
        }
        Ok(name)
    }
}

fn is_user_frame(node_id: &str, display_name: &str) -> bool {
    node_id.contains("USERADDED") || !display_name.is_empty()
}

/// The frames `Mechanics` shows, in the order their components are made: the grounds' frames,
/// the joints' base and follower frames, the user-added CAD frames (repeats included).
pub(super) fn shown_frames(model: &Model) -> Vec<FrameId> {
    let mut used: Vec<FrameId> = model.grounds.iter().map(|g| g.frame).collect();
    for j in &model.joints {
        used.push(j.base);
        used.push(j.follower);
    }
    for body in &model.bodies {
        for f in &body.frames {
            let fr = model.frame(*f);
            if is_user_frame(&fr.node_id, &fr.display_name) {
                used.push(*f);
            }
        }
    }
    used
}

/// Writes the package. Shapes are referenced for every body with a mesh; the caller writes the
/// files under `<Pkg>/Resources/Shapes/<stem>.dxf|.stl` using [`Layout::shapes`].
pub fn write(model: &Model, v: &Validated, opts: &Options) -> Package {
    write_named(model, v, opts, names::assign_with_hints(model, &opts.name_hints))
}

/// The stem of each body's shape files (`<Pkg>/Resources/Shapes/<stem>.dxf|.stl`): the body's
/// name when it has a mesh with triangles, else `None`. [`Layout::shapes`] is this; a caller that
/// assigned the names itself ([`write_named`]) knows it before the package is written.
pub fn shape_stems(model: &Model, names: &names::Names) -> Vec<Option<String>> {
    model
        .bodies
        .iter()
        .zip(&names.bodies)
        .map(|(body, name)| body.mesh.as_ref().is_some_and(|m| !m.triangles.is_empty()).then(|| name.clone()))
        .collect()
}

/// [`write`] with the names already assigned (`names::assign_with_hints(model,
/// &opts.name_hints)`), so that work needing them ([`shape_stems`]) can start beside it.
pub fn write_named(model: &Model, v: &Validated, opts: &Options, names: names::Names) -> Package {
    let pkg = opts.package_name.as_str();
    let mut w = Writer {
        model,
        v,
        pkg,
        scope: names.scope.clone(),
        decl: String::new(),
        layout: Layout {
            shapes: shape_stems(model, &names),
            joint_elements: vec![Vec::new(); model.joints.len()],
            emitted_as: vec![""; model.joints.len()],
            ..Layout::default()
        },
        plan: Plan::new(model, v, &opts.name_hints.diagram),
        sheet: Sheet::default(),
        wires: Vec::new(),
        style: Style::Frame,
        coupled: vec![false; model.joints.len()],
    };
    for c in &model.couplings {
        if couplable(v, c.leader) && couplable(v, c.follower) {
            w.coupled[c.follower.index()] = true;
        }
    }
    let g = Vector3::from(opts.gravity);
    let g_norm = g.norm();
    let n = if g_norm > 0.0 { g / g_norm } else { Vector3::new(0.0, -1.0, 0.0) };
    let place = w.put("world", Class::World, w.plan.world(10));
    let _ = writeln!(
        w.decl,
        "  inner {MB}.World world(n={}, g={}) \"World frame: the CAD assembly's frame\"\n    {place};",
        vec3(&n),
        num(g_norm)
    );

    let analysis = &v.analysis;
    let _ = writeln!(w.decl, "\n  // Bodies: frame_a is each part's CS1 frame");
    for (i, body) in model.bodies.iter().enumerate() {
        let name = &names.bodies[i];
        let cs1 = model.frame(body.cs1).pose;
        let rc = cs1.rotation.to_rotation_matrix().into_inner();
        let mp = model.mass_properties_cs1(crate::pipeline::ir::BodyId(i as u32));
        let (r_cm, ia) = (mp.r_cm, mp.inertia);
        let i_scale = ia.amax();
        let anim = if body.mesh.is_some() || body.mass == 0.0 { ",\n    animation=false" } else { "" };
        let initial = if analysis.hierarchy.free_roots.iter().any(|b| b.index() == i) {
            let a = cardan_xyz(&rc);
            format!(
                ",\n    r_0(start={}, each fixed=true),\n    v_0(start={{0, 0, 0}}, each fixed=true),\n    angles_fixed=true,\n    angles_start={},\n    w_0_fixed=true",
                vec3(&cs1.translation.vector),
                vec3(&a)
            )
        } else {
            String::new()
        };
        let want = w.plan.body(crate::pipeline::ir::BodyId(i as u32), half_for(name).max(15));
        let place = w.put(name, Class::TwoPort, want);
        let _ = writeln!(
            w.decl,
            "  {MB}.Parts.Body {name}(\n    m={},\n    r_CM={},\n    I_11={}, I_22={}, I_33={},\n    I_21={}, I_31={}, I_32={}{anim}{initial})\n    \"{}{} (nodeID {})\" {place};",
            num(body.mass),
            vec3(&r_cm),
            num_in(ia[(0, 0)], i_scale),
            num_in(ia[(1, 1)], i_scale),
            num_in(ia[(2, 2)], i_scale),
            num_in(ia[(1, 0)], i_scale),
            num_in(ia[(2, 0)], i_scale),
            num_in(ia[(2, 1)], i_scale),
            if is_root_part(body) { "Assembly root " } else { "Part " },
            mstr(&body.cad_name),
            mstr(&body.node_id)
        );
        w.layout.connectors.insert(body.cs1, format!("{name}.frame_a"));
    }

    let _ = writeln!(w.decl, "\n  // Frames: grounds, joint attachment frames and user-added CAD frames");
    let used = shown_frames(model);
    for f in used {
        w.frame_connector(f, &names.bodies);
    }

    let _ = writeln!(w.decl, "\n  // Joints: base frame -> follower frame; start values reproduce the CAD pose");
    let mut order: Vec<_> = analysis.hierarchy.tree.clone();
    order.extend(analysis.hierarchy.loops.iter().map(|l| l.closing));
    for jid in order {
        w.joint(jid, &names.joints[jid.index()]);
    }

    if !model.couplings.is_empty() {
        let _ = writeln!(w.decl, "\n  // Couplings: joints whose coordinate follows another joint's (URDF mimic)");
        for c in &model.couplings {
            let done = w.coupling(c, &names.joints);
            w.layout.couplings.push(done);
        }
    }

    w.style = Style::Frame;
    let _ = writeln!(w.decl, "\n  // Shapes: CAD meshes in each body frame, metres");
    for (i, body) in model.bodies.iter().enumerate() {
        if body.mesh.as_ref().is_none_or(|m| m.triangles.is_empty()) {
            continue;
        }
        let bname = &names.bodies[i];
        let sname = w.scope.take(&format!("{bname}_shape"));
        let c = body.display_rgb();
        let want = w.plan.shape(crate::pipeline::ir::BodyId(i as u32), half_for(&sname));
        let place = w.put(&sname, Class::TwoPort, want);
        let _ = writeln!(
            w.decl,
            "  {MB}.Visualizers.FixedShape {sname}(\n    shapeType=\"modelica://{pkg}/Resources/Shapes/{bname}.dxf\",\n    length=1, width=1, height=1,\n    extra=0,\n    color={{{}, {}, {}}})\n    \"Shape of {}\" {place};",
            c[0],
            c[1],
            c[2],
            mstr(&body.cad_name)
        );
        w.connect(&format!("{bname}.frame_a"), &format!("{sname}.frame_a"));
    }

    for (a, b, style) in std::mem::take(&mut w.wires) {
        w.sheet.connect(&a, &b, style);
    }
    let mechanics = mechanics_file(&w, opts);
    let mut files = vec![
        (format!("{pkg}/package.mo"), package_file(model, opts).into_bytes()),
        (format!("{pkg}/package.order"), b"Mechanics\nMechatronics\nComponents\n".to_vec()),
        (format!("{pkg}/Mechanics.mo"), mechanics.into_bytes()),
    ];
    files.extend(components(pkg, opts));
    let mut layout = w.layout;
    layout.names = Some(names);
    layout.diagram_groups = w.plan.groups;
    layout.diagram = w.sheet;
    Package { files, layout }
}

/// The provenance paragraph, escaped for a Modelica string.
fn provenance(model: &Model, opts: &Options) -> String {
    mstr(&provenance_html(model, &opts.converter_version))
}

/// One HTML paragraph saying where a package came from (HTML-escaped; callers escape it for a
/// Modelica string).
pub fn provenance_html(model: &Model, converter_version: &str) -> String {
    let s = &model.source;
    format!(
        "<p>Converted by cad2mo {} from <code>{}</code> ({}), exported by {} from {} on {} by {}.</p>",
        html(converter_version),
        html(&s.file),
        html(&s.container),
        html(&s.created_using),
        html(&s.created_from),
        html(&s.created_on),
        html(&s.created_by)
    )
}

fn package_file(model: &Model, opts: &Options) -> String {
    let pkg = &opts.package_name;
    format!(
        "within ;\npackage {pkg} \"Modelica model of CAD assembly {}, converted by cad2mo\"\n  annotation (\n    uses(Modelica(version=\"4.0.0\")),\n    Documentation(info=\"<html>\n{}\n<p><code>Mechanics</code> is the pure mechanical model, regenerated at every CAD change. <code>Components</code> holds joints with a 1-D <code>drive</code> flange: left open the joint is free, a motor connected to it actuates the joint.</p>\n</html>\"));\nend {pkg};\n",
        mstr(&model.name),
        provenance(model, opts)
    )
}

fn mechanics_file(w: &Writer, opts: &Options) -> String {
    let model = w.model;
    let pkg = w.pkg;
    let h = &w.v.analysis.hierarchy;
    let mut notes = String::new();
    for (l, info) in h.loops.iter().zip(&w.v.analysis.loops.loops) {
        let j = model.joint(l.closing);
        let _ = write!(notes, "<li>Joint {} closes a loop: {}.</li>", html(&j.cad_name), html(&info.why));
    }
    for b in &h.free_bodies {
        let _ = write!(notes, "<li>Body {} has no path to the ground (free body).</li>", html(&model.body(*b).cad_name));
    }
    let notes = if notes.is_empty() { String::new() } else { format!("\n<ul>{}</ul>", mstr(&notes)) };
    let ex = Experiment::for_model(model, opts.gravity);
    let extent = w.sheet.extent(40);
    format!(
        "within {pkg};\nmodel Mechanics \"Mechanical model of {} ({} bodies, {} joints)\"\n{}\nequation\n{}  annotation (\n    {},\n    Diagram({}),\n    Icon({}, graphics={{{}}}),\n    Documentation(info=\"<html>\n{}\n<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>{}\n<p>{}</p>\n<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>\n</html>\"));\nend Mechanics;\n",
        mstr(&model.name),
        model.bodies.len(),
        model.joints.len(),
        w.decl.trim_end(),
        w.sheet.equations(0),
        ex.annotation(),
        super::diagram::coordinate_system(&extent),
        super::diagram::coordinate_system(&super::diagram::Rect { x1: -100, y1: -100, x2: 100, y2: 100 }),
        MECHANICS_ICON,
        provenance(model, opts),
        notes,
        mstr(&ex.why)
    )
}

/// The icon of `Mechanics`: a two-link arm on a base.
pub const MECHANICS_ICON: &str = "\n      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),\n      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),\n      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),\n      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),\n      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),\n      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),\n      Text(extent={{-150,110},{150,150}}, textString=\"%name\", textColor={0,0,255})";

/// The `experiment` annotation of a model and the sentence that says how it was chosen.
#[derive(Clone, Debug)]
pub struct Experiment {
    pub stop: f64,
    pub why: String,
}

impl Experiment {
    /// `Mechanics`: with gravity, three periods of a pendulum as long as the mechanism's reach
    /// (the largest distance of a body's centre of mass from the world origin), rounded up to a
    /// readable value within 1 to 20 s; 1 s without gravity or without mass.
    pub fn for_model(model: &Model, gravity: [f64; 3]) -> Experiment {
        let g = Vector3::from(gravity).norm();
        let mut reach: f64 = 0.0;
        for (i, body) in model.bodies.iter().enumerate() {
            if body.mass > 0.0 {
                let mp = model.mass_properties_cs1(crate::pipeline::ir::BodyId(i as u32));
                let cg = model.frame(body.cs1).pose * nalgebra::Point3::from(mp.r_cm);
                reach = reach.max(cg.coords.norm());
            }
        }
        if !(g > 0.0 && reach > 0.0 && reach.is_finite()) {
            return Experiment {
                stop: 1.0,
                why: "Experiment: 1 s (no gravity or no mass to set a time scale), 500 output intervals, tolerance 1e-6.".into(),
            };
        }
        let period = 2.0 * std::f64::consts::PI * (reach / g).sqrt();
        let stop = nice_up((3.0 * period).clamp(1.0, 20.0));
        Experiment {
            stop,
            why: format!(
                "Experiment: {} s, about three swings of a pendulum as long as the mechanism's reach ({} m, period {} s), 500 output intervals, tolerance 1e-6.",
                num(stop),
                num((reach * 1000.0).round() / 1000.0),
                num((period * 100.0).round() / 100.0)
            ),
        }
    }

    /// For a run of `stop` seconds.
    pub fn of(stop: f64, why: String) -> Experiment {
        Experiment { stop, why }
    }

    pub fn annotation(&self) -> String {
        format!("experiment(StopTime={}, Interval={}, Tolerance=1e-06)", num(self.stop), num(interval(self.stop)))
    }
}

/// The output interval for a run of `stop` seconds: 500 intervals, as a round number.
pub fn interval(stop: f64) -> f64 {
    let v = one_two_five_up(stop / 500.0);
    format!("{v:.12e}").parse().unwrap_or(v)
}

/// `x` rounded up to 1, 2 or 5 times a power of ten, or a whole number of seconds above 2.
fn nice_up(x: f64) -> f64 {
    if x > 2.0 {
        return x.ceil();
    }
    one_two_five_up(x)
}

/// `x` (> 0) rounded up to 1, 2 or 5 times a power of ten.
fn one_two_five_up(x: f64) -> f64 {
    let p = 10f64.powf(x.log10().floor());
    let m = x / p;
    let m = if m <= 1.0 {
        1.0
    } else if m <= 2.0 {
        2.0
    } else if m <= 5.0 {
        5.0
    } else {
        10.0
    };
    m * p
}

fn components(pkg: &str, opts: &Options) -> Vec<(String, Vec<u8>)> {
    let version = mstr(&opts.converter_version);
    let joint = |class: &str, base: &str, flange: &str, what: &str| {
        format!(
            "within {pkg}.Components;\nmodel {class} \"{what} joint with a drive flange\"\n  extends {MB}.Joints.{base}(final useAxisFlange=true);\n  {flange} drive\n    \"Drive flange: connect a motor or gear here; left open, the joint is free\"\n    annotation (Placement(transformation(extent={{{{-70,90}},{{-50,110}}}})));\nequation\n  connect(drive, axis);\n  annotation (Documentation(info=\"<html><p>The MSL {base} joint with <code>useAxisFlange=true</code>, exposing the 1-D axis flange as <code>drive</code> (the abstract joint of Juh&aacute;sz and Schmucker, 2008). Generated by cad2mo {version}.</p></html>\"));\nend {class};\n"
        )
    };
    vec![
        (
            format!("{pkg}/Components/package.mo"),
            format!("within {pkg};\npackage Components \"Joints with a drive flange, used by Mechanics\"\n  extends Modelica.Icons.Package;\n  annotation (Documentation(info=\"<html><p>Generated by cad2mo {version}.</p></html>\"));\nend Components;\n").into_bytes(),
        ),
        (format!("{pkg}/Components/package.order"), b"Revolute\nPrismatic\nDrives\n".to_vec()),
        (
            format!("{pkg}/Components/Revolute.mo"),
            joint("Revolute", "Revolute", "Modelica.Mechanics.Rotational.Interfaces.Flange_a", "Revolute").into_bytes(),
        ),
        (
            format!("{pkg}/Components/Prismatic.mo"),
            joint("Prismatic", "Prismatic", "Modelica.Mechanics.Translational.Interfaces.Flange_a", "Prismatic")
                .into_bytes(),
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Rotation3, Vector3};

    fn rebuild(a: &Vector3<f64>) -> Matrix3<f64> {
        (Rotation3::from_axis_angle(&Vector3::x_axis(), a.x)
            * Rotation3::from_axis_angle(&Vector3::y_axis(), a.y)
            * Rotation3::from_axis_angle(&Vector3::z_axis(), a.z))
        .into_inner()
    }

    #[test]
    fn cardan_angles_rebuild_the_rotation() {
        for (x, y, z) in
            [(0.3, -0.2, 1.1), (2.9, 0.1, -3.0), (0.0, std::f64::consts::FRAC_PI_2, 0.4), (1.0, -std::f64::consts::FRAC_PI_2, 0.0)]
        {
            let r = Rotation3::from_euler_angles(x, y, z).into_inner();
            let a = cardan_xyz(&r);
            assert!((rebuild(&a) - r).abs().max() < 1e-12, "{x} {y} {z}: {a:?}");
        }
    }

    #[test]
    fn numbers_and_strings() {
        assert_eq!(num(-0.0), "0.0");
        assert_eq!(num(1e-5), "1e-5");
        assert_eq!(num(0.1), "0.1");
        // Unit-conversion products keep the digits the data has.
        assert_eq!(num(0.0027950400000000004), "0.00279504");
        assert_eq!(num(25.4 * 0.1), "2.54");
        assert_eq!(num(-1.0000000000000002), "-1.0");
        // Noise relative to the quantity's scale becomes 0, real small values stay.
        assert_eq!(num_in(8.6e-24, 1e-3), "0.0");
        assert_eq!(num_in(2e-15, 1e-3), "2e-15");
        assert_eq!(vec3(&Vector3::new(0.1, 1e-17, -0.2)), "{0.1, 0.0, -0.2}");
        assert_eq!(vec3(&Vector3::new(1e-17, 0.0, 0.0)), "{1e-17, 0.0, 0.0}");
        assert_eq!(mstr("a \"b\" \\c"), "a \\\"b\\\" \\\\c");
    }
}
