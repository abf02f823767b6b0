//! Scenes (issue 29): the machine's environment, no IO. A model's scene is a list of named
//! objects (primitives: box, cylinder, sphere, capsule, plane; or an uploaded mesh, see [`mesh`]), each static (fixed in the world or
//! attached to a body), moving (a prescribed motion: constant velocity, or a table of poses over
//! time) or free (a rigid object with mass). The user's [`SceneSpec`] is checked once
//! ([`check`]: every problem an [`Issue`] naming its field, e.g. `objects[2].rotation`) into a
//! [`Scene`]; collision checks take each object's convex [`SceneObject::shape`] and its pose
//! over time ([`SceneObject::pose_at`]).
//!
//! Conventions: SI units; `position` and `rotation` (a 3×3 matrix, rows, orthonormal with
//! determinant +1) place the object's frame in the world, or in its body's frame_a when it is
//! attached. Cylinders and capsules lie along their frame's z axis, centred; a plane is the
//! frame's z = 0 surface with the solid below it (a box `PLANE_SIZE` wide, `PLANE_DEPTH` deep).

use nalgebra::{Isometry3, Matrix3, Rotation3, Translation3, UnitQuaternion, Vector3};
use serde::{Deserialize, Serialize};

use crate::collision::{BodyShape, ConvexPart, ShapeKind};
pub use crate::library::Issue;

/// Most objects in one scene.
pub const MAX_OBJECTS: usize = 256;
/// Most rows of pose tables over a whole scene.
pub const MAX_POSE_ROWS: usize = 10_000;
/// Longest object name (a Modelica identifier).
pub const MAX_NAME: usize = 64;
/// Largest size or distance from the origin, metres.
pub const MAX_LENGTH: f64 = 1_000.0;
/// Smallest size, metres.
pub const MIN_LENGTH: f64 = 1e-4;
/// Largest speed of a moving object, m/s.
pub const MAX_SPEED: f64 = 100.0;
/// Largest mass of a free object, kg.
pub const MAX_MASS: f64 = 1e6;
/// How far a rotation may be from orthonormal (largest entry of RᵀR − I).
pub const ROTATION_TOLERANCE: f64 = 1e-6;
/// A plane's extent (square, metres) and the depth of the solid below it.
pub const PLANE_SIZE: f64 = 200.0;
pub const PLANE_DEPTH: f64 = 1.0;
/// Sides of the prism standing in for a cylinder.
pub const CYLINDER_SIDES: usize = 32;

fn identity() -> [[f64; 3]; 3] {
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
}

fn yes() -> bool {
    true
}

fn is_true(b: &bool) -> bool {
    *b
}

fn is_static(k: &str) -> bool {
    k == "static"
}

fn static_kind() -> String {
    "static".into()
}

/// A scene as the user gives it (`PUT .../scene`) and as it is stored.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneSpec {
    pub objects: Vec<ObjectSpec>,
}

/// One object as given. Strings and optional fields are checked by [`check`] (so a bad value
/// is an issue naming its field, not a parse error).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObjectSpec {
    pub name: String,
    pub shape: ShapeSpec,
    pub position: [f64; 3],
    #[serde(default = "identity")]
    pub rotation: [[f64; 3]; 3],
    /// `static` (default), `moving` or `free`.
    #[serde(default = "static_kind", skip_serializing_if = "is_static")]
    pub kind: String,
    /// RGB, each 0..1.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub color: Option<[f64; 3]>,
    #[serde(default = "yes", skip_serializing_if = "is_true")]
    pub visible: bool,
    /// A body's Modelica name: the object moves with it (static objects only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub attached_to: Option<String>,
    /// The prescribed motion of a moving object.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub motion: Option<MotionSpec>,
    /// Mass of a free object, kg.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass: Option<f64>,
    /// Principal moments of inertia about the centre in the object's axes (kg·m²) of a free
    /// object; default: the solid shape of uniform density.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inertia: Option<[f64; 3]>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShapeSpec {
    /// `box`, `cylinder`, `sphere`, `capsule`, `plane` or `mesh`.
    pub kind: String,
    /// Box: full edge lengths (x, y, z).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub size: Option<[f64; 3]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    /// Cylinder: full length; capsule: the length of its axis segment (without the caps).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub length: Option<f64>,
    /// Mesh: the name of a mesh uploaded for the model's scene.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mesh: Option<String>,
    /// Mesh: the unit of its file's coordinates, `m` (default), `mm`, `cm` or `in`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unit: Option<String>,
}

