//! Forward kinematics over an emitted `Mechanics.mo`, independent of the converter.
//!
//! [`forward_kinematics`] starts from the world's `frame_b` (the identity) and walks the
//! `connect` graph and the components, with MSL semantics at the joints' start values:
//!
//! - `Parts.FixedTranslation(r)`: frame_b = frame_a translated by `r` (resolved in frame_a);
//! - `Parts.FixedRotation(r, rotationType=TwoAxesVectors, n_x, n_y)`: frame_b origin = frame_a
//!   origin + R_a r, orientation R_a R_rel with `Frames.from_nxy(n_x, n_y)` (`RotationAxis`
//!   with `n`, `angle` in degrees is read too);
//! - `PKG.Components.Revolute(n, phi(start))`: rotation about unit(n) by phi;
//! - `PKG.Components.Prismatic(n, s(start))`: translation by unit(n) s;
//! - `Joints.Spherical`: the identity (its angles start at 0);
//! - `Joints.RevolutePlanarLoopConstraint(n)`: not walked through; once both frames are known it
//!   is checked (same origin, R_a^T R_b keeps n);
//! - `Joints.Constraints.{Spherical, Revolute(n), Prismatic, Universal(n_a, n_b)}`: not walked
//!   through; once both frames are known their equations are checked: frame_b's origin resolved
//!   in frame_a is zero along each locked axis (`x_locked`, ... default true), and the relative
//!   rotation is about n only (Revolute), none (Prismatic), or keeps n_a perpendicular to n_b
//!   (Universal);
//! - `World` (frame_b), `Parts.Body` and `Visualizers.FixedShape` (frame_a): end points.
//!
//! Both directions are walked. A connector reached a second time (a loop closing through a
//! connect or a component) is compared with its first pose; a mismatch is an error. Connectors
//! with no path from the world are left out of the result.

use std::collections::{BTreeMap, VecDeque};

use nalgebra::{Isometry3, Matrix3, Point3, Rotation3, Translation3, Unit, UnitQuaternion, Vector3};

pub use crate::modelica::{parse_mechanics, Component, Model, Value};

/// Position tolerance of the loop checks, m.
pub const POS_TOL: f64 = 1e-9;
/// Rotation tolerance of the loop checks, rad.
pub const ANGLE_TOL: f64 = 1e-9;

const MB: &str = "Modelica.Mechanics.MultiBody";

/// World poses of the connectors reached from the world.
#[derive(Clone, Debug, Default)]
pub struct Poses {
    /// `"LINK.frame_a"` -> pose of the connector in the world frame.
    pub connectors: BTreeMap<String, Isometry3<f64>>,
    /// Consistency checks performed on connections that closed loops (a connector reached a
    /// second time, or a constraint element with both frames known).
    pub loop_checks: usize,
}

impl Poses {
    /// The pose of `connector` (`"LINK.frame_a"`), when reached.
    pub fn get(&self, connector: &str) -> Option<&Isometry3<f64>> {
        self.connectors.get(connector)
    }
}

/// Position (m) and rotation (rad) differences between two poses. The angle is computed as
/// `2 atan2(|v|, |w|)` of the relative quaternion, accurate near zero (unlike `acos`).
pub fn pose_error(a: &Isometry3<f64>, b: &Isometry3<f64>) -> (f64, f64) {
    let dp = (a.translation.vector - b.translation.vector).norm();
    (dp, rotation_angle(&a.rotation, &b.rotation))
}

/// The angle of the rotation `a^-1 b`, rad, in [0, pi].
pub fn rotation_angle(a: &UnitQuaternion<f64>, b: &UnitQuaternion<f64>) -> f64 {
    let q = a.inverse() * b;
    2.0 * q.imag().norm().atan2(q.scalar().abs())
}

/// What a component is, with MSL semantics at its start values. The walker and the structural
/// check (`structure.rs`) both classify components with [`element`], so the two agree on every
/// class they know.
#[derive(Clone, Debug, PartialEq)]
pub enum Element {
    /// `World`: seeds its frame_b with the identity.
    World,
    /// A single connector frame_a, nothing to propagate (`Parts.Body`, `Visualizers.FixedShape`).
    Leaf,
    /// `Parts.FixedTranslation`, `Parts.FixedRotation`: pose(frame_b) = pose(frame_a) * transform.
    Rigid(Isometry3<f64>),
    /// `PKG.Components.Revolute`: rotation by `phi` (start value) about unit `n` (frame_a).
    Revolute { n: Unit<Vector3<f64>>, phi: f64 },
    /// `PKG.Components.Prismatic`: translation by `s` (start value) along unit `n` (frame_a).
    Prismatic { n: Unit<Vector3<f64>>, s: f64 },
    /// `Joints.Spherical`: coincident origins, rotation free (the identity at the start).
    Spherical,
    /// A loop-closing constraint: not walked through, checked once both frames are known.
    Constraint(Constraint),
}

/// The equations of a loop-closing constraint element.
#[derive(Clone, Debug, PartialEq)]
pub enum Constraint {
    /// `Joints.RevolutePlanarLoopConstraint(n)`, unit `n` in frame_a: the relative position of
    /// frame_b's origin, resolved in frame_a, has no component perpendicular to n (2 equations).
    /// The walker checks the stronger start-pose condition the converter guarantees: same
    /// origin, and R_a^T R_b keeps n.
    PlanarLoop(Vector3<f64>),
    /// `Joints.Constraints.{Spherical, Revolute, Prismatic, Universal}`.
    Cut(Cut),
}

/// A `Joints.Constraints.*` element.
#[derive(Clone, Debug, PartialEq)]
pub struct Cut {
    /// `Spherical`, `Revolute`, `Prismatic` or `Universal`.
    pub kind: &'static str,
    /// `x_locked`, `y_locked`, `z_locked` (default true): frame_b's origin, resolved in frame_a,
    /// has a zero component along that axis of frame_a.
    pub locked: [bool; 3],
    pub rotation: CutRotation,
}

/// The rotational equations of a [`Cut`].
#[derive(Clone, Debug, PartialEq)]
pub enum CutRotation {
    /// `Constraints.Spherical`: none.
    Free,
    /// `Constraints.Revolute(n)`: relative rotation about unit `n` (frame_a) only (2 equations).
    About(Vector3<f64>),
    /// `Constraints.Prismatic`: no relative rotation (3 equations).
    Locked,
    /// `Constraints.Universal(n_a, n_b)`: unit `n_a` (fixed in frame_a) stays perpendicular to
    /// unit `n_b` (fixed in frame_b) (1 equation).
    Perpendicular { n_a: Vector3<f64>, n_b: Vector3<f64> },
}

impl Cut {
    /// Number of equations: locked translations plus rotational equations.
    pub fn equations(&self) -> usize {
        let rot = match self.rotation {
            CutRotation::Free => 0,
            CutRotation::About(_) => 2,
            CutRotation::Locked => 3,
            CutRotation::Perpendicular { .. } => 1,
        };
        self.locked.iter().filter(|l| **l).count() + rot
    }
}

impl Element {
    /// pose(frame_b) = pose(frame_a) * transform, for elements the walker goes through.
    pub fn transform(&self) -> Option<Isometry3<f64>> {
        match self {
            Element::Rigid(t) => Some(*t),
            Element::Revolute { n, phi } => Some(Isometry3::from_parts(Translation3::identity(), UnitQuaternion::from_axis_angle(n, *phi))),
            Element::Prismatic { n, s } => Some(Isometry3::from_parts(Translation3::from(n.into_inner() * *s), UnitQuaternion::identity())),
            Element::Spherical => Some(Isometry3::identity()),
            Element::World | Element::Leaf | Element::Constraint(_) => None,
        }
    }

