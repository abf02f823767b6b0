use super::*;
use crate::collision::{contacts_at, World};

fn spec(v: serde_json::Value) -> SceneSpec {
    serde_json::from_value(v).expect("scene spec")
}

fn fields(r: Result<Scene, Vec<Issue>>) -> Vec<String> {
    r.expect_err("refused").into_iter().map(|i| i.field).collect()
}

#[test]
fn a_valid_scene_is_checked_into_objects() {
    let s = spec(serde_json::json!({"objects": [
        {"name": "table", "shape": {"kind": "box", "size": [1, 0.5, 0.02]}, "position": [0.5, 0, 0.4]},
        {"name": "conveyor", "shape": {"kind": "box", "size": [0.2, 0.2, 0.2]}, "position": [0, 1, 0], "kind": "moving",
         "motion": {"velocity": [0.1, 0, 0]}},
        {"name": "pallet", "shape": {"kind": "cylinder", "radius": 0.1, "length": 0.05}, "position": [0, 0, 1], "kind": "free", "mass": 2},
        {"name": "floor", "shape": {"kind": "plane"}, "position": [0, 0, 0]},
        {"name": "tool", "shape": {"kind": "capsule", "radius": 0.01, "length": 0.1}, "position": [0, 0, 0.05], "attached_to": "LINK"}
    ]}));
    let s = check(&s, &["LINK".into()]).expect("valid");
    assert_eq!(s.objects.len(), 5);
    assert_eq!(s.objects[1].pose_at(2.0).translation.vector, Vector3::new(0.2, 1.0, 0.0));
    let Kind::Free { inertia, .. } = s.objects[2].kind else { panic!("free") };
    assert!((inertia[2] - 0.5 * 2.0 * 0.01).abs() < 1e-12);
    assert!(s.objects[0].fixed_in_world() && !s.objects[4].fixed_in_world() && !s.objects[1].fixed_in_world());
}

