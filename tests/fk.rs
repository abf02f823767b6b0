//! Forward kinematics: from the emitted `Mechanics.mo` alone, recompute every body frame's and
//! centre of gravity's world position and compare with the XML to 1e-9 m.
//!
//! Ground truth comes from two independent sources: the XML scanned by `support/truth.rs`, and
//! for our own cases the poses the fixture generator computed (`tests/in/<case>/expect.json`).

use std::collections::BTreeMap;

use cad2mo_engine::pipeline::Options;
use cad2mo_tests::check::{fk_check, fk_check_with_inertia, nearest_rotation, TOL};
use cad2mo_tests::common::{convert_path, files_with_ext, sorted_dirs, workspace_root};
use cad2mo_tests::truth::{xml_cgs, xml_frames, xml_mass_properties, TruthFrame};
use cad2mo_tests::urdf_truth::{loops_closed, start_values, urdf_truth_at};
use nalgebra::{Matrix3, Vector3};
use serde_json::Value;

fn options(case: &std::path::Path) -> Options {
    let mut o = Options { write_shapes: false, ..Options::default() };
    if let Ok(t) = std::fs::read_to_string(case.join("options.json")) {
        let v: Value = serde_json::from_str(&t).expect("options.json");
        o.lump_welds = v["lump_welds"].as_bool().unwrap_or(false);
    }
    o
}

fn vec3(v: &Value) -> Option<Vector3<f64>> {
    let a = v.as_array()?;
    Some(Vector3::new(a.first()?.as_f64()?, a.get(1)?.as_f64()?, a.get(2)?.as_f64()?))
}

/// Frames from expect.json (the generator's own poses), when present.
fn expected_frames(case: &std::path::Path) -> (BTreeMap<String, TruthFrame>, BTreeMap<String, Vector3<f64>>) {
    let mut frames = BTreeMap::new();
    let mut cgs = BTreeMap::new();
    let Ok(t) = std::fs::read_to_string(case.join("expect.json")) else { return (frames, cgs) };
    let v: Value = serde_json::from_str(&t).expect("expect.json");
    for f in v["frames"].as_array().into_iter().flatten() {
        let (Some(node), Some(p), Some(x), Some(y)) =
            (f["node_id"].as_str(), vec3(&f["position_m"]), vec3(&f["x_axis"]), vec3(&f["y_axis"]))
        else {
            continue;
        };
        let rotation = Matrix3::from_columns(&[x, y, x.cross(&y)]);
        frames.insert(node.to_string(), TruthFrame { position: p, rotation });
    }
    if let Some(m) = v["cg_world_m"].as_object() {
        for (k, p) in m {
            if let Some(p) = vec3(p) {
                cgs.insert(k.clone(), p);
            }
        }
    }
    (frames, cgs)
}

#[test]
fn own_cases_reproduce_cad_pose() {
    let mut checked = 0;
    for case in sorted_dirs(&workspace_root().join("tests/in")) {
        let name = case.file_name().expect("name").to_string_lossy().to_string();
        let Ok(out) = convert_path(&case, &options(&case)) else { continue };
        let stats = if let Some(urdf) = files_with_ext(&case, &[".urdf"]).first() {
            let t = urdf_truth_at(&std::fs::read_to_string(urdf).expect("urdf"), &start_values(&out.report));
            loops_closed(&t).unwrap_or_else(|e| panic!("{name}: {e}"));
            fk_check_with_inertia(&out, &t.frames, &t.cgs, &t.mass).unwrap_or_else(|e| panic!("{name} (URDF truth): {e}"))
        } else {
            let xml = files_with_ext(&case, &[".xml"]);
            let text = std::fs::read_to_string(&xml[0]).expect("xml");
            if cad2mo_tests::xml2_truth::is_second_generation(&text) {
                let t = cad2mo_tests::xml2_truth::scan(&text);
                fk_check_with_inertia(&out, &t.frames, &t.cgs, &t.mass)
                    .unwrap_or_else(|e| panic!("{name} (second-generation XML truth): {e}"))
            } else {
                fk_check_with_inertia(&out, &xml_frames(&text), &xml_cgs(&text), &xml_mass_properties(&text))
                    .unwrap_or_else(|e| panic!("{name} (XML truth): {e}"))
            }
        };
        assert!(stats.frames >= out.report.bodies.len(), "{name}: only {} frames checked", stats.frames);
        let (frames, cgs) = expected_frames(&case);
        if !frames.is_empty() {
            let s2 = fk_check(&out, &frames, &cgs).unwrap_or_else(|e| panic!("{name} (generator truth): {e}"));
            assert!(s2.frames > 0, "{name}: no generator frames matched");
        }
        println!(
            "{name}: {} frames, {} CGs, {} loop checks, max error {:e} m / {:e}",
            stats.frames, stats.cgs, stats.loop_checks, stats.max_position_error, stats.max_rotation_error
        );
        checked += 1;
    }
    assert!(checked >= 7, "only {checked} cases converted");
}