    /// The element's frame connectors.
    pub fn connectors(&self) -> &'static [&'static str] {
        match self {
            Element::World => &["frame_b"],
            Element::Leaf => &["frame_a"],
            _ => &["frame_a", "frame_b"],
        }
    }
}

fn vec3_param(c: &Component, key: &str, default: Option<[f64; 3]>) -> Result<Vector3<f64>, String> {
    match c.params.get(key) {
        None => default.map(Vector3::from).ok_or_else(|| format!("component `{}` ({}): missing parameter `{key}`", c.name, c.class)),
        Some(Value::Vec(v)) if v.len() == 3 && v.iter().all(|x| x.is_finite()) => Ok(Vector3::new(v[0], v[1], v[2])),
        Some(other) => Err(format!("component `{}` ({}): `{key}` = {other} is not a finite 3-vector", c.name, c.class)),
    }
}

fn num_param(c: &Component, key: &str, default: Option<f64>) -> Result<f64, String> {
    match c.params.get(key) {
        None => default.ok_or_else(|| format!("component `{}` ({}): missing parameter `{key}`", c.name, c.class)),
        Some(Value::Num(x)) if x.is_finite() => Ok(*x),
        Some(other) => Err(format!("component `{}` ({}): `{key}` = {other} is not a finite number", c.name, c.class)),
    }
}

fn bool_param(c: &Component, key: &str, default: bool) -> Result<bool, String> {
    match c.params.get(key) {
        None => Ok(default),
        Some(Value::Bool(b)) => Ok(*b),
        Some(other) => Err(format!("component `{}` ({}): `{key}` = {other} is not a Boolean", c.name, c.class)),
    }
}

/// unit(param), like MSL's `normalizeWithAssert`.
fn unit_param(c: &Component, key: &str, default: [f64; 3]) -> Result<Unit<Vector3<f64>>, String> {
    let n = vec3_param(c, key, Some(default))?;
    Unit::try_new(n, 0.0).ok_or_else(|| format!("component `{}` ({}): axis {key} is the zero vector", c.name, c.class))
}

/// unit(n), like MSL's `normalizeWithAssert`.
fn axis_param(c: &Component, default: [f64; 3]) -> Result<Unit<Vector3<f64>>, String> {
    unit_param(c, "n", default)
}

/// MSL `Frames.from_nxy`: columns e_x, e_y, e_z of frame_b resolved in frame_a.
pub fn from_nxy(n_x: &Vector3<f64>, n_y: &Vector3<f64>) -> Rotation3<f64> {
    let e_x = if n_x.norm() < 1e-10 { Vector3::x() } else { n_x.normalize() };
    let n_z_aux = e_x.cross(n_y);
    let n_y_aux = if n_z_aux.norm_squared() > 1e-6 {
        *n_y
    } else if e_x.x.abs() > 1e-6 {
        Vector3::y()
    } else {
        Vector3::x()
    };
    let e_z = e_x.cross(&n_y_aux).normalize();
    let e_y = e_z.cross(&e_x);
    Rotation3::from_matrix_unchecked(Matrix3::from_columns(&[e_x, e_y, e_z]))
}

fn fixed_rotation(c: &Component) -> Result<Element, String> {
    let r = vec3_param(c, "r", Some([0.0; 3]))?;
    let rot_type = match c.params.get("rotationType") {
        None => "RotationAxis".to_string(),
        Some(Value::Ident(s)) => s.rsplit('.').next().unwrap_or_default().to_string(),
        Some(other) => return Err(format!("component `{}`: rotationType = {other} is not a name", c.name)),
    };
    let rot = match rot_type.as_str() {
        "TwoAxesVectors" => {
            let n_x = vec3_param(c, "n_x", Some([1.0, 0.0, 0.0]))?;
            let n_y = vec3_param(c, "n_y", Some([0.0, 1.0, 0.0]))?;
            UnitQuaternion::from_rotation_matrix(&from_nxy(&n_x, &n_y))
        }
        "RotationAxis" => {
            let n = axis_param(c, [1.0, 0.0, 0.0])?;
            let angle_deg = num_param(c, "angle", Some(0.0))?;
            UnitQuaternion::from_axis_angle(&n, angle_deg.to_radians())
        }
        other => return Err(format!("component `{}`: rotationType {other} is not supported", c.name)),
    };
    Ok(Element::Rigid(Isometry3::from_parts(Translation3::from(r), rot)))
}

/// A `Joints.Constraints.*` class (`kind` is the last part of its name).
fn cut(c: &Component, kind: &'static str) -> Result<Element, String> {
    let locked = [bool_param(c, "x_locked", true)?, bool_param(c, "y_locked", true)?, bool_param(c, "z_locked", true)?];
    let rotation = match kind {
        "Spherical" => CutRotation::Free,
        "Revolute" => CutRotation::About(axis_param(c, [0.0, 0.0, 1.0])?.into_inner()),
        "Prismatic" => CutRotation::Locked,
        _ => CutRotation::Perpendicular {
            n_a: unit_param(c, "n_a", [1.0, 0.0, 0.0])?.into_inner(),
            n_b: unit_param(c, "n_b", [0.0, 1.0, 0.0])?.into_inner(),
        },
    };
    Ok(Element::Constraint(Constraint::Cut(Cut { kind, locked, rotation })))
}

/// A 1-D flange connector (a joint's `drive`, a gear's `flange_a`/`flangeR`/...): its connects
/// (URDF mimic couplings) carry no frame.
pub fn is_flange(r: &str) -> bool {
    r.rsplit_once('.').is_some_and(|(_, c)| c == "drive" || c.starts_with("flange"))
}

/// Classifies a component of `model` (whose package is `model.package`).
pub fn element(model: &Model, c: &Component) -> Result<Element, String> {
    let class = c.class.as_str();
    if let Some(short) = class.strip_prefix(MB).and_then(|s| s.strip_prefix('.')) {
        return match short {
            "World" => Ok(Element::World),
            "Parts.Body" | "Visualizers.FixedShape" => Ok(Element::Leaf),
            "Parts.FixedTranslation" => {
                Ok(Element::Rigid(Isometry3::from_parts(Translation3::from(vec3_param(c, "r", None)?), UnitQuaternion::identity())))
            }
            "Parts.FixedRotation" => fixed_rotation(c),
            "Joints.Spherical" => {
                if let Some(v) = c.params.get("angles_start") {
                    if *v != Value::Vec(vec![0.0; 3]) {
                        return Err(format!("component `{}`: Spherical with angles_start = {v} is not supported", c.name));
                    }
                }
                Ok(Element::Spherical)
            }
            "Joints.RevolutePlanarLoopConstraint" => {
                Ok(Element::Constraint(Constraint::PlanarLoop(axis_param(c, [0.0, 0.0, 1.0])?.into_inner())))
            }
            "Joints.Constraints.Spherical" => cut(c, "Spherical"),
            "Joints.Constraints.Revolute" => cut(c, "Revolute"),
            "Joints.Constraints.Prismatic" => cut(c, "Prismatic"),
            "Joints.Constraints.Universal" => cut(c, "Universal"),
            _ => Err(format!("component `{}`: unknown class `{}`", c.name, c.class)),
        };
    }
    // 1-D couplings between drive flanges (URDF mimic) move no frame.
    // ... nor do the joints' losses on them (URDF dynamics: damping, friction).
    if matches!(
        class,
        "Modelica.Mechanics.Rotational.Components.IdealGear"
            | "Modelica.Mechanics.Rotational.Components.IdealGearR2T"
            | "Modelica.Mechanics.Rotational.Sources.LinearSpeedDependentTorque"
            | "Modelica.Mechanics.Rotational.Components.BearingFriction"
            | "Modelica.Mechanics.Translational.Sources.LinearSpeedDependentForce"
            | "Modelica.Mechanics.Translational.Components.SupportFriction"
    ) {
        return Ok(Element::Leaf);
    }
    match class.strip_prefix(model.package.as_str()).and_then(|s| s.strip_prefix(".Components.")) {
        Some("Revolute") if !model.package.is_empty() => {
            Ok(Element::Revolute { n: axis_param(c, [0.0, 0.0, 1.0])?, phi: num_param(c, "phi.start", Some(0.0))? })
        }
        Some("Prismatic") if !model.package.is_empty() => {
            Ok(Element::Prismatic { n: axis_param(c, [1.0, 0.0, 0.0])?, s: num_param(c, "s.start", Some(0.0))? })
        }
        _ => Err(format!("component `{}`: unknown class `{}`", c.name, c.class)),
    }
}

