//! VRML geometry: every `tests/in/vrml_*` bundle converts, each body gets the VRML geometry placed
//! for it (the matching rules as the report names them), and the mesh we emit, moved back into
//! the world by the body's CS1 pose, lands exactly where the VRML put it (the generator's own
//! world bounding boxes, `expect.json` `vrml_bbox_m`).

use cad2mo_engine::pipeline::Options;
use cad2mo_tests::common::{convert_path, sorted_dirs, workspace_root};
use nalgebra::{Matrix3, Vector3};
use serde_json::Value;

fn v3(v: &Value) -> Vector3<f64> {
    Vector3::new(v[0].as_f64().unwrap_or(f64::NAN), v[1].as_f64().unwrap_or(f64::NAN), v[2].as_f64().unwrap_or(f64::NAN))
}

/// Vertices of a binary STL.
fn stl_vertices(bytes: &[u8]) -> Vec<Vector3<f64>> {
    let n = u32::from_le_bytes(bytes[80..84].try_into().expect("count")) as usize;
    let f = |o: usize| f32::from_le_bytes(bytes[o..o + 4].try_into().expect("f32")) as f64;
    (0..n).flat_map(|t| (0..3).map(move |k| 84 + t * 50 + 12 + k * 12)).map(|o| Vector3::new(f(o), f(o + 4), f(o + 8))).collect()
}

#[test]
fn vrml_meshes_land_on_the_vrml_geometry() {
    let mut checked = 0;
    for case in sorted_dirs(&workspace_root().join("tests/in")) {
        let name = case.file_name().expect("name").to_string_lossy().to_string();
        if !name.starts_with("vrml_") {
            continue;
        }
        let expect: Value = serde_json::from_str(&std::fs::read_to_string(case.join("expect.json")).expect("expect")).expect("json");
        let out = convert_path(&case, &Options::default()).unwrap_or_else(|e| panic!("{name}: {e}"));
        let report = serde_json::to_value(&out.report).expect("report json");
        let vrml = &report["vrml"];
        assert!(vrml.is_object(), "{name}: no VRML matching in the report");
        if let Some(code) = expect["warning"].as_str() {
            assert!(out.report.warnings.iter().any(|w| w.code == code), "{name}: expected warning {code}");
        }
        for (node, bbox) in expect["vrml_bbox_m"].as_object().expect("bboxes") {
            let body = out.report.bodies.iter().find(|b| &b.node_id == node).expect("body");
            let matches = vrml["bodies"][node].as_array().unwrap_or_else(|| panic!("{name}: body {node} got no VRML geometry"));
            let rule = matches[0]["rule"].as_str().unwrap_or_default();
            match name.as_str() {
                "vrml_twins" => assert_eq!(rule, "name", "{name}: {node}"),
                "vrml_pinned" => assert_eq!(rule, "pinned", "{name}: {node}"),
                _ => assert_eq!(rule, "position", "{name}: {node}"),
            }
            let stl_path = format!("{}.stl", body.shape.as_ref().expect("shape").trim_end_matches(".dxf"));
            let bytes = &*out.files.iter().find(|(p, _)| *p == stl_path).expect("stl written").1.bytes();
            let x = v3(&serde_json::to_value(body.cs1.x_axis_world).expect("x"));
            let y = v3(&serde_json::to_value(body.cs1.y_axis_world).expect("y"));
            let r = Matrix3::from_columns(&[x, y, x.cross(&y)]);
            let p = v3(&serde_json::to_value(body.cs1.position_world).expect("p"));
            let world: Vec<Vector3<f64>> = stl_vertices(bytes).iter().map(|v| r * v + p).collect();
            let lo = world.iter().fold(Vector3::repeat(f64::INFINITY), |a, v| a.inf(v));
            let hi = world.iter().fold(Vector3::repeat(f64::NEG_INFINITY), |a, v| a.sup(v));
            let (want_lo, want_hi) = (v3(&bbox[0]), v3(&bbox[1]));
            let err = (lo - want_lo).abs().max().max((hi - want_hi).abs().max());
            assert!(err < 1e-6, "{name}: body {node}: mesh bounds {lo:?}..{hi:?}, VRML {want_lo:?}..{want_hi:?} (off by {err:e} m)");
            // VRML 97 parts hold two nested shapes of 12 triangles each; VRML 1.0 parts one.
            let want = if name == "vrml_v1" { 12 } else { 24 };
            assert_eq!(body.triangles, want, "{name}: {node}: nested shapes merged");
            checked += 1;
        }
    }
    assert!(checked >= 14, "only {checked} bodies checked");
}