#[test]
fn every_bad_field_is_named() {
    let bodies = ["LINK".to_string()];
    let one = |o: serde_json::Value| fields(check(&spec(serde_json::json!({"objects": [o]})), &bodies));
    let b = |extra: serde_json::Value| {
        let mut o = serde_json::json!({"name": "a", "shape": {"kind": "box", "size": [1, 1, 1]}, "position": [0, 0, 0]});
        for (k, v) in extra.as_object().expect("object") {
            o[k] = v.clone();
        }
        one(o)
    };
    assert_eq!(b(serde_json::json!({"shape": {"kind": "cone"}})), ["objects[0].shape.kind"]);
    assert_eq!(b(serde_json::json!({"shape": {"kind": "box", "size": [1, 0, 1]}})), ["objects[0].shape.size"]);
    assert_eq!(b(serde_json::json!({"shape": {"kind": "box"}})), ["objects[0].shape.size"]);
    assert_eq!(b(serde_json::json!({"shape": {"kind": "sphere", "radius": 1, "length": 2}})), ["objects[0].shape.length"]);
    assert_eq!(b(serde_json::json!({"rotation": [[1, 0, 0], [0, 1, 0], [0, 0.1, 1]]})), ["objects[0].rotation"]);
    assert_eq!(b(serde_json::json!({"rotation": [[1, 0, 0], [0, 1, 0], [0, 0, -1]]})), ["objects[0].rotation"]);
    assert_eq!(b(serde_json::json!({"position": [1e4, 0, 0]})), ["objects[0].position"]);
    assert_eq!(b(serde_json::json!({"rotation": [[1e308, -1e308, 0], [1e308, 1e308, 0], [0, 0, 1]]})), ["objects[0].rotation"]);
    assert_eq!(b(serde_json::json!({"name": "LINK"})), ["objects[0].name"]);
    assert_eq!(b(serde_json::json!({"name": "2bad"})), ["objects[0].name"]);
    assert_eq!(b(serde_json::json!({"kind": "flying"})), ["objects[0].kind"]);
    assert_eq!(b(serde_json::json!({"kind": "free"})), ["objects[0].mass"]);
    assert_eq!(b(serde_json::json!({"kind": "free", "mass": 0})), ["objects[0].mass"]);
    assert_eq!(b(serde_json::json!({"kind": "free", "mass": -2})), ["objects[0].mass"]);
    // Principal moments: positive, and each at most the sum of the other two.
    assert_eq!(b(serde_json::json!({"kind": "free", "mass": 1, "inertia": [0.1, 0.1, 0.3]})), ["objects[0].inertia"]);
    assert_eq!(b(serde_json::json!({"kind": "free", "mass": 1, "inertia": [0.1, 0, 0.1]})), ["objects[0].inertia"]);
    assert_eq!(b(serde_json::json!({"kind": "free", "mass": 1, "inertia": [-0.1, 0.1, 0.1]})), ["objects[0].inertia"]);
    assert!(
        check(
            &spec(serde_json::json!({"objects": [{"name": "a", "shape": {"kind": "box", "size": [1, 1, 1]}, "position": [0, 0, 0],
            "kind": "free", "mass": 1, "inertia": [0.1, 0.1, 0.2]}]})),
            &bodies
        )
        .is_ok(),
        "a flat plate's moments (A + B = C) are physical"
    );
    assert_eq!(b(serde_json::json!({"mass": 1})), ["objects[0].mass"]);
    assert_eq!(b(serde_json::json!({"kind": "moving"})), ["objects[0].motion"]);
    assert_eq!(b(serde_json::json!({"attached_to": "NOPE"})), ["objects[0].attached_to"]);
    assert_eq!(b(serde_json::json!({"color": [2, 0, 0]})), ["objects[0].color"]);
    assert_eq!(
        b(
            serde_json::json!({"kind": "moving", "motion": {"poses": [{"time": 1, "position": [0, 0, 0]}, {"time": 1, "position": [0, 0, 0]}]}})
        ),
        ["objects[0].motion.poses[1].time"]
    );
    let two = spec(serde_json::json!({"objects": [
        {"name": "a", "shape": {"kind": "sphere", "radius": 1}, "position": [0, 0, 0]},
        {"name": "a", "shape": {"kind": "sphere", "radius": 1}, "position": [0, 0, 0]}]}));
    assert_eq!(fields(check(&two, &bodies)), ["objects[1].name"]);
}

#[test]
fn shapes_have_their_size_and_poses_interpolate() {
    let s = spec(serde_json::json!({"objects": [
        {"name": "c", "shape": {"kind": "cylinder", "radius": 0.1, "length": 0.4}, "position": [0, 0, 0]},
        {"name": "p", "shape": {"kind": "sphere", "radius": 0.05}, "position": [0, 0, 0], "kind": "moving",
         "motion": {"poses": [{"time": 0, "position": [0.3, 0, 0]}, {"time": 1, "position": [0.1, 0, 0]}]}},
        {"name": "f", "shape": {"kind": "plane"}, "position": [0, 0, -0.3]}
    ]}));
    let s = check(&s, &[]).expect("valid");
    let world = World::new(&s.objects.iter().map(|o| Some(o.shape())).collect::<Vec<_>>());
    let at = |t: f64| {
        let poses: Vec<_> = s.objects.iter().map(|o| o.pose_at(t)).collect();
        contacts_at(&world, &poses, &|a, b| a == 0 && b == 1, 1.0)
    };
    // Sphere centre 0.3 m away: 0.3 − 0.05 − 0.1 (the prism circumscribes: at most 0.5 % more).
    let d0 = at(0.0)[0].distance;
    assert!((d0 - 0.15).abs() < 0.1 * 0.005 + 1e-9, "{d0}");
    let d = at(0.5)[0].distance;
    assert!((d - 0.05).abs() < 0.1 * 0.005 + 1e-9, "{d}");
    assert_eq!(at(9.0)[0].distance, at(1.0)[0].distance, "held after the last row");
    // The plane's top is its z = 0: the cylinder's bottom (z = -0.2) is 0.1 above it.
    let poses: Vec<_> = s.objects.iter().map(|o| o.pose_at(0.0)).collect();
    let c = contacts_at(&world, &poses, &|a, b| a == 0 && b == 2, 1.0);
    assert!((c[0].distance - 0.1).abs() < 1e-9, "{c:?}");
}