/// A moving object's motion: exactly one of `velocity` (m/s, world, from its position at t = 0)
/// or `poses` (linear in position, slerp in rotation between rows; held before the first row
/// and after the last).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MotionSpec {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub velocity: Option<[f64; 3]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub poses: Option<Vec<PoseRow>>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PoseRow {
    pub time: f64,
    pub position: [f64; 3],
    #[serde(default = "identity")]
    pub rotation: [[f64; 3]; 3],
}

/// A checked primitive, in its own frame.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    Box {
        size: [f64; 3],
    },
    Cylinder {
        radius: f64,
        length: f64,
    },
    Sphere {
        radius: f64,
    },
    Capsule {
        radius: f64,
        length: f64,
    },
    Plane,
    /// An uploaded mesh, `scale` m per file unit; collisions take its convex hull (`hull`, in
    /// metres in the object's frame).
    Mesh {
        mesh: String,
        scale: f64,
        hull: ConvexPart,
    },
}

/// A checked object's kind.
#[derive(Clone, Debug, PartialEq)]
pub enum Kind {
    Static,
    Moving(Motion),
    Free { mass: f64, inertia: [f64; 3] },
}

#[derive(Clone, Debug, PartialEq)]
pub enum Motion {
    Velocity(Vector3<f64>),
    /// (time, pose), times strictly increasing, at least two rows.
    Poses(Vec<(f64, Isometry3<f64>)>),
}

#[derive(Clone, Debug, PartialEq)]
pub struct SceneObject {
    pub name: String,
    pub shape: Shape,
    /// In the world, or in the body's frame_a when `attached_to` names one.
    pub pose: Isometry3<f64>,
    pub kind: Kind,
    pub color: [f64; 3],
    pub visible: bool,
    pub attached_to: Option<String>,
}

#[derive(Clone, Debug, Default, PartialEq)]
pub struct Scene {
    pub objects: Vec<SceneObject>,
}

/// Default colour (a light grey).
pub const DEFAULT_COLOR: [f64; 3] = [0.7, 0.7, 0.7];

fn finite(v: &[f64]) -> bool {
    v.iter().all(|x| x.is_finite())
}

/// A rotation from its rows, if orthonormal with determinant +1 within [`ROTATION_TOLERANCE`].
pub fn rotation(rows: &[[f64; 3]; 3]) -> Result<UnitQuaternion<f64>, String> {
    if !rows.iter().all(|r| finite(r)) {
        return Err("must hold finite numbers".into());
    }
    let m = Matrix3::from_fn(|i, j| rows[i][j]);
    let err = (m.transpose() * m - Matrix3::identity()).abs().max();
    // Written so that a NaN (huge entries overflowing) is refused too.
    if err.is_nan() || err > ROTATION_TOLERANCE {
        return Err(format!("is not orthonormal (RᵀR differs from the identity by {err:.3e}, more than {ROTATION_TOLERANCE:e})"));
    }
    if m.determinant() < 0.0 {
        return Err("is a reflection (determinant −1), not a rotation".into());
    }
    Ok(UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(m)))
}

fn position(p: &[f64; 3]) -> Result<Vector3<f64>, String> {
    let v = Vector3::from(*p);
    if !finite(p) || v.norm() > MAX_LENGTH {
        return Err(format!("must be finite and within {MAX_LENGTH} m of the origin"));
    }
    Ok(v)
}

fn length(x: Option<f64>, what: &str) -> Result<f64, String> {
    match x {
        None => Err(format!("{what} is required for this shape")),
        Some(x) if x.is_finite() && (MIN_LENGTH..=MAX_LENGTH).contains(&x) => Ok(x),
        Some(x) => Err(format!("{what} {x} m is outside {MIN_LENGTH} m .. {MAX_LENGTH} m")),
    }
}

/// Whether `name` can name a scene object (and so a Modelica component and an MJCF body).
pub fn valid_name(name: &str) -> bool {
    let mut c = name.chars();
    matches!(c.next(), Some(f) if f.is_ascii_alphabetic()) && c.all(|x| x.is_ascii_alphanumeric() || x == '_') && name.len() <= MAX_NAME
}

