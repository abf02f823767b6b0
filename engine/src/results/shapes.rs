//! What Dymola's animation draws, from a result of any Modelica model: the visual-shape
//! variables of every `Modelica.Mechanics.MultiBody.Visualizers.Advanced.Shape` (`<p>.Form`,
//! `<p>.rxvisobj[3]`, `<p>.ryvisobj[3]`, `<p>.rvisobj[3]`, `<p>.size[3]`, `<p>.Material`) and the
//! frames with `r_0`/`R.T` (drawn as axes).
//!
//! Codes (facts in `shared/guides/results-motion-collision.md`): shape code = `round(Form/1e20)
//! - 987000`: 101 box, 102 sphere, 103 cylinder, 104 cone, 110 pipe cylinder, 213 an external
//! file whose path is the `Form` variable's description; colour packed in `Material` as
//! `((⌊99r/255⌋·100 + ⌊99g/255⌋)·100 + ⌊99b/255⌋)·10 + ⌊9·specular⌋`.

use nalgebra::{Matrix3, Rotation3, UnitQuaternion};
use serde::Serialize;

use super::mat::Trajectory;

/// One visual shape.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Shape {
    /// The shape component's path, e.g. `mechanics.b1.shape`.
    pub name: String,
    pub kind: &'static str,
    pub code: i64,
    /// 0..255 per channel (the packing keeps 99 levels).
    pub color: [u8; 3],
    pub specular: f64,
    pub file: Option<String>,
}

/// The moving variables of one shape: rx[3], ry[3], r[3], size[3] (Form and Material are read
/// once, at the first instant).
struct ShapeVars {
    rx: [usize; 3],
    ry: [usize; 3],
    r: [usize; 3],
    size: [usize; 3],
}

/// Shapes and frames of a result, with the variables they are read from.
pub struct Scene {
    pub shapes: Vec<Shape>,
    /// Components with `r_0` and `R.T` (their path, e.g. `mechanics.b1.frame_a`).
    pub frames: Vec<String>,
    shape_vars: Vec<ShapeVars>,
    frame_vars: Vec<([usize; 3], [[usize; 3]; 3])>,
}

fn kind(code: i64) -> &'static str {
    match code {
        101 => "box",
        102 => "sphere",
        103 => "cylinder",
        104 => "cone",
        110 => "pipecylinder",
        213 => "file",
        _ => "other",
    }
}

/// Unpacks `Material`: colour (0..255) and specular coefficient.
pub fn material(m: f64) -> ([u8; 3], f64) {
    let m = m.round().max(0.0) as i64;
    let spec = (m % 10) as f64 / 9.0;
    let rgb = m / 10;
    let (r, g, b) = (rgb / 10_000, (rgb / 100) % 100, rgb % 100);
    let up = |c: i64| ((c.clamp(0, 99) as f64) * 255.0 / 99.0).round() as u8;
    ([up(r), up(g), up(b)], spec)
}

impl Scene {
    /// Finds every shape (a `.Form` with all its companions) and every frame of `t`.
    pub fn find(t: &Trajectory) -> Scene {
        let (mut shapes, mut shape_vars, mut frames, mut frame_vars) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        for (k, v) in t.variables.iter().enumerate() {
            if let Some(p) = v.name.strip_suffix(".Form") {
                let three = |what: &str| -> Option<[usize; 3]> {
                    Some([t.find(&format!("{p}.{what}[1]"))?, t.find(&format!("{p}.{what}[2]"))?, t.find(&format!("{p}.{what}[3]"))?])
                };
                let (Some(rx), Some(ry), Some(r), Some(size)) = (three("rxvisobj"), three("ryvisobj"), three("rvisobj"), three("size"))
                else {
                    continue;
                };
                let material = t.find(&format!("{p}.Material"));
                let form = if t.is_empty() { 0.0 } else { t.value(k, 0) };
                let code = (form / 1e20).round() as i64 - 987_000;
                let (color, specular) =
                    material.filter(|_| !t.is_empty()).map_or(([128, 128, 128], 0.5), |m| super::shapes::material(t.value(m, 0)));
                let file = (code == 213).then(|| v.description.clone()).filter(|d| !d.is_empty());
                shapes.push(Shape { name: p.to_string(), kind: kind(code), code, color, specular, file });
                shape_vars.push(ShapeVars { rx, ry, r, size });
            } else if let Some(p) = v.name.strip_suffix(".r_0[1]") {
                let r = [1, 2, 3].map(|i| t.find(&format!("{p}.r_0[{i}]")));
                let m = [1, 2, 3].map(|i| [1, 2, 3].map(|j| t.find(&format!("{p}.R.T[{i},{j}]"))));
                if r.iter().chain(m.iter().flatten()).all(Option::is_some) {
                    let r = r.map(|x| x.unwrap_or(0));
                    let m = m.map(|row| row.map(|x| x.unwrap_or(0)));
                    frames.push(p.to_string());
                    frame_vars.push((r, m));
                }
            }
        }
        Scene { shapes, frames, shape_vars, frame_vars }
    }

