//! A checked [`Scene`] in the package (issue 29): its part of `Mechatronics.mo` and of the MJCF.
//!
//! Modelica (every component named `scene_<object>`, so no object name can clash with a body,
//! a drive or a keyword):
//! - each object is drawn by an MSL `Visualizers.Advanced.Shape` at its pose over time;
//! - a static object fixed in the world is a constant pose; one attached to a body stands on a
//!   `Parts.FixedTranslation` from the body's `frame_a`;
//! - a moving object follows its motion: `time`-linear for a velocity, or two `CombiTimeTable`s
//!   for a table of poses (position and quaternion, linear, rows added so that no step turns more
//!   than [`MAX_TABLE_STEP`]: the normalised linear quaternion is then within 0.05 % of the
//!   engine's slerp; and the velocity and angular velocity of each segment, constant);
//! - a free object is an MSL `Parts.Body` (its mass and principal inertia, starting at rest at
//!   its pose), with no joint: a free body;
//! - every object joins the contact forces (`Components.Collision.World`) as a [`Member`]: its
//!   pose and velocities as expressions, and a frame the contact force acts on (free objects:
//!   their body; attached ones: their body through the translation; others: none, they are
//!   prescribed).
//!
//! MJCF: static objects fixed in the world are geoms of the world body, attached ones geoms of
//! their body (its frame is the body's CS1 = frame_a), free objects bodies with a `freejoint`
//! and their inertia, moving ones `mocap` bodies at their pose at t = 0 (MuJoCo moves mocap
//! bodies only when the caller sets `mocap_pos`/`mocap_quat`; said in a comment).

use std::fmt::Write as _;

use nalgebra::{Isometry3, UnitQuaternion, Vector3};

use super::{Kind, Motion, Scene, SceneObject, Shape, PLANE_DEPTH, PLANE_SIZE};
use crate::collision::ConvexPart;
use crate::pipeline::back::mjcf::{attr, n as mj, quat, v3};
use crate::pipeline::back::modelica::diagram::extend::PLACEHOLDER;

/// Largest rotation between two rows of a pose table as written into the Modelica table.
pub const MAX_TABLE_STEP: f64 = 5.0 * std::f64::consts::PI / 180.0;

/// A scene object among the contact world's members.
#[derive(Clone, Debug)]
pub struct Member {
    /// Its name in the collision world (`scene_<object>`).
    pub name: String,
    pub parts: Vec<ConvexPart>,
    /// Modelica expressions of the world's inputs: origin (world), R.T, velocity (world),
    /// angular velocity (object frame).
    pub r_0: String,
    pub r_t: String,
    pub v_0: String,
    pub w_a: String,
    /// The frame a contact force acts on (`None`: a prescribed object, no force applied).
    pub force_frame: Option<String>,
    /// Fixed in the world or prescribed: contacts between two such objects are not computed.
    pub prescribed: bool,
    /// The model body it is attached to (the pair is allowed to touch).
    pub attached_to: Option<String>,
}

/// The scene's part of `Mechatronics`.
#[derive(Clone, Debug, Default)]
pub struct Modelica {
    /// Declarations, then `equation` with connects, then `public` (empty: no objects).
    pub declarations: String,
    pub members: Vec<Member>,
    /// Whether some object is free (it falls through everything without contact forces).
    pub has_free: bool,
}

/// The Modelica component name of an object.
pub fn component(object: &str) -> String {
    format!("scene_{object}")
}

fn num(x: f64) -> String {
    crate::numtext::dbg(if x.abs() < 1e-15 { 0.0 } else { x })
}

fn vec3(v: &Vector3<f64>) -> String {
    format!("{{{}, {}, {}}}", num(v.x), num(v.y), num(v.z))
}

/// `T` (world to object: the transpose of the object's rotation) as a Modelica matrix.
fn t_of(q: &UnitQuaternion<f64>) -> String {
    let t = q.to_rotation_matrix().matrix().transpose();
    let row = |i: usize| format!("{{{}, {}, {}}}", num(t[(i, 0)]), num(t[(i, 1)]), num(t[(i, 2)]));
    format!("{{{}, {}, {}}}", row(0), row(1), row(2))
}