fn shape_of(s: &ShapeSpec, field: &str, meshes: &Meshes, issues: &mut Vec<Issue>) -> Option<Shape> {
    let mut bad = |f: &str, m: String| issues.push(Issue::new(format!("{field}.{f}"), m));
    let allowed: &[&str] = match s.kind.as_str() {
        "box" => &["size"],
        "cylinder" | "capsule" => &["radius", "length"],
        "sphere" => &["radius"],
        "plane" => &[],
        "mesh" => &["mesh", "unit"],
        k => {
            bad(
                "kind",
                format!("unknown shape kind {:?}: box, cylinder, sphere, capsule, plane or mesh", crate::pipeline::ir::clip(k, 40)),
            );
            return None;
        }
    };
    for (f, given) in [
        ("size", s.size.is_some()),
        ("radius", s.radius.is_some()),
        ("length", s.length.is_some()),
        ("mesh", s.mesh.is_some()),
        ("unit", s.unit.is_some()),
    ] {
        if given && !allowed.contains(&f) {
            bad(f, format!("a {} has no {f}", s.kind));
        }
    }
    if s.kind == "mesh" {
        let scale = mesh::unit_scale(s.unit.as_deref().unwrap_or("m"));
        if scale.is_none() {
            let u = crate::pipeline::ir::clip(s.unit.as_deref().unwrap_or_default(), 20);
            bad("unit", format!("unknown unit {u:?}: m, mm, cm or in"));
        }
        let found = match &s.mesh {
            None => {
                bad("mesh", "a mesh object names its mesh (uploaded with PUT .../scene/meshes/{name})".into());
                None
            }
            Some(m) => match meshes.get(m) {
                Some(found) => Some(found),
                None => {
                    let known: Vec<&str> = meshes.keys().map(String::as_str).take(20).collect();
                    let m = crate::pipeline::ir::clip(m, 70);
                    bad("mesh", format!("no mesh {m} was uploaded for this scene (meshes: {})", known.join(", ")));
                    None
                }
            },
        };
        let (Some(scale), Some(found)) = (scale, found) else { return None };
        let mut hull = found.hull.clone();
        for v in &mut hull.vertices {
            *v = v.map(|x| x * scale);
        }
        let extent = hull.vertices.iter().flatten().fold(0.0f64, |a, x| a.max(x.abs()));
        if extent > MAX_LENGTH {
            bad("unit", format!("the mesh reaches {extent:.1} m from its origin in this unit, more than {MAX_LENGTH} m"));
            return None;
        }
        return Some(Shape::Mesh { mesh: s.mesh.clone().unwrap_or_default(), scale, hull });
    }
    let n = issues.len();
    let mut get =
        |f: &str, x: Option<f64>| length(x, f).map_err(|m| issues.push(Issue::new(format!("{field}.{f}"), m))).unwrap_or(f64::NAN);
    let shape = match s.kind.as_str() {
        "box" => match s.size {
            None => {
                get("size", None);
                return None;
            }
            Some([x, y, z]) => Shape::Box { size: [get("size", Some(x)), get("size", Some(y)), get("size", Some(z))] },
        },
        "cylinder" => Shape::Cylinder { radius: get("radius", s.radius), length: get("length", s.length) },
        "capsule" => Shape::Capsule { radius: get("radius", s.radius), length: get("length", s.length) },
        "sphere" => Shape::Sphere { radius: get("radius", s.radius) },
        _ => Shape::Plane,
    };
    (issues.len() == n).then_some(shape)
}

/// Checks a scene: names (Modelica identifiers, unique, none a body's or `world`), shapes,
/// poses (positions within [`MAX_LENGTH`], orthonormal rotations), kinds and their fields,
/// attachments (to a body in `bodies`, static objects only), motions and masses. Every
/// problem is returned at once.
pub fn check(spec: &SceneSpec, bodies: &[String]) -> Result<Scene, Vec<Issue>> {
    check_with(spec, bodies, &Meshes::new())
}