/// `x <= tol`, false for NaN (a NaN residual is a violation).
fn within(x: f64, tol: f64) -> bool {
    x <= tol
}

/// Checks a constraint element's equations at the start poses `a` (frame_a) and `b` (frame_b),
/// to `pos_tol` m and `angle_tol` (rad, or the sine of an angle).
fn check_constraint(
    name: &str,
    constraint: &Constraint,
    a: &Isometry3<f64>,
    b: &Isometry3<f64>,
    pos_tol: f64,
    angle_tol: f64,
) -> Result<(), String> {
    let (fa, fb) = (format!("{name}.frame_a"), format!("{name}.frame_b"));
    let rel = a.rotation.inverse() * b.rotation;
    match constraint {
        Constraint::PlanarLoop(n) => {
            let dp = (a.translation.vector - b.translation.vector).norm();
            let dn = (rel * n - n).norm();
            if !(dp <= pos_tol && dn <= angle_tol) {
                return Err(format!(
                    "RevolutePlanarLoopConstraint {name} violated between {fa} and {fb}: origins differ by {dp:e} m, \
                     R_a^T R_b moves the axis {:?} by {dn:e}",
                    n.as_slice()
                ));
            }
        }
        Constraint::Cut(cut) => {
            let kind = cut.kind;
            // frame_b's origin relative to frame_a's, resolved in frame_a.
            let r = a.rotation.inverse() * (b.translation.vector - a.translation.vector);
            for (i, axis) in ["x", "y", "z"].iter().enumerate() {
                if cut.locked[i] && !within(r[i].abs(), pos_tol) {
                    return Err(format!(
                        "Constraints.{kind} {name} violated between {fa} and {fb}: frame_b's origin is {:e} m from \
                         frame_a's along the locked {axis} axis of frame_a",
                        r[i]
                    ));
                }
            }
            match &cut.rotation {
                CutRotation::Free => {}
                CutRotation::About(n) => {
                    let dn = (rel * n - n).norm();
                    if !within(dn, angle_tol) {
                        return Err(format!(
                            "Constraints.{kind} {name} violated between {fa} and {fb}: R_a^T R_b moves the axis {:?} \
                             by {dn:e}",
                            n.as_slice()
                        ));
                    }
                }
                CutRotation::Locked => {
                    let da = rotation_angle(&a.rotation, &b.rotation);
                    if !within(da, angle_tol) {
                        return Err(format!(
                            "Constraints.{kind} {name} violated between {fa} and {fb}: the frames are rotated by \
                             {da:e} rad"
                        ));
                    }
                }
                CutRotation::Perpendicular { n_a, n_b } => {
                    let dot = n_a.dot(&(rel * n_b));
                    if !within(dot.abs(), angle_tol) {
                        return Err(format!(
                            "Constraints.{kind} {name} violated between {fa} and {fb}: n_a {:?} . n_b {:?} = {dot:e} \
                             (must be 0)",
                            n_a.as_slice(),
                            n_b.as_slice()
                        ));
                    }
                }
            }
        }
    }
    Ok(())
}

struct Link {
    a: String,
    b: String,
    /// pose(b) = pose(a) * t
    t: Isometry3<f64>,
    what: String,
}

/// [`forward_kinematics_tol`] with [`POS_TOL`] and [`ANGLE_TOL`].
pub fn forward_kinematics(model: &Model) -> Result<Poses, String> {
    forward_kinematics_tol(model, POS_TOL, ANGLE_TOL)
}

/// World poses of every connector reachable from the world, checking every loop closure to
/// `pos_tol` m and `angle_tol` rad.
pub fn forward_kinematics_tol(model: &Model, pos_tol: f64, angle_tol: f64) -> Result<Poses, String> {
    let mut kinds: BTreeMap<&str, Element> = BTreeMap::new();
    let mut world = None;
    let mut links: Vec<Link> = Vec::new();
    let mut constraints = Vec::new();
    for c in &model.components {
        let kind = element(model, c)?;
        if kind == Element::World {
            if let Some(w) = world.replace(c.name.as_str()) {
                return Err(format!("two worlds: `{w}` and `{}`", c.name));
            }
        }
        if let Some(t) = kind.transform() {
            links.push(Link {
                a: format!("{}.frame_a", c.name),
                b: format!("{}.frame_b", c.name),
                t,
                what: format!("component {} ({})", c.name, c.class),
            });
        }
        if let Element::Constraint(k) = &kind {
            constraints.push((c.name.as_str(), k.clone()));
        }
        if kinds.insert(c.name.as_str(), kind).is_some() {
            return Err(format!("component `{}` declared twice", c.name));
        }
    }
    let world = world.ok_or("no World component")?;

    let check_connector = |r: &str| -> Result<(), String> {
        let (comp, conn) = r.split_once('.').ok_or_else(|| format!("connect to `{r}`: not COMPONENT.CONNECTOR"))?;
        let kind = kinds.get(comp).ok_or_else(|| format!("connect to `{r}`: no component `{comp}`"))?;
        if kind.connectors().contains(&conn) {
            Ok(())
        } else {
            Err(format!("connect to `{r}`: `{comp}` has no frame connector `{conn}`"))
        }
    };
    for (a, b) in &model.connects {
        if is_flange(a) || is_flange(b) {
            continue;
        }
        check_connector(a)?;
        check_connector(b)?;
        links.push(Link { a: a.clone(), b: b.clone(), t: Isometry3::identity(), what: format!("connect({a}, {b})") });
    }

    let mut adjacency: BTreeMap<&str, Vec<usize>> = BTreeMap::new();
    for (i, l) in links.iter().enumerate() {
        adjacency.entry(l.a.as_str()).or_default().push(i);
        if l.b != l.a {
            adjacency.entry(l.b.as_str()).or_default().push(i);
        }
    }

    let mut poses = Poses::default();
    // How each connector got its pose, for error messages.
    let mut source: BTreeMap<String, String> = BTreeMap::new();
    let seed = format!("{world}.frame_b");
    poses.connectors.insert(seed.clone(), Isometry3::identity());
    source.insert(seed.clone(), "the world".to_string());
    let mut queue = VecDeque::from([seed]);
    let mut used = vec![false; links.len()];
    loop {
        while let Some(c) = queue.pop_front() {
            let pose_c = poses.connectors[&c];
            for &i in adjacency.get(c.as_str()).map(Vec::as_slice).unwrap_or_default() {
                if std::mem::replace(&mut used[i], true) {
                    continue;
                }
                let l = &links[i];
                let (other, pose) = if l.a == c { (&l.b, pose_c * l.t) } else { (&l.a, pose_c * l.t.inverse()) };
                match poses.connectors.get(other) {
                    None => {
                        poses.connectors.insert(other.clone(), pose);
                        source.insert(other.clone(), format!("{} from {c}", l.what));
                        queue.push_back(other.clone());
                    }
                    Some(first) => {
                        poses.loop_checks += 1;
                        let (dp, da) = pose_error(first, &pose);
                        if !(dp <= pos_tol && da <= angle_tol) {
                            return Err(format!(
                                "loop closure mismatch between {c} and {other} across {}: {other} was placed at {:?} \
                             by {}, but {c} puts it at {:?}; position differs by {dp:e} m, rotation by {da:e} rad",
                                l.what,
                                first.translation.vector.as_slice(),
                                source[other],
                                pose.translation.vector.as_slice(),
                            ));
                        }
                    }
                }
            }
        }
        // A component with no path to the world starts where its root body's initial conditions
        // put it: `r_0(start=...)` and `angles_start` (Cardan sequence_start, default {1,2,3}).
        let Some((name, pose)) = model
            .components
            .iter()
            .filter(|c| kinds.get(c.name.as_str()).is_some_and(|k| *k == Element::Leaf) && c.class.ends_with("Parts.Body"))
            .find_map(|c| {
                let conn = format!("{}.frame_a", c.name);
                if poses.connectors.contains_key(&conn) {
                    return None;
                }
                let r = vec3_param(c, "r_0.start", None).ok()?;
                let angles = vec3_param(c, "angles_start", Some([0.0; 3])).ok()?;
                let seq = vec3_param(c, "sequence_start", Some([1.0, 2.0, 3.0])).ok()?;
                let mut rot = UnitQuaternion::identity();
                for k in 0..3 {
                    let axis = match seq[k] as i64 {
                        1 => Vector3::x_axis(),
                        2 => Vector3::y_axis(),
                        _ => Vector3::z_axis(),
                    };
                    rot *= UnitQuaternion::from_axis_angle(&axis, angles[k]);
                }
                Some((conn, Isometry3::from_parts(r.into(), rot)))
            })
        else {
            break;
        };
        poses.connectors.insert(name.clone(), pose);
        source.insert(name.clone(), "its initial conditions r_0, angles_start".to_string());
        queue.push_back(name);
    }

    for (name, constraint) in constraints {
        let (Some(a), Some(b)) = (poses.connectors.get(&format!("{name}.frame_a")), poses.connectors.get(&format!("{name}.frame_b")))
        else {
            continue;
        };
        poses.loop_checks += 1;
        check_constraint(name, &constraint, a, b, pos_tol, angle_tol)?;
    }
    Ok(poses)
}