/// Angles a, b, c of MSL's `sequence_start = {1, 2, 3}`: R = Rx(a)·Ry(b)·Rz(c).
pub fn xyz_angles(q: &UnitQuaternion<f64>) -> [f64; 3] {
    let r = q.to_rotation_matrix();
    let m = r.matrix();
    let b = m[(0, 2)].clamp(-1.0, 1.0).asin();
    if (1.0 - m[(0, 2)].abs()) < 1e-12 {
        // Gimbal lock: c = 0 and a takes the rest.
        return [m[(2, 1)].atan2(m[(1, 1)]), b, 0.0];
    }
    [(-m[(1, 2)]).atan2(m[(2, 2)]), b, (-m[(0, 1)]).atan2(m[(0, 0)])]
}

/// The MSL shape modifiers drawing `shape` centred on its frame.
fn shape_modifiers(shape: &Shape, pkg: &str) -> String {
    if let Shape::Mesh { mesh, scale, .. } = shape {
        // An external shape: length, width and height scale the file's x, y and z.
        return format!(
            "shapeType=\"modelica://{pkg}/Resources/Shapes/{}\", r_shape={{0, 0, 0}}, lengthDirection={{1, 0, 0}}, widthDirection={{0, 1, 0}}, length={s}, width={s}, height={s}, extra=0",
            mesh_file(mesh),
            s = num(*scale)
        );
    }
    let (kind, r_shape, dir, len, w, h) = match *shape {
        Shape::Box { size: [a, b, c] } => ("box", [-a / 2.0, 0.0, 0.0], [1.0, 0.0, 0.0], a, b, c),
        Shape::Plane => ("box", [-PLANE_SIZE / 2.0, 0.0, -PLANE_DEPTH / 2.0], [1.0, 0.0, 0.0], PLANE_SIZE, PLANE_SIZE, PLANE_DEPTH),
        Shape::Sphere { radius: r } => ("sphere", [-r, 0.0, 0.0], [1.0, 0.0, 0.0], 2.0 * r, 2.0 * r, 2.0 * r),
        Shape::Cylinder { radius: r, length: l } => ("cylinder", [0.0, 0.0, -l / 2.0], [0.0, 0.0, 1.0], l, 2.0 * r, 2.0 * r),
        // Drawn as the cylinder through both caps.
        Shape::Capsule { radius: r, length: l } => ("cylinder", [0.0, 0.0, -l / 2.0 - r], [0.0, 0.0, 1.0], l + 2.0 * r, 2.0 * r, 2.0 * r),
        Shape::Mesh { .. } => unreachable!("drawn from its file above"),
    };
    let width_dir = if dir[0] == 1.0 { "{0, 1, 0}" } else { "{1, 0, 0}" };
    format!(
        "shapeType=\"{kind}\", r_shape={}, lengthDirection={}, widthDirection={width_dir}, length={}, width={}, height={}",
        vec3(&Vector3::from(r_shape)),
        vec3(&Vector3::from(dir)),
        num(len),
        num(w),
        num(h)
    )
}

/// Pose table rows for Modelica: (time, position, quaternion), with rows added within segments
/// turning more than [`MAX_TABLE_STEP`], quaternion signs continuous; and the rate rows (time,
/// velocity in world, angular velocity in the object frame), constant per segment, zero outside.
type Rows = (Vec<(f64, Vector3<f64>, UnitQuaternion<f64>)>, Vec<(f64, Vector3<f64>, Vector3<f64>)>);