/// [`check`] with the scene's uploaded meshes (mesh objects name one of them).
pub fn check_with(spec: &SceneSpec, bodies: &[String], meshes: &Meshes) -> Result<Scene, Vec<Issue>> {
    let mut issues = Vec::new();
    if spec.objects.len() > MAX_OBJECTS {
        return Err(vec![Issue::new("objects", format!("{} objects is more than the limit of {MAX_OBJECTS}", spec.objects.len()))]);
    }
    let rows: usize = spec.objects.iter().filter_map(|o| o.motion.as_ref()?.poses.as_ref().map(Vec::len)).sum();
    if rows > MAX_POSE_ROWS {
        return Err(vec![Issue::new("objects", format!("{rows} pose rows is more than the limit of {MAX_POSE_ROWS} per scene"))]);
    }
    let mut seen = std::collections::BTreeSet::new();
    let mut objects = Vec::new();
    for (k, o) in spec.objects.iter().enumerate() {
        let f = |x: &str| format!("objects[{k}].{x}");
        let n = issues.len();
        let shown = crate::pipeline::ir::clip(&o.name, 70);
        if !valid_name(&o.name) {
            issues.push(Issue::new(
                f("name"),
                format!("{shown:?} is not a valid name: a letter, then letters, digits or _, at most {MAX_NAME} characters"),
            ));
        } else if !seen.insert(o.name.as_str()) {
            issues.push(Issue::new(f("name"), format!("the name {shown} is given twice")));
        } else if bodies.iter().any(|b| b == &o.name) || o.name == "world" {
            issues.push(Issue::new(f("name"), format!("the name {shown} is a body of the model: choose another")));
        }
        let shape = shape_of(&o.shape, &f("shape"), meshes, &mut issues);
        let p = position(&o.position).map_err(|m| issues.push(Issue::new(f("position"), m))).ok();
        let r = rotation(&o.rotation).map_err(|m| issues.push(Issue::new(f("rotation"), m))).ok();
        let color = o.color.unwrap_or(DEFAULT_COLOR);
        if !color.iter().all(|c| (0.0..=1.0).contains(c)) {
            issues.push(Issue::new(f("color"), "each of red, green and blue must be within 0 .. 1"));
        }
        if let Some(b) = &o.attached_to {
            if o.kind != "static" {
                issues.push(Issue::new(f("attached_to"), "only static objects can be attached to a body"));
            } else if !bodies.contains(b) {
                let known: Vec<&str> = bodies.iter().map(String::as_str).take(20).collect();
                let b = crate::pipeline::ir::clip(b, 70);
                issues.push(Issue::new(f("attached_to"), format!("{b} is not a body of the model (bodies: {})", known.join(", "))));
            }
        }
        let is_plane = o.shape.kind == "plane";
        if o.kind != "moving" && o.motion.is_some() {
            issues.push(Issue::new(f("motion"), "only moving objects have a motion"));
        }
        if o.kind != "free" {
            if o.mass.is_some() {
                issues.push(Issue::new(f("mass"), "only free objects have a mass"));
            }
            if o.inertia.is_some() {
                issues.push(Issue::new(f("inertia"), "only free objects have an inertia"));
            }
        }
        let kind = match o.kind.as_str() {
            "static" => Some(Kind::Static),
            "moving" if is_plane => {
                issues.push(Issue::new(f("kind"), "a plane is static"));
                None
            }
            "moving" => motion(o.motion.as_ref(), &f("motion"), &mut issues).map(Kind::Moving),
            "free" if is_plane => {
                issues.push(Issue::new(f("kind"), "a plane is static"));
                None
            }
            "free" => match o.mass {
                Some(m) if m.is_finite() && m > 0.0 && m <= MAX_MASS => {
                    let inertia = match (o.inertia, &shape) {
                        (Some(i), _) => {
                            let ok = finite(&i)
                                && i.iter().all(|x| *x > 0.0)
                                && i[0] + i[1] >= i[2] * (1.0 - 1e-9)
                                && i[1] + i[2] >= i[0] * (1.0 - 1e-9)
                                && i[0] + i[2] >= i[1] * (1.0 - 1e-9);
                            if !ok {
                                issues.push(Issue::new(
                                    f("inertia"),
                                    "principal moments must be positive and satisfy the triangle inequality",
                                ));
                            }
                            i
                        }
                        (None, Some(s)) => solid_inertia(s, m),
                        (None, None) => [1.0; 3],
                    };
                    Some(Kind::Free { mass: m, inertia })
                }
                Some(m) => {
                    issues.push(Issue::new(f("mass"), format!("{m} kg is outside 0 .. {MAX_MASS} kg (exclusive of 0)")));
                    None
                }
                None => {
                    issues.push(Issue::new(f("mass"), "a free object needs its mass (kg)"));
                    None
                }
            },
            k => {
                let k = crate::pipeline::ir::clip(k, 40);
                issues.push(Issue::new(f("kind"), format!("unknown kind {k:?}: static, moving or free")));
                None
            }
        };
        if issues.len() == n {
            if let (Some(shape), Some(p), Some(r), Some(kind)) = (shape, p, r, kind) {
                objects.push(SceneObject {
                    name: o.name.clone(),
                    shape,
                    pose: Isometry3::from_parts(Translation3::from(p), r),
                    kind,
                    color,
                    visible: o.visible,
                    attached_to: o.attached_to.clone(),
                });
            }
        }
    }
    if issues.is_empty() {
        Ok(Scene { objects })
    } else {
        Err(issues)
    }
}

