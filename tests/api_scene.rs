//! Scenes through the REST API (issue 29) on a generated two-link arm: create, read back, edit
//! and delete a scene; every bad input a 422 naming its field; the scene kept by a new CAD
//! version; scene objects named as interferences at the CAD pose, in the allowed-collision
//! matrix and along a motion, with first contact times checked against an independent sampled
//! computation (separating axes on the arm's and the obstacle's rectangles in the swing plane,
//! and the analytic time a conveyor's crate reaches the base).

use cad2mo_tests::app::{json_of, TestApp};
use serde_json::{json, Value};

/// A base box (0.1 × 0.1 × 0.2 m, z 0 .. 0.2) and an arm box (0.04 × 0.04 × 0.4 m, its centre
/// of mass in its middle) on a revolute shoulder about y at z = 0.2, pointing up at q = 0.
fn arm() -> Vec<u8> {
    let inertial = r#"<inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>"#;
    let arm_inertial = inertial.replace("<mass", r#"<origin xyz="0 0 0.2"/><mass"#);
    let urdf = format!(
        r#"<robot name="scenearm">
<link name="base">{inertial}<visual><origin xyz="0 0 0.1"/><geometry><box size="0.1 0.1 0.2"/></geometry></visual></link>
<link name="arm">{arm_inertial}<visual><origin xyz="0 0 0.2"/><geometry><box size="0.04 0.04 0.4"/></geometry></visual></link>
<joint name="shoulder" type="revolute"><parent link="base"/><child link="arm"/><origin xyz="0 0 0.2"/><axis xyz="0 1 0"/>
<limit lower="-3" upper="3" effort="10" velocity="2"/></joint></robot>"#
    );
    cad2mo_engine::pipeline::back::bundle::write_zip(&[("scenearm/scenearm.urdf".into(), urdf.into_bytes())]).expect("zip")
}

/// The rotation about y by `a` (rows).
fn rot_y(a: f64) -> [[f64; 3]; 3] {
    [[a.cos(), 0.0, a.sin()], [0.0, 1.0, 0.0], [-a.sin(), 0.0, a.cos()]]
}

const OBSTACLE_AT: [f64; 3] = [0.35, 0.0, 0.25];
const OBSTACLE_HALF: [f64; 2] = [0.05, 0.05];
const OBSTACLE_TILT: f64 = 0.3;

fn scene(wall_z: f64) -> Value {
    json!({"objects": [
        {"name": "wall", "shape": {"kind": "box", "size": [0.1, 0.3, 0.1]}, "position": [0, 0, wall_z], "color": [0.8, 0.2, 0.2]},
        {"name": "obstacle", "shape": {"kind": "box", "size": [2.0 * OBSTACLE_HALF[0], 0.3, 2.0 * OBSTACLE_HALF[1]]},
         "position": OBSTACLE_AT, "rotation": rot_y(OBSTACLE_TILT)},
        {"name": "crate", "shape": {"kind": "box", "size": [0.1, 0.1, 0.1]}, "position": [-0.5, 0, 0.1], "kind": "moving",
         "motion": {"velocity": [0.5, 0, 0]}},
        {"name": "pallet", "shape": {"kind": "box", "size": [0.2, 0.2, 0.02]}, "position": [2, 0, 0.5], "kind": "free", "mass": 3},
        {"name": "floor", "shape": {"kind": "plane"}, "position": [0, 0, -0.01]},
        {"name": "tool", "shape": {"kind": "sphere", "radius": 0.03}, "position": [0, 0, 0.2], "attached_to": "arm"}
    ]})
}

/// Independent check: do the arm's and the obstacle's rectangles (their sections by the swing
/// plane y = 0; both boxes span y = 0) overlap at shoulder angle `q`? Separating axes.
fn arm_meets_obstacle(q: f64) -> bool {
    // A rotation about y by a maps (x, z) to (x cos a + z sin a, −x sin a + z cos a).
    let turn = |a: f64, v: [f64; 2]| [v[0] * a.cos() + v[1] * a.sin(), -v[0] * a.sin() + v[1] * a.cos()];
    let arm_c = {
        let d = turn(q, [0.0, 0.2]);
        [d[0], 0.2 + d[1]]
    };
    let rects = [
        (arm_c, [turn(q, [1.0, 0.0]), turn(q, [0.0, 1.0])], [0.02, 0.2]),
        ([OBSTACLE_AT[0], OBSTACLE_AT[2]], [turn(OBSTACLE_TILT, [1.0, 0.0]), turn(OBSTACLE_TILT, [0.0, 1.0])], OBSTACLE_HALF),
    ];
    let dot = |a: [f64; 2], b: [f64; 2]| a[0] * b[0] + a[1] * b[1];
    for (_, axes, _) in &rects {
        for n in axes {
            let span = |(c, ax, h): &([f64; 2], [[f64; 2]; 2], [f64; 2])| {
                let m = dot(*c, *n);
                let r = h[0] * dot(ax[0], *n).abs() + h[1] * dot(ax[1], *n).abs();
                (m - r, m + r)
            };
            let (a, b) = (span(&rects[0]), span(&rects[1]));
            if a.1 < b.0 || b.1 < a.0 {
                return false;
            }
        }
    }
    true
}

/// The scene a response holds, compared as the API reads it (defaults filled, 0 = 0.0).
fn same_scene(got: &Value, want: &Value) {
    let read = |v: &Value| serde_json::from_value::<cad2mo_engine::scene::SceneSpec>(v.clone()).expect("a scene");
    assert_eq!(read(got), read(want), "{got:#}");
}

fn pair<'a>(v: &'a Value, a: &str, b: &str) -> Option<&'a Value> {
    v["pairs"].as_array().expect("pairs").iter().find(|p| (p["a"] == a && p["b"] == b) || (p["a"] == b && p["b"] == a))
}