fn table_rows(rows: &[(f64, Isometry3<f64>)]) -> Rows {
    let mut path = Vec::new();
    let mut rate = Vec::new();
    if rows[0].0 > 0.0 {
        rate.push((0.0, Vector3::zeros(), Vector3::zeros()));
    }
    let mut last_q: Option<nalgebra::Quaternion<f64>> = None;
    let mut push = |t: f64, p: Vector3<f64>, q: UnitQuaternion<f64>, path: &mut Vec<_>| {
        let mut raw = *q.quaternion();
        if let Some(l) = last_q {
            if l.dot(&raw) < 0.0 {
                raw = -raw;
            }
        }
        last_q = Some(raw);
        path.push((t, p, UnitQuaternion::new_unchecked(raw)));
    };
    push(rows[0].0, rows[0].1.translation.vector, rows[0].1.rotation, &mut path);
    for w in rows.windows(2) {
        let ((t0, a), (t1, b)) = (w[0], w[1]);
        let dt = t1 - t0;
        let rel = a.rotation.inverse() * b.rotation;
        let angle = rel.angle();
        let steps = ((angle / MAX_TABLE_STEP).ceil() as usize).max(1);
        for k in 1..=steps {
            let s = k as f64 / steps as f64;
            let p = a.translation.vector.lerp(&b.translation.vector, s);
            let q = a.rotation * UnitQuaternion::from_scaled_axis(rel.scaled_axis() * s);
            push(t0 + s * dt, p, q, &mut path);
        }
        rate.push((t0, (b.translation.vector - a.translation.vector) / dt, rel.scaled_axis() / dt));
    }
    rate.push((rows[rows.len() - 1].0, Vector3::zeros(), Vector3::zeros()));
    (path, rate)
}

fn matrix(rows: impl Iterator<Item = Vec<f64>>) -> String {
    let lines: Vec<String> = rows.map(|r| r.into_iter().map(num).collect::<Vec<_>>().join(", ")).collect();
    format!("[{}]", lines.join("; "))
}

/// The scene's declarations for `Mechatronics` and its members of the contact world.
/// The file of a scene mesh under `Resources/Shapes/` (a `-` keeps it apart from the bodies'
/// shapes, whose stems are identifiers).
pub fn mesh_file(mesh: &str) -> String {
    format!("scene-{mesh}.stl")
}

/// The scene's mesh files for the package: `(path, bytes)` under `{pkg}/Resources/Shapes/`, one
/// per mesh some object uses.
pub fn mesh_files(scene: &Scene, meshes: &super::Meshes, pkg: &str) -> Vec<(String, Vec<u8>)> {
    let used: std::collections::BTreeSet<&str> = scene
        .objects
        .iter()
        .filter_map(|o| match &o.shape {
            Shape::Mesh { mesh, .. } => Some(mesh.as_str()),
            _ => None,
        })
        .collect();
    used.into_iter().filter_map(|m| Some((format!("{pkg}/Resources/Shapes/{}", mesh_file(m)), meshes.get(m)?.stl.clone()))).collect()
}