fn body_pose<'a>(model: &'a Model, poses: &Poses, body: &str) -> Option<(&'a Component, Isometry3<f64>)> {
    let c = model.component(body)?;
    if c.class != format!("{MB}.Parts.Body") {
        return None;
    }
    Some((c, *poses.connectors.get(&format!("{body}.frame_a"))?))
}

/// World position of a body's centre of gravity: pose(frame_a) * r_CM.
pub fn cg_world(model: &Model, poses: &Poses, body: &str) -> Option<Vector3<f64>> {
    let (c, pose) = body_pose(model, poses, body)?;
    let r = vec3_param(c, "r_CM", None).ok()?;
    Some((pose * Point3::from(r)).coords)
}

/// A body's inertia about its centre of gravity, resolved in the world: R_a I_a R_a^T, with
/// I_a = [[I_11, I_21, I_31], [I_21, I_22, I_32], [I_31, I_32, I_33]] and MSL's defaults (0.001 on
/// the diagonal, 0 off it) for absent entries.
pub fn body_inertia_world(model: &Model, poses: &Poses, body: &str) -> Option<Matrix3<f64>> {
    let (c, pose) = body_pose(model, poses, body)?;
    let get = |k: &str, d: f64| num_param(c, k, Some(d)).ok();
    let (i11, i22, i33) = (get("I_11", 0.001)?, get("I_22", 0.001)?, get("I_33", 0.001)?);
    let (i21, i31, i32) = (get("I_21", 0.0)?, get("I_31", 0.0)?, get("I_32", 0.0)?);
    let ia = Matrix3::new(i11, i21, i31, i21, i22, i32, i31, i32, i33);
    let r = pose.rotation.to_rotation_matrix().into_inner();
    Some(r * ia * r.transpose())
}