fn interference_names(c: &Value) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = c["interferences"]
        .as_array()
        .expect("interferences")
        .iter()
        .map(|i| {
            let (a, b) = (i["a"].as_str().expect("a").to_string(), i["b"].as_str().expect("b").to_string());
            if a < b {
                (a, b)
            } else {
                (b, a)
            }
        })
        .collect();
    out.sort();
    out
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn scenes_are_stored_checked_and_collide() {
    let app = TestApp::spawn().await;
    let (id, v, job) = app.upload_model_ok(arm(), &[]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");
    let url = format!("/api/models/{id}/scene");
    let put = |body: Value| app.client.put(app.url(&url)).json(&body).send();

    // Empty at first; the model's bodies are base and arm.
    assert_eq!(json_of(app.get(&url).await, 200).await, json!({"objects": []}));
    let m = json_of(app.get(&format!("/api/models/{id}/collision-matrix")).await, 200).await;
    assert_eq!(m["bodies"], json!(["base", "arm"]), "{m:#}");

    // Create and read back (defaults left out, the given values kept).
    let stored = json_of(put(scene(0.55)).await.expect("put"), 200).await;
    same_scene(&stored, &scene(0.55));
    same_scene(&json_of(app.get(&url).await, 200).await, &scene(0.55));

    // The CAD pose: the wall across the arm's top is an interference; the obstacle is clear of
    // the upright arm; the tool (attached to the arm, inside it) and objects fixed in the world
    // are allowed by default.
    let collision = format!("/api/models/{id}/versions/{v}/collision");
    let c = json_of(app.get(&collision).await, 200).await;
    assert_eq!(interference_names(&c), [("arm".to_string(), "wall".to_string())], "{c:#}");
    let depth = c["interferences"][0]["depth"].as_f64().expect("depth");
    // The arm's top is at z = 0.6, the wall's bottom at 0.5; sideways the arm (±0.02) is inside the wall (±0.05).
    assert!((depth - 0.07).abs() < 1e-6 || (depth - 0.1).abs() < 1e-6, "depth {depth}: {c:#}");
    let m = json_of(app.get(&format!("/api/models/{id}/collision-matrix")).await, 200).await;
    assert_eq!(m["bodies"], json!(["base", "arm", "wall", "obstacle", "crate", "pallet", "floor", "tool"]), "{m:#}");
    let tool = pair(&m, "arm", "tool").expect("arm/tool");
    assert_eq!(tool["allowed"], true);
    assert!(tool["why"].as_str().expect("why").contains("attached"), "{tool:#}");
    assert_eq!(pair(&m, "wall", "floor").expect("wall/floor")["allowed"], true);
    assert_eq!(pair(&m, "crate", "floor").expect("crate/floor")["allowed"], false);
    assert_eq!(pair(&m, "arm", "obstacle").expect("arm/obstacle")["allowed"], false);
    // The base stands on the floor (touching is not an interference); allowing a pair by name
    // removes it from the checks.
    let mp = format!("/api/models/{id}/collision-matrix");
    let r = app.client.put(app.url(&mp)).json(&json!({"pairs": [{"a": "wall", "b": "arm", "allowed": true}]})).send().await.expect("put");
    json_of(r, 200).await;
    assert_eq!(interference_names(&json_of(app.get(&collision).await, 200).await), Vec::<(String, String)>::new());
    let r = app.client.put(app.url(&mp)).json(&json!({"pairs": [{"a": "wall", "b": "arm", "allowed": null}]})).send().await.expect("put");
    json_of(r, 200).await;

    // Edit: the wall moved up out of reach, no interference left.
    json_of(put(scene(0.9)).await.expect("put"), 200).await;
    assert_eq!(interference_names(&json_of(app.get(&collision).await, 200).await), Vec::<(String, String)>::new());

    // A motion swinging the arm through the obstacle.
    let motion = json!({"name": "swing", "keyframes": [{"kind": "joints", "values": {}}, {"kind": "joints", "values": {"shoulder": 2.0}}]});
    let r = app.client.post(app.url(&format!("/api/models/{id}/motions"))).json(&motion).send().await.expect("post");
    let mid = json_of(r, 201).await["id"].as_str().expect("id").to_string();
    let s = json_of(app.get(&format!("/api/models/{id}/motions/{mid}/collisions")).await, 200).await;
    assert_eq!(s["rate_hz"], 1000.0);
    let guarantee = s["guarantee"].as_str().expect("guarantee");
    let hit = pair(&s, "arm", "obstacle").unwrap_or_else(|| panic!("arm/obstacle checked: {s:#}"));
    let t_api = hit["first_contact"].as_f64().unwrap_or_else(|| panic!("the arm hits the obstacle: {s:#}"));
    // The independent computation on the same 1 kHz samples of the motion.
    let tr = json_of(app.get(&format!("/api/models/{id}/motions/{mid}/trajectory?rate=1000")).await, 200).await;
    let times: Vec<f64> = serde_json::from_value(tr["t"].clone()).expect("t");
    let q: Vec<f64> = serde_json::from_value(tr["q"][0].clone()).expect("q");
    let k = q.iter().position(|&a| arm_meets_obstacle(a)).expect("the swing meets the obstacle");
    let t_own = times[k];
    // The sweep's guarantee: first contact is exact over the samples (every sample where a
    // checked pair touches is evaluated); one sample either way for a touch within rounding.
    assert!((t_api - t_own).abs() <= 1.0e-3 + 1e-9, "first contact {t_api} s, independent {t_own} s; {guarantee}");
    assert!(t_own > 0.05 && t_own < times[times.len() - 1], "{t_own}");
    println!("arm/obstacle first contact: the API {t_api} s, the independent check {t_own} s");
    // The crate on its conveyor (0.5 m/s from x = -0.5) reaches the base (x = -0.05) at 0.8 s.
    let c = pair(&s, "base", "crate").unwrap_or_else(|| panic!("base/crate: {s:#}"));
    let t_crate = c["first_contact"].as_f64().unwrap_or_else(|| panic!("the crate reaches the base: {s:#}"));
    assert!((t_crate - 0.8).abs() <= 1.0e-3 + 1e-9, "crate contact at {t_crate} s");
    assert!(times[times.len() - 1] > 0.8, "the motion lasts past the crate's arrival");
    println!("base/crate first contact: the API {t_crate} s, analytic 0.8 s");
    // The tool moves with the arm: nearer the obstacle than the arm's root, never checked
    // against the arm.
    assert!(pair(&s, "arm", "tool").is_none(), "{s:#}");
    assert!(pair(&s, "obstacle", "tool").is_some(), "{s:#}");

    // The closed-loop simulation checks the simulated motion: the arm, let go at 0.3 rad, falls
    // under gravity through the obstacle, and the crate arrives meanwhile. Its first contacts
    // are the independent check's on the run's stored samples.
    let body = json!({"duration": 1.0, "drives": false, "start": {"shoulder": 0.3}});
    let r = app.client.post(app.url(&format!("/api/models/{id}/simulations"))).json(&body).send().await.expect("simulate");
    let sim = json_of(r, 201).await;
    let c = &sim["collisions"];
    let contact = |a: &str, b: &str| {
        c["contacts"].as_array().expect("contacts").iter().find(|p| (p["a"] == a && p["b"] == b) || (p["a"] == b && p["b"] == a)).cloned()
    };
    let rid = sim["result_id"].as_str().expect("result");
    let series = json_of(app.get(&format!("/api/results/{rid}/series?name=shoulder.phi&width=10000")).await, 200).await;
    let times: Vec<f64> = serde_json::from_value(series["variables"][0]["t"].clone()).expect("t");
    let q: Vec<f64> = serde_json::from_value(series["variables"][0]["y"].clone()).expect("q");
    let t_sim = contact("arm", "obstacle")
        .unwrap_or_else(|| panic!("the falling arm meets the obstacle: {c:#}, q {:?}", q.iter().step_by(200).collect::<Vec<_>>()))
        ["first_contact"]
        .as_f64()
        .expect("time");
    assert_eq!(times.len(), c["samples"].as_u64().expect("samples") as usize, "{c:#}");
    let k = q.iter().position(|&a| arm_meets_obstacle(a)).expect("the fall meets the obstacle");
    let step = times[1] - times[0];
    assert!((t_sim - times[k]).abs() <= step + 1e-9, "first contact {t_sim} s, independent {} s; {}", times[k], c["guarantee"]);
    assert!(times[k] > 0.05 && q[0] == 0.3, "it falls from 0.3 rad: {} s, q0 {}", times[k], q[0]);
    let t_crate =
        contact("base", "crate").unwrap_or_else(|| panic!("the crate reaches the base: {c:#}"))["first_contact"].as_f64().expect("t");
    assert!((t_crate - 0.8).abs() <= step + 1e-9, "crate contact at {t_crate} s");
    let first = c["first_contact"]["time"].as_f64().expect("first contact");
    assert!(first <= t_sim.min(t_crate), "{c:#}");
    assert_eq!(sim["ok"], false, "a contact fails the verdict: {sim:#}");
    assert!(sim["reasons"].as_array().expect("reasons").iter().any(|r| r.as_str().expect("reason").contains("touches")), "{sim:#}");
    println!("simulated fall: arm/obstacle first contact {t_sim} s (independent {} s), base/crate {t_crate} s", times[k]);

    // A new CAD version keeps the scene (keyed by names); its interference view names it.
    json_of(put(scene(0.55)).await.expect("put"), 200).await;
    let (_, v2, job2) = app.upload_version_ok(&id, arm(), &[]).await;
    assert_eq!(app.wait_for_job(&job2).await["status"], "succeeded");
    // The job wrote the stored scene into the new version's package: Mechatronics and MJCF.
    let zip = app.package(&id, v2).await.bytes().await.expect("zip");
    let mut z = zip::ZipArchive::new(std::io::Cursor::new(zip.to_vec())).expect("zip");
    let mut read = |suffix: &str| -> String {
        let name = z.file_names().find(|n| n.ends_with(suffix)).unwrap_or_else(|| panic!("no {suffix}")).to_string();
        let mut s = String::new();
        std::io::Read::read_to_string(&mut z.by_name(&name).expect("entry"), &mut s).expect("utf-8");
        s
    };
    let mech = read("/Mechatronics.mo");
    for needle in
        ["scene_wall_shape(", "Parts.Body scene_pallet(m=3.0,", "\"scene_crate\"", "connect(arm.frame_a, scene_tool_frame.frame_a);"]
    {
        assert!(mech.contains(needle), "the package's Mechatronics.mo lacks {needle}");
    }
    let mjcf = read(".mjcf.xml");
    assert!(mjcf.contains("<body name=\"pallet\"") && mjcf.contains("<freejoint name=\"pallet_free\"/>"), "{mjcf}");
    assert!(mjcf.contains("<geom name=\"wall\" type=\"box\""), "{mjcf}");
    same_scene(&json_of(app.get(&url).await, 200).await, &scene(0.55));
    let c = json_of(app.get(&format!("/api/models/{id}/versions/{v2}/collision")).await, 200).await;
    assert_eq!(interference_names(&c), [("arm".to_string(), "wall".to_string())], "{c:#}");

    // Delete: nothing left, nothing collides.
    let r = app.client.delete(app.url(&url)).send().await.expect("delete");
    assert_eq!(r.status().as_u16(), 204);
    assert_eq!(json_of(app.get(&url).await, 200).await, json!({"objects": []}));
    assert_eq!(interference_names(&json_of(app.get(&collision).await, 200).await), Vec::<(String, String)>::new());

    // Unknown models are 404s.
    json_of(app.get("/api/models/nope/scene").await, 404).await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bad_scenes_are_422s_naming_the_field() {
    let app = TestApp::spawn().await;
    let (id, _, job) = app.upload_model_ok(arm(), &[]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");
    let url = format!("/api/models/{id}/scene");
    json_of(app.client.put(app.url(&url)).json(&scene(0.55)).send().await.expect("put"), 200).await;
    let one = |o: Value| json!({"objects": [o]});
    let good = || json!({"name": "b", "shape": {"kind": "box", "size": [0.1, 0.1, 0.1]}, "position": [0, 0, 1]});
    let with = |k: &str, v: Value| {
        let mut o = good();
        o[k] = v;
        one(o)
    };
    let two = json!({"objects": [good(), good()]});
    let cases = [
        (with("shape", json!({"kind": "cone", "radius": 1})), "objects[0].shape.kind", "unknown shape kind"),
        (with("shape", json!({"kind": "box", "size": [0.1, -1, 0.1]})), "objects[0].shape.size", "outside"),
        (with("shape", json!({"kind": "sphere"})), "objects[0].shape.radius", "required"),
        (with("shape", json!({"kind": "cylinder", "radius": 0.1, "length": 0.2, "size": [1, 1, 1]})), "objects[0].shape.size", "no size"),
        (with("rotation", json!([[1, 0, 0], [0, 1, 0.2], [0, 0, 1]])), "objects[0].rotation", "not orthonormal"),
        (with("rotation", json!([[1, 0, 0], [0, 1, 0], [0, 0, -1]])), "objects[0].rotation", "reflection"),
        (with("rotation", json!([[1, 0, 0], [0, 1, 0]])), "objects[0].rotation", "invalid length"),
        (with("position", json!("here")), "objects[0].position", "invalid type"),
        (with("position", json!([5000, 0, 0])), "objects[0].position", "within"),
        (two, "objects[1].name", "given twice"),
        (with("name", json!("arm")), "objects[0].name", "is a body of the model"),
        (with("name", json!("a b")), "objects[0].name", "not a valid name"),
        (with("kind", json!("floating")), "objects[0].kind", "unknown kind"),
        (with("kind", json!("free")), "objects[0].mass", "needs its mass"),
        (with("kind", json!("moving")), "objects[0].motion", "needs its motion"),
        (with("attached_to", json!("nope")), "objects[0].attached_to", "not a body"),
        (with("color", json!([0, 0, 3])), "objects[0].color", "within 0 .. 1"),
        (with("surprise", json!(1)), "objects[0].surprise", "unknown field"),
        (json!({"objects": [good()], "x": 1}), "x", "unknown field"),
        (json!([1]), "scene", "JSON object"),
        (json!({}), "scene", "missing field `objects`"),
    ];
    for (body, field, what) in cases {
        let r = app.client.put(app.url(&url)).json(&body).send().await.expect("put");
        let p = json_of(r, 422).await;
        assert_eq!(p["errors"][0]["field"], field, "{body}: {p:#}");
        assert!(p["errors"][0]["message"].as_str().expect("message").contains(what), "{body}: {p:#}");
    }
    // Too many objects.
    let many: Vec<Value> =
        (0..257).map(|i| json!({"name": format!("o{i}"), "shape": {"kind": "sphere", "radius": 0.1}, "position": [0, 0, 0]})).collect();
    let p = json_of(app.client.put(app.url(&url)).json(&json!({"objects": many})).send().await.expect("put"), 422).await;
    assert_eq!(p["errors"][0]["field"], "objects", "{p:#}");
    // Nothing of it was stored.
    same_scene(&json_of(app.get(&url).await, 200).await, &scene(0.55));
}

/// An ASCII STL cube of edge `edge` (file units) centred on the origin: 12 triangles.
fn cube_stl(edge: f64) -> String {
    let h = edge / 2.0;
    let c = |i: usize| [if i & 1 != 0 { h } else { -h }, if i & 2 != 0 { h } else { -h }, if i & 4 != 0 { h } else { -h }];
    // Each face as two triangles of corner indices (outward winding).
    let faces = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
    let mut s = String::from("solid cube\n");
    for f in faces {
        for t in [[f[0], f[1], f[2]], [f[0], f[2], f[3]]] {
            s += "facet normal 0 0 0\nouter loop\n";
            for k in t {
                let p = c(k);
                s += &format!("vertex {} {} {}\n", p[0], p[1], p[2]);
            }
            s += "endloop\nendfacet\n";
        }
    }
    s + "endsolid cube\n"
}

/// A VRML 97 file: a 0.1 × 0.2 × 0.3 box scaled by 2 at x = 1 (12 triangles) and a unit
/// tetrahedron moved to z = −1 (4 triangles). Bounds: x 0 .. 1.1, y −0.2 .. 1, z −1 .. 0.3.
const VRML: &str = "#VRML V2.0 utf8
Transform { translation 1 0 0 scale 2 2 2 children [ Shape { geometry Box { size 0.1 0.2 0.3 } } ] }
Transform { translation 0 0 -1 children [ Shape { geometry IndexedFaceSet {
  coord Coordinate { point [ 0 0 0, 1 0 0, 0 1 0, 0 0 1 ] }
  coordIndex [ 0 2 1 -1, 0 1 3 -1, 0 3 2 -1, 1 2 3 -1 ] } } ] }
";

/// A COLLADA tetrahedron in millimetres, Y up: corners 0, 100 mm on x, 200 mm on y, 300 mm on z,
/// so in metres, Z up ((x, y, z) → (x, −z, y)): x 0 .. 0.1, y −0.3 .. 0, z 0 .. 0.2.
const COLLADA: &str = r##"<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<asset><unit name="millimeter" meter="0.001"/><up_axis>Y_UP</up_axis></asset>
<library_geometries><geometry id="t"><mesh>
<source id="t-pos"><float_array id="t-arr" count="12">0 0 0 100 0 0 0 200 0 0 0 300</float_array>
<technique_common><accessor source="#t-arr" count="4" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>
<vertices id="t-v"><input semantic="POSITION" source="#t-pos"/></vertices>
<triangles count="4"><input semantic="VERTEX" source="#t-v" offset="0"/>
<p>0 2 1 0 1 3 0 3 2 1 2 3</p></triangles>
</mesh></geometry></library_geometries>
<library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#t"/></node></visual_scene></library_visual_scenes>
<scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
"##;

/// The stored binary STL of a scene mesh.
async fn stored_stl(app: &TestApp, id: &str, name: &str) -> Vec<u8> {
    let r = app.get(&format!("/api/models/{id}/scene/meshes/{name}")).await;
    assert_eq!(r.status().as_u16(), 200);
    r.bytes().await.expect("stl").to_vec()
}

/// The bounds of a binary STL's corners equal `lo` .. `hi` (to f32 rounding).
fn assert_bounds(stl: &[u8], lo: [f64; 3], hi: [f64; 3]) {
    let n = u32::from_le_bytes(stl[80..84].try_into().expect("count")) as usize;
    assert_eq!(stl.len(), 84 + 50 * n);
    let (mut a, mut b) = ([f64::MAX; 3], [f64::MIN; 3]);
    for k in 0..n {
        for c in 0..3 {
            for i in 0..3 {
                let o = 84 + 50 * k + 12 + 12 * c + 4 * i;
                let x = f32::from_le_bytes(stl[o..o + 4].try_into().expect("f32")) as f64;
                a[i] = a[i].min(x);
                b[i] = b[i].max(x);
            }
        }
    }
    let close = |x: [f64; 3], y: [f64; 3]| x.iter().zip(y).all(|(p, q)| (p - q).abs() < 1e-6);
    assert!(close(a, lo) && close(b, hi), "bounds {a:?} .. {b:?}, expected {lo:?} .. {hi:?}");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn mesh_objects_are_uploaded_collide_and_ship() {
    let app = TestApp::spawn().await;
    let (id, _, job) = app.upload_model_ok(arm(), &[]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");
    let mesh_url = |name: &str, file: &str| app.url(&format!("/api/models/{id}/scene/meshes/{name}?file={file}"));
    let upload =
        |name: &str, file: &str, body: Vec<u8>| app.client.put(mesh_url(name, file)).header("X-Requested-With", "cad2mo").body(body).send();

    // Upload a cube of 100 mm (ASCII STL) and a tetrahedron (OBJ); read them back.
    let r = json_of(upload("block", "block.stl", cube_stl(100.0).into_bytes()).await.expect("put"), 200).await;
    assert_eq!(r, json!({"name": "block", "triangles": 12}));
    let obj = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n".to_vec();
    json_of(upload("tetra", "tetra.obj", obj).await.expect("put"), 200).await;
    let list = json_of(app.get(&format!("/api/models/{id}/scene/meshes")).await, 200).await;
    assert_eq!(list, json!({"meshes": [{"name": "block", "triangles": 12}, {"name": "tetra", "triangles": 4}]}));
    // Each mesh's file as stored (the 3D view draws it): a binary STL of its triangles, in the
    // file's own units (the cube's corners at ±50 mm); an unknown mesh is a 404.
    let r = app.get(&format!("/api/models/{id}/scene/meshes/block")).await;
    assert_eq!(r.status().as_u16(), 200);
    assert_eq!(r.headers()["content-type"], "model/stl");
    let stl = r.bytes().await.expect("stl");
    assert_eq!(stl.len(), 84 + 12 * 50, "a binary STL of 12 triangles");
    assert_eq!(u32::from_le_bytes(stl[80..84].try_into().expect("count")), 12);
    let coords: Vec<f32> = (0..12)
        .flat_map(|k| (0..9).map(move |i| 84 + 50 * k + 12 + 4 * i))
        .map(|o| f32::from_le_bytes(stl[o..o + 4].try_into().expect("f32")))
        .collect();
    assert!(coords.iter().all(|c| c.abs() == 50.0), "the cube's corners at ±50 (mm, as uploaded): {coords:?}");
    assert_eq!(app.get(&format!("/api/models/{id}/scene/meshes/nope")).await.status().as_u16(), 404);

    // Bad uploads: 422 naming the file or the name; too big: 413.
    let p =
        json_of(upload("bad", "bad.stl", b"solid x\nfacet normal 0 0 0\nouter loop\nvertex 1 2\n".to_vec()).await.expect("put"), 422).await;
    assert_eq!(p["errors"][0]["field"], "file", "{p:#}");
    let p = json_of(upload("flat", "flat.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n".to_vec()).await.expect("put"), 422).await;
    assert_eq!(p["errors"][0]["field"], "file", "{p:#}");
    assert!(p["errors"][0]["message"].as_str().expect("message").contains("flat"), "{p:#}");
    let p = json_of(upload("v", "v.wrl", cube_stl(1.0).into_bytes()).await.expect("put"), 422).await;
    assert_eq!(p["errors"][0]["field"], "file", "{p:#}");
    let p = json_of(upload("9lives", "c.stl", cube_stl(1.0).into_bytes()).await.expect("put"), 422).await;
    assert_eq!(p["errors"][0]["field"], "name", "{p:#}");
    // VRML and COLLADA: the file's shapes placed by their transforms (VRML) or in metres, Z up
    // (COLLADA's <unit> and <up_axis> applied); the stored STL's bounds say so.
    let r = json_of(upload("vrml", "parts.wrl", VRML.as_bytes().to_vec()).await.expect("put"), 200).await;
    assert_eq!(r, json!({"name": "vrml", "triangles": 16}));
    assert_bounds(&stored_stl(&app, &id, "vrml").await, [0.0, -0.2, -1.0], [1.1, 1.0, 0.3]);
    let r = json_of(upload("dae", "tetra.dae", COLLADA.as_bytes().to_vec()).await.expect("put"), 200).await;
    assert_eq!(r, json!({"name": "dae", "triangles": 4}));
    assert_bounds(&stored_stl(&app, &id, "dae").await, [0.0, -0.3, 0.0], [0.1, 0.0, 0.2]);
    // Without ?file= the body's first bytes choose the reader.
    let r = app.client.put(app.url(&format!("/api/models/{id}/scene/meshes/sniffed"))).header("X-Requested-With", "cad2mo");
    json_of(r.body(COLLADA.as_bytes().to_vec()).send().await.expect("put"), 200).await;
    assert_bounds(&stored_stl(&app, &id, "sniffed").await, [0.0, -0.3, 0.0], [0.1, 0.0, 0.2]);
    // A bad file of each: 422 naming the file, with the file name and line in the message (VRML:
    // the IndexedFaceSet holding the bad index; COLLADA: its <p>).
    let bad_vrml = VRML.replace("0 1 3 -1", "0 1 9 -1");
    let p = json_of(upload("bad", "bad.wrl", bad_vrml.into_bytes()).await.expect("put"), 422).await;
    assert_eq!(p["errors"][0]["field"], "file", "{p:#}");
    let m = p["errors"][0]["message"].as_str().expect("message");
    assert!(m.starts_with("bad.wrl:3:") && m.contains("coordIndex 9 is out of range"), "{p:#}");
    let bad_dae = COLLADA.replace("0 3 2 1", "0 3 7 1");
    let p = json_of(upload("bad", "bad.dae", bad_dae.into_bytes()).await.expect("put"), 422).await;
    assert_eq!(p["errors"][0]["field"], "file", "{p:#}");
    let m = p["errors"][0]["message"].as_str().expect("message");
    assert!(m.starts_with("bad.dae:9:") && m.contains("out of range"), "{p:#}");
    let big = vec![b' '; cad2mo_engine::scene::mesh::MAX_MESH_BYTES + 1];
    assert_eq!(upload("big", "big.stl", big).await.expect("put").status().as_u16(), 413);

    // A mesh object at the arm's top, in mm: the cube spans z 0.55 .. 0.65, the arm reaches
    // 0.6, so they overlap by 0.05 m upwards (sideways by 0.07 m): an interference of depth 0.05.
    let url = format!("/api/models/{id}/scene");
    let block = |mesh: &str, unit: &str| json!({"objects": [{"name": "block", "shape": {"kind": "mesh", "mesh": mesh, "unit": unit}, "position": [0, 0, 0.6]}]});
    let stored = json_of(app.client.put(app.url(&url)).json(&block("block", "mm")).send().await.expect("put"), 200).await;
    same_scene(&stored, &block("block", "mm"));
    let collision = |v: i64| format!("/api/models/{id}/versions/{v}/collision");
    let c = json_of(app.get(&collision(1)).await, 200).await;
    assert_eq!(interference_names(&c), [("arm".to_string(), "block".to_string())], "{c:#}");
    let depth = c["interferences"][0]["depth"].as_f64().expect("depth");
    assert!((depth - 0.05).abs() < 1e-6, "depth {depth}: {c:#}");

    // Bad mesh objects: 422 naming the field.
    for (body, field) in [
        (block("nope", "mm"), "objects[0].shape.mesh"),
        (block("block", "furlong"), "objects[0].shape.unit"),
        (json!({"objects": [{"name": "b", "shape": {"kind": "mesh"}, "position": [0, 0, 0]}]}), "objects[0].shape.mesh"),
        (
            json!({"objects": [{"name": "b", "shape": {"kind": "box", "size": [1, 1, 1], "unit": "mm"}, "position": [0, 0, 0]}]}),
            "objects[0].shape.unit",
        ),
    ] {
        let p = json_of(app.client.put(app.url(&url)).json(&body).send().await.expect("put"), 422).await;
        assert_eq!(p["errors"][0]["field"], field, "{body}: {p:#}");
    }

    // The package of a new version holds the mesh file, Mechatronics draws it, the MJCF has a
    // mesh asset scaled to metres and a mesh geom.
    let (_, v2, job2) = app.upload_version_ok(&id, arm(), &[]).await;
    assert_eq!(app.wait_for_job(&job2).await["status"], "succeeded");
    let zip = app.package(&id, v2).await.bytes().await.expect("zip");
    let mut z = zip::ZipArchive::new(std::io::Cursor::new(zip.to_vec())).expect("zip");
    let stl_name = z.file_names().find(|n| n.ends_with("/Resources/Shapes/scene-block.stl")).expect("the mesh file").to_string();
    let mut stl = Vec::new();
    std::io::Read::read_to_end(&mut z.by_name(&stl_name).expect("entry"), &mut stl).expect("read");
    assert_eq!(stl.len(), 84 + 12 * 50, "a binary STL of 12 triangles");
    let mut read = |suffix: &str| -> String {
        let name = z.file_names().find(|n| n.ends_with(suffix)).unwrap_or_else(|| panic!("no {suffix}")).to_string();
        let mut s = String::new();
        std::io::Read::read_to_string(&mut z.by_name(&name).expect("entry"), &mut s).expect("utf-8");
        s
    };
    let mech = read("/Mechatronics.mo");
    assert!(mech.contains("/Resources/Shapes/scene-block.stl\"") && mech.contains("length=0.001, width=0.001, height=0.001"), "{mech}");
    let mjcf = read(".mjcf.xml");
    assert!(mjcf.contains("<mesh name=\"scene-block\" file=\"scene-block.stl\" scale=\"0.001 0.001 0.001\"/>"), "{mjcf}");
    assert!(mjcf.contains("<geom name=\"block\" type=\"mesh\" mesh=\"scene-block\""), "{mjcf}");
    let c = json_of(app.get(&collision(v2)).await, 200).await;
    assert_eq!(interference_names(&c), [("arm".to_string(), "block".to_string())], "{c:#}");
}