/// The truth scanner and the rotation clean-up agree with a hand-computed frame.
#[test]
fn truth_scanner_reads_columns() {
    let xml = "<Frame ref=\"1\"><name>\"CS2\"</name><nodeID>\"7::CS2\"</nodeID><position>1,2,3</position><positionUnits>\"mm\"</positionUnits><orientation>0,1,0,-1,0,0,0,0,1</orientation></Frame>";
    let f = &xml_frames(xml)["7::CS2"];
    assert!((f.position - Vector3::new(0.001, 0.002, 0.003)).norm() < 1e-15);
    assert_eq!(f.rotation.column(0), Vector3::new(0.0, 1.0, 0.0));
    let r = nearest_rotation(&(f.rotation * 1.000001));
    assert!((r - f.rotation).norm() < TOL);
}

/// The truth scanner resolves frames given relative to a sibling frame and ADJOINING.
#[test]
fn truth_scanner_resolves_relative_frames() {
    let frame = |r: &str, name: &str, node: &str, pos: &str, o: &str, refs: [&str; 3]| {
        format!(
            "<Frame{r}><name>\"{name}\"</name><nodeID>\"{node}\"</nodeID><position>{pos}</position><positionOrigin>\"{}\"</positionOrigin><positionReferenceFrame>\"{}\"</positionReferenceFrame><positionUnits>\"mm\"</positionUnits><orientation>{o}</orientation><orientationReferenceFrame>\"{}\"</orientationReferenceFrame></Frame>",
            refs[0], refs[1], refs[2]
        )
    };
    let (w, rz90, id) = (["WORLD"; 3], "0,1,0,-1,0,0,0,0,1", "1,0,0,0,1,0,0,0,1");
    let xml = format!(
        "<Body><nodeID>\"A\"</nodeID>{}{}</Body><Body><nodeID>\"B\"</nodeID>{}{}</Body><SimpleJoint><base><Frame ref=\"1\"></Frame></base><follower><Frame ref=\"2\"></Frame></follower></SimpleJoint>",
        frame(" ref=\"1\"", "CS1", "a1", "10,0,0", rz90, w),
        frame("", "CG", "acg", "0,0,1", id, ["WORLD", "CS1", "CS1"]),
        frame(" ref=\"2\"", "CS1", "b1", "2,0,0", rz90, ["ADJOINING"; 3]),
        frame("", "CG", "bcg", "1,0,0", id, ["CS1", "WORLD", "WORLD"]),
    );
    let f = xml_frames(&xml);
    let near = |a: Vector3<f64>, b: [f64; 3]| (a - Vector3::from(b) * 1e-3).norm() < 1e-15;
    assert!(near(f["acg"].position, [0.0, 0.0, 1.0]), "{}", f["acg"].position);
    assert!((f["acg"].rotation.column(0) - Vector3::new(0.0, 1.0, 0.0)).norm() < 1e-15);
    // b1: 2 mm along a1's x axis (world y) from a1, turned Rz(90) twice.
    assert!(near(f["b1"].position, [10.0, 2.0, 0.0]), "{}", f["b1"].position);
    assert!((f["b1"].rotation.column(0) - Vector3::new(-1.0, 0.0, 0.0)).norm() < 1e-15);
    assert!(near(f["bcg"].position, [11.0, 2.0, 0.0]), "{}", f["bcg"].position);
    assert!(near(xml_cgs(&xml)["B"], [11.0, 2.0, 0.0]));
}