    /// The binary stream of the API (little-endian): `C2MS`, u32 version 1, u32 shapes, u32
    /// frames, u32 steps; per step f32 time, per shape 12 f32 (r, rx, ry, size), per frame 7 f32
    /// (position, quaternion x y z w).
    pub fn stream(&self, t: &Trajectory) -> Vec<u8> {
        let n = t.len();
        let mut out = Vec::with_capacity(20 + n * (4 + 48 * self.shapes.len() + 28 * self.frames.len()));
        out.extend_from_slice(b"C2MS");
        for w in [1u32, self.shapes.len() as u32, self.frames.len() as u32, n as u32] {
            out.extend_from_slice(&w.to_le_bytes());
        }
        let put = |x: f64, out: &mut Vec<u8>| out.extend_from_slice(&(x as f32).to_le_bytes());
        for i in 0..n {
            put(t.value(0, i), &mut out);
            for s in &self.shape_vars {
                for group in [&s.r, &s.rx, &s.ry, &s.size] {
                    for v in group.iter() {
                        put(t.value(*v, i), &mut out);
                    }
                }
            }
            for (r, m) in &self.frame_vars {
                let tm = Matrix3::from_fn(|a, b| t.value(m[a][b], i));
                let q = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(tm.transpose()));
                let q = UnitQuaternion::new_normalize(q.into_inner());
                for v in r {
                    put(t.value(*v, i), &mut out);
                }
                for x in [q.i, q.j, q.k, q.w] {
                    put(x, &mut out);
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::results::write::trajectory;

    #[test]
    fn material_unpacks_the_dymola_colour() {
        // Red 255, green 0, blue 0, specular 0.7: ((99*100 + 0)*100 + 0)*10 + 6.
        let (c, s) = material(((99.0 * 100.0) * 100.0) * 10.0 + 6.0);
        assert_eq!(c, [255, 0, 0]);
        assert!((s - 6.0 / 9.0).abs() < 1e-12);
        assert_eq!(material(((50.0 * 100.0 + 25.0) * 100.0 + 99.0) * 10.0).0, [129, 64, 255]);
    }

    #[test]
    fn a_moving_box_and_a_frame() {
        let time = [0.0, 1.0, 2.0];
        let c = |v: f64| vec![v; 3];
        let series: Vec<(String, Vec<f64>)> = vec![
            ("b.shape.Form".into(), c((987_000.0 + 101.0) * 1e20)),
            ("b.shape.rxvisobj[1]".into(), c(1.0)),
            ("b.shape.rxvisobj[2]".into(), c(0.0)),
            ("b.shape.rxvisobj[3]".into(), c(0.0)),
            ("b.shape.ryvisobj[1]".into(), c(0.0)),
            ("b.shape.ryvisobj[2]".into(), c(1.0)),
            ("b.shape.ryvisobj[3]".into(), c(0.0)),
            ("b.shape.rvisobj[1]".into(), vec![0.0, 1.0, 2.0]),
            ("b.shape.rvisobj[2]".into(), c(0.5)),
            ("b.shape.rvisobj[3]".into(), c(0.0)),
            ("b.shape.size[1]".into(), c(0.3)),
            ("b.shape.size[2]".into(), c(0.2)),
            ("b.shape.size[3]".into(), c(0.1)),
            ("b.shape.Material".into(), c(((99.0 * 100.0) * 100.0) * 10.0)),
            ("b.frame_a.r_0[1]".into(), vec![0.0, 1.0, 2.0]),
            ("b.frame_a.r_0[2]".into(), c(0.0)),
            ("b.frame_a.r_0[3]".into(), c(0.0)),
            ("b.frame_a.R.T[1, 1]".into(), c(1.0)),
            ("b.frame_a.R.T[1, 2]".into(), c(0.0)),
            ("b.frame_a.R.T[1, 3]".into(), c(0.0)),
            ("b.frame_a.R.T[2, 1]".into(), c(0.0)),
            ("b.frame_a.R.T[2, 2]".into(), c(1.0)),
            ("b.frame_a.R.T[2, 3]".into(), c(0.0)),
            ("b.frame_a.R.T[3, 1]".into(), c(0.0)),
            ("b.frame_a.R.T[3, 2]".into(), c(0.0)),
            ("b.frame_a.R.T[3, 3]".into(), c(1.0)),
        ];
        let bytes = trajectory(&time, &series, true);
        let t = Trajectory::read(&bytes, "box.mat").expect("reads");
        let s = Scene::find(&t);
        assert_eq!(s.shapes.len(), 1);
        assert_eq!((s.shapes[0].kind, s.shapes[0].code, s.shapes[0].color), ("box", 101, [255, 0, 0]));
        assert_eq!(s.frames, vec!["b.frame_a".to_string()]);
        let b = s.stream(&t);
        assert_eq!(&b[..4], b"C2MS");
        assert_eq!(b.len(), 20 + 3 * (4 + 48 + 28));
        let f = |k: usize| f32::from_le_bytes([b[k], b[k + 1], b[k + 2], b[k + 3]]);
        let step2 = 20 + 2 * (4 + 48 + 28);
        assert_eq!((f(step2), f(step2 + 4), f(step2 + 8)), (2.0, 2.0, 0.5), "time, then r at t = 2");
        assert_eq!(f(step2 + 4 + 36), 0.3, "length");
        assert_eq!(f(step2 + 4 + 48 + 24), 1.0, "the frame's quaternion w");
    }

    /// MSL RobotR3 from Dymola: its animation shapes and frames are all found.
    #[test]
    fn robot_r3_has_its_shapes() {
        let Some(dir) = crate::pipeline::testutil::fixtures_dir() else { return };
        let Ok(bytes) = std::fs::read(dir.join("mat/lbl-srg+BuildingsPy/fullRobot.mat")) else {
            println!("NOTICE: fullRobot.mat absent; skipped");
            return;
        };
        let t = Trajectory::read(&bytes, "fullRobot.mat").expect("reads");
        let s = Scene::find(&t);
        assert!(s.shapes.len() >= 7, "{} shapes", s.shapes.len());
        assert!(s.shapes.iter().all(|x| x.kind != "other"), "{:?}", s.shapes.iter().map(|x| (&x.name, x.code)).collect::<Vec<_>>());
        assert!(s.frames.len() > 10);
        let b = s.stream(&t);
        assert_eq!(b.len(), 20 + t.len() * (4 + 48 * s.shapes.len() + 28 * s.frames.len()));
    }
}