/// The scene's part of `Mechatronics` in package `pkg`.
pub fn modelica(scene: &Scene, pkg: &str) -> Modelica {
    if scene.objects.is_empty() {
        return Modelica::default();
    }
    let mut decl = String::new();
    let mut conn = String::new();
    let mut members = Vec::new();
    let mut has_free = false;
    let _ = writeln!(
        decl,
        "\n  // Scene: {} objects of the machine's environment (static, moving, free; drawn, and in the contact forces)",
        scene.objects.len()
    );
    for o in &scene.objects {
        let c = component(&o.name);
        let t = t_of(&o.pose.rotation);
        let p = o.pose.translation.vector;
        let shape = o.shape();
        let parts = shape.parts;
        let mut member = |r_0: String, r_t: String, v_0: String, w_a: String, force_frame: Option<String>, prescribed: bool| {
            members.push(Member {
                name: c.clone(),
                parts: parts.clone(),
                r_0,
                r_t,
                v_0,
                w_a,
                force_frame,
                prescribed,
                attached_to: o.attached_to.clone(),
            })
        };
        let (r, rot) = match (&o.kind, &o.attached_to) {
            (Kind::Static, Some(body)) => {
                let _ = writeln!(
                    decl,
                    "  Modelica.Mechanics.MultiBody.Parts.FixedTranslation {c}_frame(r={}, animation=false) \"Where {} stands on {body}\"\n    {PLACEHOLDER};",
                    vec3(&p),
                    o.name
                );
                let _ = writeln!(conn, "  connect({body}.frame_a, {c}_frame.frame_a);");
                member(
                    format!("{c}_frame.frame_b.r_0"),
                    format!("{t}*{c}_frame.frame_b.R.T"),
                    format!("{body}.v_0 + Modelica.Mechanics.MultiBody.Frames.resolve1({body}.frame_a.R, cross({body}.w_a, {}))", vec3(&p)),
                    format!("{t}*{body}.w_a"),
                    Some(format!("{c}_frame.frame_b")),
                    false,
                );
                (
                    format!("{c}_frame.frame_b.r_0"),
                    format!(
                        "Modelica.Mechanics.MultiBody.Frames.absoluteRotation({c}_frame.frame_b.R, Modelica.Mechanics.MultiBody.Frames.Orientation(T={t}, w=zeros(3)))"
                    ),
                )
            }
            (Kind::Static, None) => {
                member(vec3(&p), t.clone(), "zeros(3)".into(), "zeros(3)".into(), None, true);
                (vec3(&p), format!("Modelica.Mechanics.MultiBody.Frames.Orientation(T={t}, w=zeros(3))"))
            }
            (Kind::Moving(Motion::Velocity(v)), _) => {
                let r = format!("{} + {}*time", vec3(&p), vec3(v));
                member(r.clone(), t.clone(), vec3(v), "zeros(3)".into(), None, true);
                (r, format!("Modelica.Mechanics.MultiBody.Frames.Orientation(T={t}, w=zeros(3))"))
            }
            (Kind::Moving(Motion::Poses(rows)), _) => {
                let (path, rate) = table_rows(rows);
                let path_table = matrix(path.iter().map(|(t, p, q)| vec![*t, p.x, p.y, p.z, q.i, q.j, q.k, q.w]));
                let rate_table = matrix(rate.iter().map(|(t, v, w)| vec![*t, v.x, v.y, v.z, w.x, w.y, w.z]));
                let _ = writeln!(
                    decl,
                    "  Modelica.Blocks.Sources.CombiTimeTable {c}_path(table={path_table}, smoothness=Modelica.Blocks.Types.Smoothness.LinearSegments, extrapolation=Modelica.Blocks.Types.Extrapolation.HoldLastPoint) \"Pose of {} over time: position (m, world), quaternion {{x, y, z, w}} (object to world)\"\n    {PLACEHOLDER};",
                    o.name
                );
                let _ = writeln!(
                    decl,
                    "  Modelica.Blocks.Sources.CombiTimeTable {c}_rate(table={rate_table}, smoothness=Modelica.Blocks.Types.Smoothness.ConstantSegments, extrapolation=Modelica.Blocks.Types.Extrapolation.HoldLastPoint) \"Velocity (m/s, world) and angular velocity (rad/s, object frame) of {} per segment\"\n    {PLACEHOLDER};",
                    o.name
                );
                let q = format!("{c}_path.y[4:7]");
                let t = format!("Modelica.Mechanics.MultiBody.Frames.Quaternions.to_T({q}/sqrt({q}*{q}))");
                member(format!("{c}_path.y[1:3]"), t.clone(), format!("{c}_rate.y[1:3]"), format!("{c}_rate.y[4:6]"), None, true);
                (format!("{c}_path.y[1:3]"), format!("Modelica.Mechanics.MultiBody.Frames.Orientation(T={t}, w={c}_rate.y[4:6])"))
            }
            (Kind::Free { mass, inertia }, _) => {
                has_free = true;
                let [a, b, g] = xyz_angles(&o.pose.rotation);
                let _ = writeln!(
                    decl,
                    "  Modelica.Mechanics.MultiBody.Parts.Body {c}(m={}, r_CM={{0, 0, 0}}, I_11={}, I_22={}, I_33={}, animation=false, r_0(start={}, each fixed=true), v_0(start={{0, 0, 0}}, each fixed=true), angles_fixed=true, angles_start={{{}, {}, {}}}, sequence_start={{1, 2, 3}}, w_0_fixed=true, enforceStates=true) \"{}: a free object, starting at rest\"\n    {PLACEHOLDER};",
                    num(*mass),
                    num(inertia[0]),
                    num(inertia[1]),
                    num(inertia[2]),
                    vec3(&p),
                    num(a),
                    num(b),
                    num(g),
                    o.name
                );
                member(
                    format!("{c}.frame_a.r_0"),
                    format!("{c}.frame_a.R.T"),
                    format!("{c}.v_0"),
                    format!("{c}.w_a"),
                    Some(format!("{c}.frame_a")),
                    false,
                );
                (format!("{c}.frame_a.r_0"), format!("{c}.frame_a.R"))
            }
        };
        let rgb = o.color.map(|x| (x * 255.0).round());
        let _ = writeln!(
            decl,
            "  Modelica.Mechanics.MultiBody.Visualizers.Advanced.Shape {c}_shape({}, color={{{}, {}, {}}}, r={r}, R={rot}) if {} \"Shape of {}\"\n    {PLACEHOLDER};",
            shape_modifiers(&o.shape, pkg),
            num(rgb[0]),
            num(rgb[1]),
            num(rgb[2]),
            if o.visible { "true" } else { "false" },
            o.name
        );
    }
    let mut declarations = decl;
    if !conn.is_empty() {
        let _ = write!(declarations, "equation\n{conn}public\n");
    }
    Modelica { declarations, members, has_free }
}

