//! The URDF the pipeline writes (`<Pkg>/<Pkg>.urdf`, `back::urdf`), read by MuJoCo (which loads
//! URDF directly): for our golden cases and the real first-generation fixtures, MuJoCo's total
//! mass equals ours, and at qpos = 0 every body's world pose equals its CS1 pose in our IR (the
//! CAD pose) to 1e-9. For tree mechanisms, random URDF coordinates `u` put every body where our
//! own forward kinematics puts it at the Modelica coordinates `q0 + u` (URDF q = Modelica q −
//! start value). Skips with a NOTICE when mujoco cannot be imported, unless
//! CAD2MO_REQUIRE_TOOLS=1.

use std::path::{Path, PathBuf};

use cad2mo_engine::mechanism::{Mechanism, XorShift};
use cad2mo_engine::pipeline::front::bundle::Limits;
use cad2mo_engine::pipeline::{self, Options};
use cad2mo_tests::common::{files_with_ext, fixture_bundle, fixtures_dir, python_check, sorted_dirs, use_package_names, workspace_root};
use nalgebra::{Isometry3, Matrix3, Quaternion, Rotation3, Translation3, UnitQuaternion, Vector3};

const TOL: f64 = 1e-9;

/// What MuJoCo reported, `None` when it cannot be run here.
fn mujoco(label: &str, urdf: &str, samples: &[serde_json::Value]) -> Option<serde_json::Value> {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("robot.urdf");
    std::fs::write(&path, urdf).expect("write urdf");
    let spec = serde_json::json!({"urdf": path, "samples": samples});
    python_check(dir.path(), "urdf_mujoco.py", &spec, label, "URDF MuJoCo check (python3 -m pip install mujoco)")
}

fn pose_of(result: &serde_json::Value, s: usize, body: &str) -> Option<Isometry3<f64>> {
    let f = |v: &serde_json::Value| v.as_f64().unwrap_or(f64::NAN);
    let p = result["xpos"][s][body].as_array()?;
    let r = result["xquat"][s][body].as_array()?;
    Some(Isometry3::from_parts(
        Translation3::new(f(&p[0]), f(&p[1]), f(&p[2])),
        UnitQuaternion::from_quaternion(Quaternion::new(f(&r[0]), f(&r[1]), f(&r[2]), f(&r[3]))),
    ))
}

fn off(a: &Isometry3<f64>, b: &Isometry3<f64>) -> (f64, f64) {
    ((a.translation.vector - b.translation.vector).norm(), a.rotation.angle_to(&b.rotation))
}