/// Lumping welded parts: the emitted body's mass, CG and world inertia equal the generator's
/// independently combined values (parallel-axis theorem done in Python).
#[test]
fn lumped_mass_properties_match_the_generator() {
    let case = workspace_root().join("tests/in/lump_welds");
    let out = convert_path(&case, &options(&case)).expect("lump_welds converts");
    let expect: Value = serde_json::from_str(&std::fs::read_to_string(case.join("expect.json")).expect("expect.json")).expect("json");
    let mechanics = cad2mo_tests::common::file_text(&out, "/Mechanics.mo").expect("Mechanics.mo");
    let model = cad2mo_tests::fk::parse_mechanics(&mechanics).expect("parse");
    let poses = cad2mo_tests::fk::forward_kinematics(&model).expect("fk");
    let groups = expect["lumped"].as_array().expect("lumped groups");
    assert!(!groups.is_empty());
    for g in groups {
        let members: Vec<&str> = g["bodies"].as_array().expect("bodies").iter().filter_map(Value::as_str).collect();
        let body = out
            .report
            .bodies
            .iter()
            .find(|b| members.contains(&b.node_id.as_str()) && !b.lumped.is_empty())
            .expect("a lumped body for the group");
        let mut all: Vec<&str> = body.lumped.iter().map(String::as_str).chain([body.node_id.as_str()]).collect();
        all.sort();
        let mut want = members.clone();
        want.sort();
        assert_eq!(all, want, "lumped members");
        let mass = g["mass_kg"].as_f64().expect("mass");
        assert!((body.mass - mass).abs() < 1e-12, "mass {} vs {mass}", body.mass);
        let cg = cad2mo_tests::fk::cg_world(&model, &poses, &body.modelica_name).expect("cg");
        let cg_want = vec3(&g["cg_world_m"]).expect("cg");
        assert!((cg - cg_want).norm() < TOL, "CG {cg:?} vs {cg_want:?}");
        let i = cad2mo_tests::fk::body_inertia_world(&model, &poses, &body.modelica_name).expect("inertia");
        let rows: Vec<f64> = g["inertia_world_kgm2"]
            .as_array()
            .expect("rows")
            .iter()
            .flat_map(|r| r.as_array().expect("row").iter().filter_map(Value::as_f64))
            .collect();
        let want = Matrix3::from_row_slice(&rows);
        let err = (i - want).abs().max() / want.abs().max();
        assert!(err < 1e-9, "inertia differs by {err:e} (relative):\n{i}\n{want}");
    }
}

/// Planar loops are planar in the emitted model, not only in the XML: every revolute of a loop
/// the report calls planar turns about the same world axis to 1e-12 rad (MSL's
/// RevolutePlanarLoopConstraint stops the simulation once its axes drift apart by 1e-10), however
/// noisy the XML's axes and frames are (`sixbar_6digit`, `crank_rocker_noise`).
#[test]
fn planar_loops_have_parallel_axes_in_the_emitted_model() {
    let mut loops = 0;
    for case in sorted_dirs(&workspace_root().join("tests/in")) {
        let name = case.file_name().expect("name").to_string_lossy().to_string();
        let Ok(out) = convert_path(&case, &options(&case)) else { continue };
        let planar: Vec<_> = out.report.loops.iter().filter(|l| l.kind == "planar").collect();
        if planar.is_empty() {
            continue;
        }
        let text = cad2mo_tests::common::file_text(&out, "/Mechanics.mo").expect("Mechanics.mo");
        let model = cad2mo_tests::fk::parse_mechanics(&text).expect("parse");
        let poses = cad2mo_tests::fk::forward_kinematics(&model).expect("fk");
        for l in planar {
            let mut axes = Vec::new();
            for j in &l.joints {
                let joint = out.report.joints.iter().find(|r| &r.modelica_name == j).expect("joint in report");
                for e in joint.elements.iter().filter(|e| e.kind == cad2mo_engine::pipeline::ir::PrimitiveKind::Revolute) {
                    let c = model.component(&e.modelica_name).expect("element component");
                    let Some(cad2mo_tests::fk::Value::Vec(n)) = c.params.get("n") else { panic!("{name}: {} has no n", c.name) };
                    let frame_a = poses.get(&format!("{}.frame_a", c.name)).expect("frame_a reached");
                    axes.push((c.name.clone(), frame_a.rotation * Vector3::new(n[0], n[1], n[2]).normalize()));
                }
            }
            let (first_name, first) = axes[0].clone();
            for (n, a) in &axes {
                let angle = a.cross(&first).norm().atan2(a.dot(&first).abs());
                assert!(angle < 1e-12, "{name}: axis of {n} is {angle:e} rad off {first_name}'s");
            }
            loops += 1;
        }
    }
    assert!(loops >= 5, "only {loops} planar loops checked");
}