/// A stored scene against a version's bodies: each object checked on its own, those that fail
/// (their name is now a body's, their body is gone) left out with the issues naming them.
pub fn check_stored(spec: &SceneSpec, bodies: &[String], meshes: &Meshes) -> (Scene, Vec<Issue>) {
    let mut scene = Scene::default();
    let mut left_out = Vec::new();
    for (k, o) in spec.objects.iter().enumerate() {
        match check_with(&SceneSpec { objects: vec![o.clone()] }, bodies, meshes) {
            Ok(s) => scene.objects.extend(s.objects),
            Err(issues) => left_out
                .extend(issues.into_iter().map(|i| Issue::new(i.field.replacen("objects[0]", &format!("objects[{k}]"), 1), i.message))),
        }
    }
    (scene, left_out)
}

fn motion(m: Option<&MotionSpec>, field: &str, issues: &mut Vec<Issue>) -> Option<Motion> {
    let Some(m) = m else {
        issues.push(Issue::new(field, "a moving object needs its motion: a velocity or a table of poses"));
        return None;
    };
    match (&m.velocity, &m.poses) {
        (Some(v), None) => {
            let v3 = Vector3::from(*v);
            if !finite(v) || v3.norm() > MAX_SPEED {
                issues.push(Issue::new(format!("{field}.velocity"), format!("must be finite and at most {MAX_SPEED} m/s")));
                return None;
            }
            Some(Motion::Velocity(v3))
        }
        (None, Some(rows)) => {
            if rows.len() < 2 {
                issues.push(Issue::new(format!("{field}.poses"), "a table of poses needs at least two rows"));
                return None;
            }
            let n = issues.len();
            let mut out = Vec::with_capacity(rows.len());
            let mut last = f64::NEG_INFINITY;
            for (i, row) in rows.iter().enumerate() {
                let rf = |x: &str| format!("{field}.poses[{i}].{x}");
                if !(row.time.is_finite() && row.time >= 0.0 && row.time > last && row.time <= 1e6) {
                    issues.push(Issue::new(rf("time"), "times must be finite, from 0 s, strictly increasing, at most 1e6 s"));
                }
                last = row.time;
                let p = position(&row.position).map_err(|m| issues.push(Issue::new(rf("position"), m))).ok();
                let r = rotation(&row.rotation).map_err(|m| issues.push(Issue::new(rf("rotation"), m))).ok();
                if let (Some(p), Some(r)) = (p, r) {
                    out.push((row.time, Isometry3::from_parts(Translation3::from(p), r)));
                }
            }
            (issues.len() == n).then_some(Motion::Poses(out))
        }
        _ => {
            issues.push(Issue::new(field, "give exactly one of velocity and poses"));
            None
        }
    }
}

/// Principal moments of the solid shape of mass `m` (uniform density) about its centre.
pub fn solid_inertia(s: &Shape, m: f64) -> [f64; 3] {
    match *s {
        Shape::Box { size: [a, b, c] } => [m * (b * b + c * c) / 12.0, m * (a * a + c * c) / 12.0, m * (a * a + b * b) / 12.0],
        Shape::Sphere { radius: r } => [0.4 * m * r * r; 3],
        Shape::Cylinder { radius: r, length: h } => {
            let t = m * (3.0 * r * r + h * h) / 12.0;
            [t, t, 0.5 * m * r * r]
        }
        // The cylinder through both caps: an upper bound, close for slim capsules.
        Shape::Capsule { radius: r, length: h } => {
            let h = h + 2.0 * r;
            let t = m * (3.0 * r * r + h * h) / 12.0;
            [t, t, 0.5 * m * r * r]
        }
        Shape::Plane => [1.0; 3],
        // The box around the hull: an upper bound.
        Shape::Mesh { ref hull, .. } => {
            let (lo, hi) = hull.vertices.iter().fold(([f64::MAX; 3], [f64::MIN; 3]), |(lo, hi), v| {
                ([lo[0].min(v[0]), lo[1].min(v[1]), lo[2].min(v[2])], [hi[0].max(v[0]), hi[1].max(v[1]), hi[2].max(v[2])])
            });
            solid_inertia(&Shape::Box { size: [hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]] }, m)
        }
    }
}