/// Checks one bundle; `None` when MuJoCo is unavailable, `Some(false)` when the bundle does not
/// convert (broken cases).
fn check(label: &str, bundle_path: &Path) -> Option<bool> {
    let Ok(bundle) = cad2mo::read_bundle(bundle_path, &Limits::default()) else { return Some(false) };
    let opts = Options { write_shapes: false, ..Options::default() };
    let out = match pipeline::convert(&bundle, &opts) {
        Ok(out) => out,
        Err(e) => {
            println!("{label}: {e}");
            return Some(false);
        }
    };
    let urdf = out.files.iter().find(|(p, _)| p.ends_with(".urdf")).map(|(_, b)| String::from_utf8(b.bytes().into_owned()).expect("utf-8"));
    let urdf = urdf.unwrap_or_else(|| panic!("{label}: no .urdf in the output"));
    assert!(!urdf.contains("<mesh"), "{label}: meshes written without shapes");
    // Our tree mechanisms (no loops, free bodies, sphericals): random coordinates too.
    let a = pipeline::analyse(&bundle, &opts).expect("analyses as it converted");
    let mech = Mechanism::from_validated(&a.model, &a.validated).ok().filter(|m| !m.has_loops() && m.dof() > 0).map(|mut m| {
        use_package_names(&mut m, &a, &out);
        m
    });
    let mut samples = vec![serde_json::json!({})];
    let mut us: Vec<Vec<f64>> = Vec::new();
    if let Some(m) = &mech {
        let mut rng = XorShift::new(7);
        for _ in 0..3 {
            let u: Vec<f64> = (0..m.dof()).map(|_| rng.range(-1.0, 1.0)).collect();
            samples.push(serde_json::Value::Object(
                m.coordinates().iter().zip(&u).map(|(c, x)| (c.name.clone(), serde_json::json!(x))).collect(),
            ));
            us.push(u);
        }
    }
    let result = mujoco(label, &urdf, &samples)?;
    for link in result["inertia_replaced"].as_array().into_iter().flatten() {
        let body = out.report.bodies.iter().find(|b| Some(b.modelica_name.as_str()) == link.as_str());
        let body = body.unwrap_or_else(|| panic!("{label}: MuJoCo replaced the inertia of {link}, which is no body"));
        let warned =
            out.report.warnings.iter().any(|w| w.code == "inertia-not-positive" && w.location.contains(&format!("\"{}\"", body.cad_name)));
        // Without a warning, it must be semi-definite within the validator's tolerance.
        let i = Matrix3::from_fn(|r, c| body.inertia_cg[r][c]);
        let eig = i.symmetric_eigenvalues();
        let semi = eig.min() >= -1e-6 * eig.amax();
        assert!(
            warned || semi,
            "{label}: the inertia of {} is not positive definite ({eig:?}), and the validator did not say so",
            body.cad_name
        );
    }
    let ours: f64 = out.report.bodies.iter().map(|b| b.mass).sum();
    let theirs = result["total_mass"].as_f64().unwrap_or(f64::NAN);
    assert!((ours - theirs).abs() <= TOL * ours.max(1.0), "{label}: total mass {ours} vs MuJoCo {theirs}");
    let mut worst = (0.0f64, 0.0f64);
    for b in &out.report.bodies {
        let c = &b.cs1;
        let (x, y) = (Vector3::from(c.x_axis_world), Vector3::from(c.y_axis_world));
        let r = Rotation3::from_matrix_unchecked(Matrix3::from_columns(&[x, y, x.cross(&y)]));
        let cad = Isometry3::from_parts(Translation3::from(Vector3::from(c.position_world)), UnitQuaternion::from_rotation_matrix(&r));
        let Some(mj) = pose_of(&result, 0, &b.modelica_name) else { panic!("{label}: body {} not in MuJoCo's model", b.modelica_name) };
        let (dp, dr) = off(&cad, &mj);
        assert!(dp <= TOL && dr <= TOL, "{label}: body {} at qpos=0 off the CAD pose by {dp:e} m, {dr:e} rad", b.modelica_name);
        worst = (worst.0.max(dp), worst.1.max(dr));
    }
    if let Some(m) = &mech {
        for (s, u) in us.iter().enumerate() {
            let q: Vec<f64> = m.q0().iter().zip(u).map(|(q0, u)| q0 + u).collect();
            let k = m.forward(&q).expect("fk");
            for (b, name) in m.body_names().iter().enumerate() {
                let ours = m.body_pose(&k, cad2mo_engine::pipeline::ir::BodyId(b as u32)).expect("pose");
                let mj = pose_of(&result, s + 1, name).unwrap_or_else(|| panic!("{label}: body {name} not in MuJoCo's model"));
                let (dp, dr) = off(&ours, &mj);
                assert!(
                    dp <= TOL && dr <= TOL,
                    "{label}: sample {s}, body {name}: MuJoCo at u is {dp:e} m, {dr:e} rad from ours at q0 + u"
                );
                worst = (worst.0.max(dp), worst.1.max(dr));
            }
        }
    }
    println!(
        "{label}: {} bodies, total mass {ours}, {} random configurations; worst {:e} m, {:e} rad (MuJoCo {})",
        out.report.bodies.len(),
        us.len(),
        worst.0,
        worst.1,
        result["mujoco"]
    );
    Some(true)
}

#[test]
fn mujoco_reads_our_urdf_at_the_cad_pose_and_moves_it_as_modelica() {
    let mut cases: Vec<(String, PathBuf, Option<tempfile::TempDir>)> = sorted_dirs(&workspace_root().join("tests/in"))
        .into_iter()
        .filter(|d| !d.file_name().is_some_and(|n| n.to_string_lossy().starts_with("broken")))
        .map(|d| (format!("golden {}", d.file_name().unwrap_or_default().to_string_lossy()), d, None))
        .collect();
    let golden = cases.len();
    if let Some(fx) = fixtures_dir("urdf_out_mujoco") {
        for xml in files_with_ext(&fx.join("xml"), &[".xml"]) {
            let text = std::fs::read_to_string(&xml).unwrap_or_default();
            if !text.contains("<PhysicalModelingXMLFile") {
                continue;
            }
            let (dir, tmp) = fixture_bundle(&xml);
            cases.push((xml.strip_prefix(&fx).unwrap_or(&xml).display().to_string(), dir, tmp));
        }
    }
    let mut checked = 0;
    for (label, dir, _tmp) in &cases {
        match check(label, dir) {
            None => return,
            Some(true) => checked += 1,
            Some(false) => println!("{label}: does not convert; skipped"),
        }
    }
    assert!(checked >= golden.min(10), "only {checked} models checked");
}