/// A binary STL of the tetrahedron (0,0,0), (a,0,0), (0,a,0), (0,0,a).
fn tetra_stl(a: f32) -> Vec<u8> {
    let p = [[0.0, 0.0, 0.0], [a, 0.0, 0.0], [0.0, a, 0.0], [0.0, 0.0, a]];
    let mesh = crate::pipeline::ir::Mesh { vertices: p.to_vec(), triangles: vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]] };
    crate::pipeline::back::stl::write_binary(&mesh, "t")
}

#[test]
fn mesh_objects_take_their_hull_scaled_by_their_unit_and_ship_their_file() {
    let mut meshes = Meshes::new();
    meshes.insert("tetra".into(), mesh::read("t.stl", &tetra_stl(100.0)).expect("a mesh"));
    assert_eq!(meshes["tetra"].triangles, 4);
    let s = spec(serde_json::json!({"objects": [
        {"name": "wedge", "shape": {"kind": "mesh", "mesh": "tetra", "unit": "mm"}, "position": [1, 0, 0]},
        {"name": "rock", "shape": {"kind": "mesh", "mesh": "tetra", "unit": "in"}, "position": [0, 0, 0], "kind": "free", "mass": 1}
    ]}));
    let s = check_with(&s, &[], &meshes).expect("valid");
    // The hull in metres: the far corners at 0.1 m (mm) and 2.54 m (in).
    let far = |o: &SceneObject| o.shape().parts[0].vertices.iter().flatten().fold(0.0f64, |a, x| a.max(*x));
    assert!((far(&s.objects[0]) - 0.1).abs() < 1e-9 && (far(&s.objects[1]) - 2.54).abs() < 1e-6);
    // Unknown mesh or unit, or no mesh named: refused naming the field.
    for (shape, field) in [
        (serde_json::json!({"kind": "mesh", "mesh": "nope"}), "objects[0].shape.mesh"),
        (serde_json::json!({"kind": "mesh", "mesh": "tetra", "unit": "ft"}), "objects[0].shape.unit"),
        (serde_json::json!({"kind": "mesh"}), "objects[0].shape.mesh"),
    ] {
        let one = spec(serde_json::json!({"objects": [{"name": "x", "shape": shape, "position": [0, 0, 0]}]}));
        assert_eq!(fields(check_with(&one, &[], &meshes)), [field]);
    }
    // The package: one file per mesh, a drawn external shape scaled to metres, MJCF assets
    // (an <asset> added where the model has none) and mesh geoms.
    let files = package::mesh_files(&s, &meshes, "P");
    assert_eq!(files.len(), 1);
    assert_eq!(files[0].0, "P/Resources/Shapes/scene-tetra.stl");
    let m = package::modelica(&s, "P");
    assert!(
        m.declarations.contains("shapeType=\"modelica://P/Resources/Shapes/scene-tetra.stl\"") && m.declarations.contains("length=0.001,")
    );
    let x = package::mjcf("<mujoco>\n  <worldbody>\n  </worldbody>\n</mujoco>\n", &s);
    assert!(x.contains("  <asset>\n    <mesh name=\"scene-wedge\" file=\"scene-tetra.stl\" scale=\"0.001 0.001 0.001\"/>\n"), "{x}");
    assert!(x.find("</asset>").expect("asset") < x.find("<worldbody>").expect("worldbody"), "{x}");
    assert!(x.contains("<geom name=\"rock\" type=\"mesh\" mesh=\"scene-rock\""), "{x}");
    // A flat mesh is refused.
    let flat = crate::pipeline::ir::Mesh { vertices: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], triangles: vec![[0, 1, 2]] };
    assert!(mesh::read("f.stl", &crate::pipeline::back::stl::write_binary(&flat, "f")).expect_err("flat").contains("flat"));
}