fn geom(o: &SceneObject, pose: &Isometry3<f64>) -> String {
    let (kind, size) = match o.shape {
        Shape::Mesh { .. } => ("mesh", String::new()),
        Shape::Box { size: [a, b, c] } => ("box", format!("{} {} {}", mj(a / 2.0), mj(b / 2.0), mj(c / 2.0))),
        Shape::Plane => ("plane", format!("{} {} {}", mj(PLANE_SIZE / 2.0), mj(PLANE_SIZE / 2.0), mj(PLANE_DEPTH))),
        Shape::Sphere { radius } => ("sphere", mj(radius)),
        Shape::Cylinder { radius, length } => ("cylinder", format!("{} {}", mj(radius), mj(length / 2.0))),
        Shape::Capsule { radius, length } => ("capsule", format!("{} {}", mj(radius), mj(length / 2.0))),
    };
    let (t, q) = (pose.translation.vector, pose.rotation);
    let [r, g, b] = o.color;
    let size = if kind == "mesh" { format!("mesh=\"scene-{}\"", attr(&o.name)) } else { format!("size=\"{size}\"") };
    format!(
        "<geom name=\"{}\" type=\"{kind}\" {size} pos=\"{}\" quat=\"{}\" rgba=\"{} {} {} {}\"/>",
        attr(&o.name),
        v3(&t),
        quat(&q),
        mj(r),
        mj(g),
        mj(b),
        if o.visible { "1" } else { "0" }
    )
}