fn box_part(half: [f64; 3], centre: [f64; 3]) -> ConvexPart {
    let mut vertices = Vec::with_capacity(8);
    for i in 0..8 {
        let s = |bit: usize| if i & (1 << bit) != 0 { 1.0 } else { -1.0 };
        vertices.push([centre[0] + s(0) * half[0], centre[1] + s(1) * half[1], centre[2] + s(2) * half[2]]);
    }
    ConvexPart { vertices, faces: Vec::new(), radius: 0.0 }
}

impl SceneObject {
    /// The object's convex collision shape in its own frame (a cylinder: a circumscribed prism
    /// of [`CYLINDER_SIDES`] sides).
    pub fn shape(&self) -> BodyShape {
        let (kind, part) = match &self.shape {
            Shape::Box { size } => (ShapeKind::Box, box_part([size[0] / 2.0, size[1] / 2.0, size[2] / 2.0], [0.0; 3])),
            Shape::Mesh { hull, .. } => (ShapeKind::Hull, hull.clone()),
            Shape::Plane => {
                (ShapeKind::Box, box_part([PLANE_SIZE / 2.0, PLANE_SIZE / 2.0, PLANE_DEPTH / 2.0], [0.0, 0.0, -PLANE_DEPTH / 2.0]))
            }
            &Shape::Sphere { radius } => (ShapeKind::Sphere, ConvexPart { vertices: vec![[0.0; 3]], faces: Vec::new(), radius }),
            &Shape::Capsule { radius, length } => (
                ShapeKind::Capsule,
                ConvexPart { vertices: vec![[0.0, 0.0, -length / 2.0], [0.0, 0.0, length / 2.0]], faces: Vec::new(), radius },
            ),
            &Shape::Cylinder { radius, length } => {
                let rc = radius / (std::f64::consts::PI / CYLINDER_SIDES as f64).cos();
                let mut vertices = Vec::with_capacity(2 * CYLINDER_SIDES);
                for z in [-length / 2.0, length / 2.0] {
                    for i in 0..CYLINDER_SIDES {
                        let a = std::f64::consts::TAU * i as f64 / CYLINDER_SIDES as f64;
                        vertices.push([rc * a.cos(), rc * a.sin(), z]);
                    }
                }
                (ShapeKind::Cylinder, ConvexPart { vertices, faces: Vec::new(), radius: 0.0 })
            }
        };
        let vertex_count = part.vertices.len();
        BodyShape { kind, parts: vec![part], vertex_count, fit_error: 0.0, volume_ratio: 1.0, source_triangles: 0, warnings: Vec::new() }
    }

    /// Whether the object never moves in the world (static and not attached to a body).
    pub fn fixed_in_world(&self) -> bool {
        self.kind == Kind::Static && self.attached_to.is_none()
    }

    /// The object's pose at time `t` s: in the world, or in its body's frame_a when attached.
    /// Free objects stay at their pose (their dynamics belong to a simulation).
    pub fn pose_at(&self, t: f64) -> Isometry3<f64> {
        match &self.kind {
            Kind::Moving(Motion::Velocity(v)) => {
                Isometry3::from_parts(Translation3::from(self.pose.translation.vector + v * t), self.pose.rotation)
            }
            Kind::Moving(Motion::Poses(rows)) => {
                let k = rows.partition_point(|(time, _)| *time <= t);
                if k == 0 {
                    return rows[0].1;
                }
                if k == rows.len() {
                    return rows[k - 1].1;
                }
                let ((t0, a), (t1, b)) = (rows[k - 1], rows[k]);
                let s = (t - t0) / (t1 - t0);
                let p = a.translation.vector.lerp(&b.translation.vector, s);
                let r = a.rotation.try_slerp(&b.rotation, s, 1e-12).unwrap_or(a.rotation);
                Isometry3::from_parts(Translation3::from(p), r)
            }
            _ => self.pose,
        }
    }
}

pub mod mesh;
pub mod package;

pub use mesh::{Meshes, SceneMesh};

#[cfg(test)]
mod tests;