/// Builders of `Mechanics.mo` texts, shared with the structural check's tests.
#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    const PLACE: &str = "annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-25})))";

    /// Modelica's number format as the writer uses it (shortest round trip).
    fn num(x: f64) -> String {
        let x = if x == 0.0 { 0.0 } else { x };
        format!("{x:?}")
    }

    fn v3(v: [f64; 3]) -> String {
        format!("{{{}, {}, {}}}", num(v[0]), num(v[1]), num(v[2]))
    }

    pub(crate) fn world() -> String {
        format!("  inner {MB}.World world(n={{0.0, -1.0, 0.0}}, g=9.81) \"World frame: the CAD assembly's frame\"\n    {PLACE};\n")
    }

    pub(crate) fn body(name: &str, r_cm: [f64; 3], i: [f64; 6]) -> String {
        format!(
            "  {MB}.Parts.Body {name}(\n    m=1.5,\n    r_CM={},\n    I_11={}, I_22={}, I_33={},\n    I_21={}, I_31={}, I_32={},\n    animation=false)\n    \"Part {name} (nodeID 1)\" {PLACE};\n",
            v3(r_cm),
            num(i[0]),
            num(i[1]),
            num(i[2]),
            num(i[3]),
            num(i[4]),
            num(i[5])
        )
    }

    pub(crate) fn translation(name: &str, r: [f64; 3]) -> String {
        format!("  {MB}.Parts.FixedTranslation {name}(r={}, animation=false)\n    \"Frame of {name}\" {PLACE};\n", v3(r))
    }

    pub(crate) fn rotation(name: &str, r: [f64; 3], nx: [f64; 3], ny: [f64; 3]) -> String {
        format!(
            "  {MB}.Parts.FixedRotation {name}(\n    r={},\n    rotationType={MB}.Types.RotationTypes.TwoAxesVectors,\n    n_x={},\n    n_y={},\n    animation=false)\n    \"Frame of {name}\" {PLACE};\n",
            v3(r),
            v3(nx),
            v3(ny)
        )
    }

    pub(crate) fn revolute(name: &str, n: [f64; 3], q: f64, fixed: bool) -> String {
        let f = if fixed { ", fixed=true" } else { "" };
        format!(
            "  Demo.Components.Revolute {name}(\n    n={},\n    phi(start={}{f}),\n    w(start=0{f}))\n    \"Joint {name} (nodeID 9)\" {PLACE};\n",
            v3(n),
            num(q)
        )
    }

    pub(crate) fn prismatic(name: &str, n: [f64; 3], q: f64) -> String {
        format!(
            "  Demo.Components.Prismatic {name}(\n    n={},\n    s(start={}, fixed=true),\n    v(start=0, fixed=true))\n    \"Joint {name} (nodeID 9)\" {PLACE};\n",
            v3(n),
            num(q)
        )
    }

    pub(crate) fn spherical(name: &str, states: bool) -> String {
        let s = if states {
            "(\n    enforceStates=true,\n    useQuaternions=true,\n    angles_fixed=true,\n    w_rel_a_fixed=true)"
        } else {
            ""
        };
        format!("  {MB}.Joints.Spherical {name}{s}\n    \"Joint {name} (nodeID 9)\" {PLACE};\n")
    }

    pub(crate) fn planar_constraint(name: &str, n: [f64; 3]) -> String {
        format!(
            "  {MB}.Joints.RevolutePlanarLoopConstraint {name}(n={})\n    \"Joint {name} (nodeID 9): closes a planar loop\" {PLACE};\n",
            v3(n)
        )
    }

    fn shape(name: &str, body: &str) -> String {
        format!(
            "  {MB}.Visualizers.FixedShape {name}(\n    shapeType=\"modelica://Demo/Resources/Shapes/{body}.dxf\",\n    length=1, width=1, height=1,\n    extra=0,\n    color={{178, 178, 178}})\n    \"Shape of {body}\" {PLACE};\n"
        )
    }

    pub(crate) fn mechanics(decls: &[String], connects: &[(&str, &str)]) -> String {
        let eqs: String = connects.iter().map(|(a, b)| format!("  connect({a}, {b});\n")).collect();
        format!(
            "within Demo;\nmodel Mechanics \"Mechanical model of demo (n bodies, n joints)\"\n{}\nequation\n{eqs}  annotation (\n    experiment(StopTime=1),\n    Documentation(info=\"<html>\n<p>Converted.</p>\n</html>\"));\nend Mechanics;\n",
            decls.concat().trim_end()
        )
    }

    fn fk(text: &str) -> Result<(Model, Poses), String> {
        let model = parse_mechanics(text)?;
        let poses = forward_kinematics(&model)?;
        Ok((model, poses))
    }

    pub(crate) fn fk_ok(text: &str) -> (Model, Poses) {
        match fk(text) {
            Ok(r) => r,
            Err(e) => panic!("forward kinematics failed: {e}\n{text}"),
        }
    }

    fn fk_err(text: &str) -> String {
        match fk(text) {
            Ok((_, p)) => panic!("expected an error, got {:?}", p.connectors.keys().collect::<Vec<_>>()),
            Err(e) => e,
        }
    }

    fn rz(a: f64) -> Matrix3<f64> {
        let (s, c) = a.sin_cos();
        Matrix3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0)
    }

    /// The number printed right after `prefix` in `text`.
    #[track_caller]
    fn number_after(text: &str, prefix: &str) -> f64 {
        let start = text.find(prefix).unwrap_or_else(|| panic!("no `{prefix}` in {text}")) + prefix.len();
        let rest = &text[start..];
        let end = rest.find(' ').unwrap_or(rest.len());
        rest[..end].parse().unwrap_or_else(|e| panic!("`{}` after `{prefix}`: {e}", &rest[..end]))
    }

    #[track_caller]
    fn assert_pose(poses: &Poses, connector: &str, p: [f64; 3], r: Matrix3<f64>) {
        let got = poses.get(connector).unwrap_or_else(|| panic!("{connector} not reached"));
        let dp = (got.translation.vector - Vector3::from(p)).norm();
        let dr = (got.rotation.to_rotation_matrix().into_inner() - r).norm();
        assert!(dp < 1e-12 && dr < 1e-12, "{connector}: got {got}, expected {p:?} / {r}; dp {dp:e}, dr {dr:e}");
    }

    #[test]
    fn serial_chain_of_every_element() {
        let (s5, c5) = 0.5f64.sin_cos();
        let text = mechanics(
            &[
                world(),
                translation("RootGround", [1.0, 0.0, 0.0]),
                body("base", [0.1, 0.0, 0.0], [0.01, 0.02, 0.03, 0.0, 0.0, 0.0]),
                // +90 degrees about z: x -> y, y -> -x
                rotation("base_CS2", [0.0, 0.5, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]),
                revolute("J1", [0.0, 0.0, 1.0], 0.5, true),
                body("arm", [0.2, 0.0, 0.0], [0.01, 0.02, 0.03, 0.001, 0.0, 0.0]),
                translation("arm_CS2", [0.4, 0.0, 0.0]),
                // a non-unit axis: unit(n) = y
                prismatic("J2", [0.0, 2.0, 0.0], 0.25),
                body("slider", [0.0, 0.0, -1e-7], [1e-7, 1e-7, 1e-7, 0.0, 0.0, 0.0]),
                spherical("J3", true),
                translation("J3_offset", [0.0, 0.0, 0.1]),
                body("ball", [0.0, 0.0, 0.0], [0.001, 0.001, 0.001, 0.0, 0.0, 0.0]),
                spherical("J4", false),
                body("ball2", [0.0, 0.0, 0.0], [0.001, 0.001, 0.001, 0.0, 0.0, 0.0]),
                shape("arm_shape", "arm"),
            ],
            &[
                ("world.frame_b", "RootGround.frame_a"),
                ("RootGround.frame_b", "base.frame_a"),
                ("base.frame_a", "base_CS2.frame_a"),
                ("arm.frame_a", "arm_CS2.frame_a"),
                ("base_CS2.frame_b", "J1.frame_a"),
                ("J1.frame_b", "arm.frame_a"),
                ("arm_CS2.frame_b", "J2.frame_a"),
                ("J2.frame_b", "slider.frame_a"),
                ("slider.frame_a", "J3.frame_a"),
                ("J3.frame_b", "J3_offset.frame_a"),
                ("J3_offset.frame_b", "ball.frame_a"),
                ("ball.frame_a", "J4.frame_a"),
                ("J4.frame_b", "ball2.frame_a"),
                ("arm.frame_a", "arm_shape.frame_a"),
            ],
        );
        let (model, poses) = fk_ok(&text);
        let id = Matrix3::identity();
        assert_pose(&poses, "world.frame_b", [0.0; 3], id);
        assert_pose(&poses, "RootGround.frame_a", [0.0; 3], id);
        assert_pose(&poses, "RootGround.frame_b", [1.0, 0.0, 0.0], id);
        assert_pose(&poses, "base.frame_a", [1.0, 0.0, 0.0], id);
        let r90 = Matrix3::new(0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0);
        assert_pose(&poses, "base_CS2.frame_b", [1.0, 0.5, 0.0], r90);
        assert_pose(&poses, "J1.frame_a", [1.0, 0.5, 0.0], r90);
        // 90 degrees + 0.5 rad about z: x axis = (-sin 0.5, cos 0.5, 0), y axis = (-cos 0.5, -sin 0.5, 0).
        let r1 = Matrix3::new(-s5, -c5, 0.0, c5, -s5, 0.0, 0.0, 0.0, 1.0);
        assert_pose(&poses, "J1.frame_b", [1.0, 0.5, 0.0], r1);
        assert_pose(&poses, "arm.frame_a", [1.0, 0.5, 0.0], r1);
        assert_pose(&poses, "arm_shape.frame_a", [1.0, 0.5, 0.0], r1);
        let cs2 = [1.0 - 0.4 * s5, 0.5 + 0.4 * c5, 0.0];
        assert_pose(&poses, "arm_CS2.frame_b", cs2, r1);
        assert_pose(&poses, "J2.frame_a", cs2, r1);
        let slider = [cs2[0] - 0.25 * c5, cs2[1] - 0.25 * s5, 0.0];
        assert_pose(&poses, "J2.frame_b", slider, r1);
        assert_pose(&poses, "slider.frame_a", slider, r1);
        assert_pose(&poses, "J3.frame_b", slider, r1);
        let ball = [slider[0], slider[1], 0.1];
        assert_pose(&poses, "ball.frame_a", ball, r1);
        assert_pose(&poses, "J4.frame_b", ball, r1);
        assert_pose(&poses, "ball2.frame_a", ball, r1);
        assert_eq!(poses.connectors.len(), 23);
        assert_eq!(poses.loop_checks, 0);

        let cg = cg_world(&model, &poses, "arm").expect("arm cg");
        assert!((cg - Vector3::new(1.0 - 0.2 * s5, 0.5 + 0.2 * c5, 0.0)).norm() < 1e-12, "{cg}");
        let cg = cg_world(&model, &poses, "base").expect("base cg");
        assert!((cg - Vector3::new(1.1, 0.0, 0.0)).norm() < 1e-12, "{cg}");
        assert_eq!(cg_world(&model, &poses, "J1"), None, "not a body");
        assert_eq!(cg_world(&model, &poses, "nobody"), None);

        // R I R^T for R = Rz(theta), theta = pi/2 + 0.5.
        let inertia = body_inertia_world(&model, &poses, "arm").expect("arm inertia");
        let (s, c) = (FRAC_PI_2 + 0.5).sin_cos();
        let (i11, i22, i33, i21) = (0.01, 0.02, 0.03, 0.001);
        let expect = Matrix3::new(
            c * c * i11 - 2.0 * c * s * i21 + s * s * i22,
            c * s * (i11 - i22) + (c * c - s * s) * i21,
            0.0,
            c * s * (i11 - i22) + (c * c - s * s) * i21,
            s * s * i11 + 2.0 * c * s * i21 + c * c * i22,
            0.0,
            0.0,
            0.0,
            i33,
        );
        assert!((inertia - expect).norm() < 1e-15, "{inertia} vs {expect}");
        let base = body_inertia_world(&model, &poses, "base").expect("base inertia");
        assert!((base - Matrix3::from_diagonal(&Vector3::new(0.01, 0.02, 0.03))).norm() < 1e-15);
    }

    #[test]
    fn components_reached_from_frame_b_are_inverted() {
        // world -> J.frame_b: J.frame_a = Rz(-0.5); then a FixedRotation and a Prismatic backwards.
        let text = mechanics(
            &[
                world(),
                revolute("J", [0.0, 0.0, 3.0], 0.5, true),
                rotation("F", [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]),
                prismatic("P", [0.0, 0.0, -1.0], 2.0),
                body("b", [0.0, 0.0, 0.0], [0.001, 0.001, 0.001, 0.0, 0.0, 0.0]),
            ],
            &[("world.frame_b", "J.frame_b"), ("J.frame_a", "F.frame_b"), ("F.frame_a", "P.frame_b"), ("P.frame_a", "b.frame_a")],
        );
        let (_, poses) = fk_ok(&text);
        assert_pose(&poses, "J.frame_a", [0.0; 3], rz(-0.5));
        // F.frame_b = F.frame_a * (t=(1,0,0), Rz(90)) => F.frame_a = F.frame_b * (Rz(-90), -Rz(-90) t)
        let ra = rz(-0.5) * rz(-FRAC_PI_2);
        let pa = -(ra * Vector3::new(1.0, 0.0, 0.0));
        assert_pose(&poses, "F.frame_a", pa.into(), ra);
        // P.frame_b = P.frame_a + R (0,0,-2) => P.frame_a = P.frame_b + (0, 0, 2) (R keeps z).
        assert_pose(&poses, "P.frame_a", [pa.x, pa.y, 2.0], ra);
        assert_pose(&poses, "b.frame_a", [pa.x, pa.y, 2.0], ra);
        assert_eq!(poses.loop_checks, 0);
    }

    #[test]
    fn fixed_rotation_follows_from_nxy() {
        // n_x, n_y neither unit nor orthogonal: e_x = unit(n_x), e_z = unit(n_x x n_y), e_y = e_z x e_x.
        let text =
            mechanics(&[world(), rotation("F", [0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [1.0, 1.0, 0.0])], &[("world.frame_b", "F.frame_a")]);
        let (_, poses) = fk_ok(&text);
        assert_pose(&poses, "F.frame_b", [0.0; 3], Matrix3::identity());

        // 120 degrees about (1,1,1)/sqrt 3: x -> y, y -> z, z -> x.
        let text =
            mechanics(&[world(), rotation("F", [0.5, -2.5e-5, 1e-7], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0])], &[("world.frame_b", "F.frame_a")]);
        let (_, poses) = fk_ok(&text);
        let perm = Matrix3::new(0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0);
        assert_pose(&poses, "F.frame_b", [0.5, -2.5e-5, 1e-7], perm);
    }

    /// A four-bar: ground pivots A = 0 and B = (d, 0, 0); crank a at theta2, coupler b, rocker c.
    /// Each link's frame_a is at its base pivot with x along the link; the loop closes at D
    /// between rocker_CS2.frame_b and coupler_CS2.frame_b.
    pub(crate) fn four_bar(j3_error: f64, closing_axis: [f64; 3], with_j3: bool) -> String {
        let (a, b, c, d) = (0.3, 0.9, 0.7, 1.0);
        let t2: f64 = 0.8;
        let cx = a * t2.cos();
        let cy = a * t2.sin();
        // D: intersection of |D - C| = b and |D - B| = c (upper branch).
        let (ex, ey) = (d - cx, -cy);
        let l = ex.hypot(ey);
        let along = (b * b - c * c + l * l) / (2.0 * l);
        let h = (b * b - along * along).sqrt();
        let (dx, dy) = (cx + (along * ex + h * ey) / l, cy + (along * ey - h * ex) / l);
        let (dx, dy) = if dy >= 0.0 { (dx, dy) } else { (cx + (along * ex - h * ey) / l, cy + (along * ey + h * ex) / l) };
        let t3 = (dy - cy).atan2(dx - cx);
        let t4 = dy.atan2(dx - d);
        let mut decls = vec![
            world(),
            body("ground", [0.5, 0.0, 0.0], [0.01, 0.01, 0.01, 0.0, 0.0, 0.0]),
            body("crank", [0.15, 0.0, 0.0], [0.001, 0.002, 0.002, 0.0, 0.0, 0.0]),
            body("coupler", [0.45, 0.0, 0.0], [0.001, 0.003, 0.003, 0.0, 0.0, 0.0]),
            body("rocker", [0.35, 0.0, 0.0], [0.001, 0.003, 0.003, 0.0, 0.0, 0.0]),
            translation("ground_CS2", [d, 0.0, 0.0]),
            translation("crank_CS2", [a, 0.0, 0.0]),
            translation("coupler_CS2", [b, 0.0, 0.0]),
            translation("rocker_CS2", [c, 0.0, 0.0]),
            revolute("J1", [0.0, 0.0, 1.0], t2, false),
            revolute("J2", [0.0, 0.0, 1.0], t3 - t2, false),
            planar_constraint("J4", closing_axis),
        ];
        let mut connects = vec![
            ("world.frame_b", "ground.frame_a"),
            ("ground.frame_a", "ground_CS2.frame_a"),
            ("crank.frame_a", "crank_CS2.frame_a"),
            ("coupler.frame_a", "coupler_CS2.frame_a"),
            ("rocker.frame_a", "rocker_CS2.frame_a"),
            ("ground.frame_a", "J1.frame_a"),
            ("J1.frame_b", "crank.frame_a"),
            ("crank_CS2.frame_b", "J2.frame_a"),
            ("J2.frame_b", "coupler.frame_a"),
        ];
        if with_j3 {
            decls.push(revolute("J3", [0.0, 0.0, 1.0], t4 + j3_error, false));
            connects.push(("ground_CS2.frame_b", "J3.frame_a"));
            connects.push(("J3.frame_b", "rocker.frame_a"));
        }
        connects.push(("rocker_CS2.frame_b", "J4.frame_a"));
        connects.push(("J4.frame_b", "coupler_CS2.frame_b"));
        mechanics(&decls, &connects)
    }

    #[test]
    fn four_bar_closed_by_planar_loop_constraint() {
        let (model, poses) = fk_ok(&four_bar(0.0, [0.0, 0.0, 1.0], true));
        assert_eq!(poses.loop_checks, 1, "only the constraint closes the loop");
        let d_a = poses.get("J4.frame_a").expect("J4.frame_a");
        let d_b = poses.get("J4.frame_b").expect("J4.frame_b");
        assert!((d_a.translation.vector - d_b.translation.vector).norm() < 1e-12);
        // |D - B| = c and |D - C| = b.
        let d = d_a.translation.vector;
        assert!(((d - Vector3::new(1.0, 0.0, 0.0)).norm() - 0.7).abs() < 1e-12);
        let c = poses.get("crank_CS2.frame_b").expect("C").translation.vector;
        assert!((c - Vector3::new(0.3 * 0.8f64.cos(), 0.3 * 0.8f64.sin(), 0.0)).norm() < 1e-15);
        assert!(((d - c).norm() - 0.9).abs() < 1e-12);
        // Frames of the two sides differ by a rotation about z.
        assert!(rotation_angle(&d_a.rotation, &d_b.rotation) > 0.1);
        let cg = cg_world(&model, &poses, "coupler").expect("coupler cg");
        assert!((cg - (c + (d - c) * 0.5)).norm() < 1e-12, "{cg}");
    }

    #[test]
    fn inconsistent_planar_loop_is_reported() {
        let e = fk_err(&four_bar(1e-3, [0.0, 0.0, 1.0], true));
        assert!(e.contains("J4") && e.contains("J4.frame_a") && e.contains("J4.frame_b"), "{e}");
        let dp = number_after(&e, "origins differ by ");
        assert!((dp - 7e-4).abs() < 1e-6, "{e}");

        // Right positions, wrong axis: R_a^T R_b is a rotation about z, which moves x.
        let e = fk_err(&four_bar(0.0, [1.0, 0.0, 0.0], true));
        assert!(e.contains("J4") && e.contains("moves the axis [1.0, 0.0, 0.0]"), "{e}");
    }

    #[test]
    fn walker_does_not_cross_a_loop_constraint() {
        // Without J3 the rocker hangs only on the constraint: it stays unreached, nothing checked.
        let (_, poses) = fk_ok(&four_bar(0.0, [0.0, 0.0, 1.0], false));
        assert!(poses.get("J4.frame_b").is_some(), "the coupler side is reached");
        assert!(poses.get("J4.frame_a").is_none(), "not propagated through the constraint");
        assert!(poses.get("rocker.frame_a").is_none());
        assert!(poses.get("rocker_CS2.frame_b").is_none());
        assert_eq!(poses.loop_checks, 0);
    }

    /// A `Joints.Constraints.KIND` element with the modifiers `mods` (written as in Modelica).
    pub(crate) fn cut_constraint(name: &str, kind: &str, mods: &str) -> String {
        let mods = if mods.is_empty() { String::new() } else { format!("({mods})") };
        format!("  {MB}.Joints.Constraints.{kind} {name}{mods}\n    \"Joint {name} (nodeID 9): closes a loop\" {PLACE};\n")
    }

    /// The world reaches the cut's frame_a through FixedRotation `A` (r_a; x axis along nx_a,
    /// y in the plane of ny_a) and its frame_b through FixedRotation `B` (r_b, nx_b, ny_b).
    fn cut_between(cut: String, a: ([f64; 3], [f64; 3], [f64; 3]), b: ([f64; 3], [f64; 3], [f64; 3])) -> String {
        mechanics(
            &[world(), rotation("A", a.0, a.1, a.2), rotation("B", b.0, b.1, b.2), cut],
            &[("world.frame_b", "A.frame_a"), ("world.frame_b", "B.frame_a"), ("A.frame_b", "C.frame_a"), ("B.frame_b", "C.frame_b")],
        )
    }

    const X: [f64; 3] = [1.0, 0.0, 0.0];
    const Y: [f64; 3] = [0.0, 1.0, 0.0];
    const Z: [f64; 3] = [0.0, 0.0, 1.0];

    #[test]
    fn cut_spherical_checks_locked_translations_in_frame_a() {
        // Same origin, any rotation: all locked translations hold, no rotational equation.
        let text = cut_between(cut_constraint("C", "Spherical", ""), ([1.0, 2.0, 3.0], X, Y), ([1.0, 2.0, 3.0], Y, Z));
        let (_, poses) = fk_ok(&text);
        assert_eq!(poses.loop_checks, 1);
        assert!(poses.get("C.frame_b").is_some());

        // frame_a turned +90 degrees about z: world y is frame_a's x. An offset of 1e-6 m along
        // world y violates the x equation, unless x is unlocked.
        let a = ([1.0, 0.0, 0.0], Y, [-1.0, 0.0, 0.0]);
        let b = ([1.0, 1e-6, 0.0], X, Y);
        let e = fk_err(&cut_between(cut_constraint("C", "Spherical", ""), a, b));
        assert!(e.contains("Constraints.Spherical C violated") && e.contains("locked x axis"), "{e}");
        assert!((number_after(&e, "frame_b's origin is ") - 1e-6).abs() < 1e-15, "{e}");
        let e = fk_err(&cut_between(cut_constraint("C", "Spherical", "y_locked=false"), a, b));
        assert!(e.contains("locked x axis"), "{e}");
        assert!(fk(&cut_between(cut_constraint("C", "Spherical", "x_locked=false"), a, b)).is_ok());
        // Within tolerance.
        assert!(fk(&cut_between(cut_constraint("C", "Spherical", ""), a, ([1.0, 5e-10, 0.0], X, Y))).is_ok());
    }

    #[test]
    fn cut_revolute_allows_rotation_about_n_only() {
        let (s, c) = 0.4f64.sin_cos();
        let about_z = ([0.5, 0.0, 0.0], [c, s, 0.0], [-s, c, 0.0]);
        let about_x = ([0.5, 0.0, 0.0], X, [0.0, c, s]);
        let origin = ([0.5, 0.0, 0.0], X, Y);
        assert!(fk(&cut_between(cut_constraint("C", "Revolute", "n={0.0, 0.0, 2.0}"), origin, about_z)).is_ok());
        let e = fk_err(&cut_between(cut_constraint("C", "Revolute", "n={0.0, 0.0, 2.0}"), origin, about_x));
        assert!(e.contains("Constraints.Revolute C violated") && e.contains("moves the axis [0.0, 0.0, 1.0]"), "{e}");
        assert!((number_after(&e, "by ") - 2.0 * (0.2f64).sin()).abs() < 1e-12, "{e}");
        // The default axis is z.
        assert!(fk(&cut_between(cut_constraint("C", "Revolute", ""), origin, about_z)).is_ok());
        // Translations: z unlocked allows an offset along z only.
        let up = ([0.5, 0.0, 0.25], [c, s, 0.0], [-s, c, 0.0]);
        assert!(fk(&cut_between(cut_constraint("C", "Revolute", "z_locked=false"), origin, up)).is_ok());
        let e = fk_err(&cut_between(cut_constraint("C", "Revolute", ""), origin, up));
        assert!(e.contains("locked z axis"), "{e}");
    }

    #[test]
    fn cut_prismatic_and_universal_rotations() {
        let origin = ([0.0, 0.0, 1.0], X, Y);
        let shifted = ([0.3, 0.0, 1.0], X, Y);
        let (s, c) = 0.3f64.sin_cos();
        let about_z = ([0.0, 0.0, 1.0], [c, s, 0.0], [-s, c, 0.0]);
        let about_x = ([0.0, 0.0, 1.0], X, [0.0, c, s]);

        assert!(fk(&cut_between(cut_constraint("C", "Prismatic", "x_locked=false"), origin, shifted)).is_ok());
        let e = fk_err(&cut_between(cut_constraint("C", "Prismatic", "x_locked=false"), origin, about_z));
        assert!(e.contains("Constraints.Prismatic C violated") && e.contains("rotated by"), "{e}");
        assert!((number_after(&e, "rotated by ") - 0.3).abs() < 1e-12, "{e}");

        // n_a = x (frame_a), n_b = y (frame_b): a rotation about x keeps them perpendicular, one
        // about z tilts n_b towards -x by sin 0.3.
        let uni = || cut_constraint("C", "Universal", "n_a={2.0, 0.0, 0.0}, n_b={0.0, 1.0, 0.0}");
        let (_, poses) = fk_ok(&cut_between(uni(), origin, about_x));
        assert_eq!(poses.loop_checks, 1);
        let e = fk_err(&cut_between(uni(), origin, about_z));
        assert!(e.contains("Constraints.Universal C violated") && e.contains("n_a [1.0, 0.0, 0.0]"), "{e}");
        assert!((number_after(&e, "= ") + s).abs() < 1e-12, "{e}");
        let e = fk_err(&cut_between(uni(), origin, ([0.0, 1e-3, 1.0], X, Y)));
        assert!(e.contains("locked y axis"), "{e}");
    }

    #[test]
    fn cut_errors_and_classification() {
        let e = fk_err(&cut_between(cut_constraint("C", "Spherical", "x_locked=1"), ([0.0; 3], X, Y), ([0.0; 3], X, Y)));
        assert!(e.contains("`x_locked` = 1.0 is not a Boolean"), "{e}");
        let e = fk_err(&cut_between(cut_constraint("C", "Universal", "n_b={0.0, 0.0, 0.0}"), ([0.0; 3], X, Y), ([0.0; 3], X, Y)));
        assert!(e.contains("axis n_b is the zero vector"), "{e}");
        let e = fk_err(&cut_between(cut_constraint("C", "Gearbox", ""), ([0.0; 3], X, Y), ([0.0; 3], X, Y)));
        assert!(e.contains("unknown class"), "{e}");

        let model = parse_mechanics(&cut_between(
            cut_constraint("C", "Revolute", "x_locked=false, n={0.0, 3.0, 0.0}"),
            ([0.0; 3], X, Y),
            ([0.0; 3], X, Y),
        ))
        .expect("parse");
        let c = model.component("C").expect("C");
        let Element::Constraint(Constraint::Cut(cut)) = element(&model, c).expect("element") else { panic!("not a cut") };
        assert_eq!(cut.kind, "Revolute");
        assert_eq!(cut.locked, [false, true, true]);
        assert_eq!(cut.rotation, CutRotation::About(Vector3::new(0.0, 1.0, 0.0)));
        assert_eq!(cut.equations(), 4);
        // Not walked through: without B the cut's frame_b is never reached.
        let text = mechanics(
            &[world(), rotation("A", [0.0; 3], X, Y), cut_constraint("C", "Prismatic", "")],
            &[("world.frame_b", "A.frame_a"), ("A.frame_b", "C.frame_a")],
        );
        let (_, poses) = fk_ok(&text);
        assert!(poses.get("C.frame_b").is_none());
        assert_eq!(poses.loop_checks, 0);
    }

    fn two_paths(r2: [f64; 3], nx: [f64; 3]) -> String {
        mechanics(
            &[
                world(),
                translation("A", [1.0, 0.0, 0.0]),
                rotation("B", r2, nx, [0.0, 1.0, 0.0]),
                body("b", [0.0; 3], [0.001, 0.001, 0.001, 0.0, 0.0, 0.0]),
            ],
            &[("world.frame_b", "A.frame_a"), ("world.frame_b", "B.frame_a"), ("A.frame_b", "b.frame_a"), ("B.frame_b", "b.frame_a")],
        )
    }

    #[test]
    fn loop_through_plain_connects() {
        let (_, poses) = fk_ok(&two_paths([1.0, 0.0, 0.0], [1.0, 0.0, 0.0]));
        assert_eq!(poses.loop_checks, 1);
        assert_pose(&poses, "b.frame_a", [1.0, 0.0, 0.0], Matrix3::identity());

        let e = fk_err(&two_paths([1.0, 1e-6, 0.0], [1.0, 0.0, 0.0]));
        assert!(e.contains("loop closure mismatch"), "{e}");
        assert!(e.contains("b.frame_a") && (e.contains("A.frame_b") || e.contains("B.frame_b")), "{e}");
        assert!((number_after(&e, "position differs by ") - 1e-6).abs() < 1e-12, "{e}");
        assert!(number_after(&e, "rotation by ") < 1e-15, "{e}");

        // Rotation only: n_x tilted by 1e-8 rad about z. An acos-based angle would miss it.
        let e = fk_err(&two_paths([1.0, 0.0, 0.0], [1.0, 1e-8, 0.0]));
        assert!((number_after(&e, "rotation by ") - 1e-8).abs() < 1e-14, "{e}");
        assert!(number_after(&e, "position differs by ") < 1e-15, "{e}");
        assert!(fk(&two_paths([1.0, 0.0, 0.0], [1.0, 5e-10, 0.0])).is_ok());
    }

    #[test]
    fn duplicate_connect_counts_as_a_closed_loop() {
        let text = mechanics(
            &[world(), body("b", [0.0; 3], [0.001, 0.001, 0.001, 0.0, 0.0, 0.0])],
            &[("world.frame_b", "b.frame_a"), ("b.frame_a", "world.frame_b")],
        );
        let (_, poses) = fk_ok(&text);
        assert_eq!(poses.loop_checks, 1);
        assert_eq!(poses.connectors.len(), 2);
    }

    #[test]
    fn free_bodies_are_absent() {
        let text = mechanics(
            &[
                world(),
                body("fixed", [0.0; 3], [0.001, 0.001, 0.001, 0.0, 0.0, 0.0]),
                body("free", [0.1, 0.0, 0.0], [0.001, 0.001, 0.001, 0.0, 0.0, 0.0]),
                translation("free_CS2", [0.0, 1.0, 0.0]),
            ],
            &[("world.frame_b", "fixed.frame_a"), ("free.frame_a", "free_CS2.frame_a")],
        );
        let (model, poses) = fk_ok(&text);
        assert_eq!(poses.connectors.keys().collect::<Vec<_>>(), ["fixed.frame_a", "world.frame_b"]);
        assert_eq!(cg_world(&model, &poses, "free"), None);
        assert_eq!(body_inertia_world(&model, &poses, "free"), None);
    }

    #[test]
    fn model_errors() {
        let base = |extra: String, connects: &[(&str, &str)]| mechanics(&[world(), extra], connects);

        let e = fk_err(&base(format!("  Modelica.Mechanics.MultiBody.Joints.Revolute r(n={{0.0, 0.0, 1.0}}) {PLACE};\n"), &[]));
        assert!(e.contains("unknown class `Modelica.Mechanics.MultiBody.Joints.Revolute`") && e.contains("`r`"), "{e}");

        let e = fk_err(&base(body("b", [0.0; 3], [0.001; 6]), &[("world.frame_b", "c.frame_a")]));
        assert!(e.contains("no component `c`"), "{e}");

        let e = fk_err(&base(body("b", [0.0; 3], [0.001; 6]), &[("world.frame_b", "b.frame_b")]));
        assert!(e.contains("`b` has no frame connector `frame_b`"), "{e}");

        let e = fk_err(&base(revolute("r", [0.0, 0.0, 0.0], 1.0, true), &[]));
        assert!(e.contains("zero vector"), "{e}");

        let e = fk_err(&base(format!("  {MB}.Parts.FixedTranslation t(animation=false) {PLACE};\n"), &[]));
        assert!(e.contains("missing parameter `r`"), "{e}");

        let e = fk_err(&base(format!("  {MB}.Parts.FixedTranslation t(r={{1.0, 2.0}}) {PLACE};\n"), &[]));
        assert!(e.contains("not a finite 3-vector"), "{e}");

        let e = fk_err(&base(
            format!("  {MB}.Parts.FixedRotation t(rotationType={MB}.Types.RotationTypes.PlanarRotationSequence) {PLACE};\n"),
            &[],
        ));
        assert!(e.contains("PlanarRotationSequence is not supported"), "{e}");

        let e = fk_err(&mechanics(&[body("b", [0.0; 3], [0.001; 6])], &[]));
        assert!(e.contains("no World"), "{e}");
    }

    #[test]
    fn precise_rotation_angle() {
        let a = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 0.3);
        let b = a * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 2e-9);
        assert!((rotation_angle(&a, &b) - 2e-9).abs() < 1e-15);
        let c = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 3.0);
        let (dp, da) = pose_error(
            &Isometry3::from_parts(Translation3::new(1.0, 0.0, 0.0), a),
            &Isometry3::from_parts(Translation3::new(1.0, 0.0, 3.0), a * c),
        );
        assert!((dp - 3.0).abs() < 1e-15 && (da - 3.0).abs() < 1e-12);
    }
}