/// The MJCF text of a model (`mjcf`, as `back::mjcf` writes it) with the scene added: world
/// geoms, free and mocap bodies before `</worldbody>`, attached geoms inside their body.
pub fn mjcf(mjcf: &str, scene: &Scene) -> String {
    if scene.objects.is_empty() {
        return mjcf.to_string();
    }
    let mut world = String::from("    <!-- Scene (cad2mo issue 29): the machine's environment -->\n");
    let mut out = String::with_capacity(mjcf.len() + 256 * scene.objects.len());
    for o in &scene.objects {
        match (&o.kind, &o.attached_to) {
            (Kind::Static, Some(_)) => {}
            (Kind::Static, None) => {
                let _ = writeln!(world, "    {}", geom(o, &o.pose));
            }
            (Kind::Moving(_), _) => {
                let p = o.pose_at(0.0);
                let _ = writeln!(
                    world,
                    "    <!-- {}: prescribed motion (a mocap body at its pose at t = 0; set data.mocap_pos/mocap_quat to move it) -->",
                    attr(&o.name)
                );
                let _ = writeln!(
                    world,
                    "    <body name=\"{}\" mocap=\"true\" pos=\"{}\" quat=\"{}\">\n      {}\n    </body>",
                    attr(&o.name),
                    v3(&p.translation.vector),
                    quat(&p.rotation),
                    geom(o, &Isometry3::identity())
                );
            }
            (Kind::Free { mass, inertia }, _) => {
                let p = o.pose;
                let _ = writeln!(
                    world,
                    "    <body name=\"{}\" pos=\"{}\" quat=\"{}\">\n      <freejoint name=\"{}_free\"/>\n      <inertial pos=\"0 0 0\" mass=\"{}\" diaginertia=\"{} {} {}\"/>\n      {}\n    </body>",
                    attr(&o.name),
                    v3(&p.translation.vector),
                    quat(&p.rotation),
                    attr(&o.name),
                    mj(*mass),
                    mj(inertia[0]),
                    mj(inertia[1]),
                    mj(inertia[2]),
                    geom(o, &Isometry3::identity())
                );
            }
        }
    }
    // Mesh assets, one per mesh object (its unit's scale), in the model's <asset> or a new one.
    let mut assets = String::new();
    for o in &scene.objects {
        if let Shape::Mesh { mesh, scale, .. } = &o.shape {
            let _ = writeln!(
                assets,
                "    <mesh name=\"scene-{}\" file=\"{}\" scale=\"{s} {s} {s}\"/>",
                attr(&o.name),
                attr(&mesh_file(mesh)),
                s = mj(*scale)
            );
        }
    }
    let has_asset = mjcf.lines().any(|l| l.trim() == "</asset>");
    for line in mjcf.split_inclusive('\n') {
        if !assets.is_empty() {
            let t = line.trim();
            if (has_asset && t == "</asset>") || (!has_asset && t.starts_with("<worldbody")) {
                if !has_asset {
                    out.push_str("  <asset>\n");
                }
                out.push_str(&assets);
                if !has_asset {
                    out.push_str("  </asset>\n");
                }
                assets.clear();
            }
        }
        if line.trim() == "</worldbody>" {
            out.push_str(&world);
        }
        out.push_str(line);
        let t = line.trim_start();
        if let Some(rest) = t.strip_prefix("<body name=\"") {
            let name = rest.split('"').next().unwrap_or_default();
            let ind = &line[..line.len() - t.len()];
            for o in scene.objects.iter().filter(|o| o.attached_to.as_deref().map(attr).as_deref() == Some(name)) {
                let _ = writeln!(out, "{ind}  {}", geom(o, &o.pose));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn xyz_angles_rebuild_the_rotation() {
        for q in [
            UnitQuaternion::from_euler_angles(0.3, -0.7, 2.0),
            UnitQuaternion::from_euler_angles(0.0, std::f64::consts::FRAC_PI_2, 0.4),
            UnitQuaternion::identity(),
        ] {
            let [a, b, c] = xyz_angles(&q);
            let r = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), a)
                * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), b)
                * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), c);
            assert!(r.angle_to(&q) < 1e-9, "{q:?}: {a} {b} {c}");
        }
    }

    #[test]
    fn table_rows_turn_in_small_steps_and_rates_integrate_to_the_rows() {
        let a = Isometry3::new(Vector3::new(0.0, 0.0, 0.0), Vector3::zeros());
        let b = Isometry3::new(Vector3::new(1.0, 0.0, 0.0), Vector3::new(0.0, 0.0, 1.0));
        let (path, rate) = table_rows(&[(1.0, a), (3.0, b)]);
        // 1 rad in at most 5° steps: 12 steps, 13 rows.
        assert_eq!(path.len(), 13);
        assert!(path.windows(2).all(|w| w[0].2.angle_to(&w[1].2) <= MAX_TABLE_STEP + 1e-12));
        assert!((path[12].2.angle_to(&b.rotation)) < 1e-12 && (path[12].1 - b.translation.vector).norm() < 1e-12);
        // zero before, the segment's rates, zero after
        assert_eq!(rate.len(), 3);
        assert_eq!((rate[0].0, rate[1].0, rate[2].0), (0.0, 1.0, 3.0));
        assert!((rate[1].1 - Vector3::new(0.5, 0.0, 0.0)).norm() < 1e-12);
        assert!((rate[1].2 - Vector3::new(0.0, 0.0, 0.5)).norm() < 1e-12);
        assert_eq!(rate[2].1, Vector3::zeros());
    }
}
