//! Collisions through the REST API on the hand-made arm (three box links): shapes per body, the
//! allowed-collision matrix (defaults from joints, edits by name that survive a new version,
//! refusals naming the pair), interferences at the CAD pose under the matrix, and a motion that
//! swings the fore link into the base (first contact, depth) checked at 1 kHz.

use cad2mo_tests::app::{json_of, zip_dir, TestApp};
use cad2mo_tests::common::workspace_root;
use serde_json::{json, Value};

fn pair<'a>(m: &'a Value, a: &str, b: &str) -> &'a Value {
    m["pairs"]
        .as_array()
        .expect("pairs")
        .iter()
        .find(|p| (p["a"] == a && p["b"] == b) || (p["a"] == b && p["b"] == a))
        .unwrap_or_else(|| panic!("no pair {a}/{b} in {m:#}"))
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn shapes_matrix_interferences_and_motions() {
    let app = TestApp::spawn().await;
    let bundle = zip_dir(&workspace_root().join("tests/in/arm_subsystems"));
    let (id, v, job) = app.upload_model_ok(bundle.clone(), &[]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");

    // Shapes: the three links are boxes (their STL meshes are boxes), the root parts have none.
    let c = json_of(app.get(&format!("/api/models/{id}/versions/{v}/collision")).await, 200).await;
    let kinds: Vec<(String, String)> = c["bodies"]
        .as_array()
        .expect("bodies")
        .iter()
        .map(|b| (b["body"].as_str().expect("b").into(), b["kind"].as_str().expect("k").into()))
        .collect();
    for (body, kind) in &kinds {
        let want = if body.starts_with("RootPart") { "none" } else { "box" };
        assert_eq!(kind, want, "{body}: {c:#}");
    }
    assert_eq!(c["interferences"], json!([]), "joined links may touch at their joints");

    // Defaults: joined links may touch; the base and the fore link are checked.
    let base = format!("/api/models/{id}/collision-matrix");
    let m = json_of(app.get(&base).await, 200).await;
    assert_eq!(m["bodies"], json!(["BASE", "LINK_UPPER", "LINK_FORE"]));
    assert_eq!(pair(&m, "BASE", "LINK_UPPER")["allowed"], true);
    assert!(pair(&m, "BASE", "LINK_UPPER")["why"].as_str().expect("why").contains("BASE_LINK"));
    assert_eq!(pair(&m, "BASE", "LINK_FORE")["allowed"], false);

    // Checking the joined pairs shows where the CAD boxes overlap at their joints.
    let put = |body: Value| app.client.put(app.url(&base)).json(&body).send();
    let m = json_of(put(json!({"pairs": [{"a": "LINK_UPPER", "b": "BASE", "allowed": false}]})).await.expect("put"), 200).await;
    assert_eq!(pair(&m, "BASE", "LINK_UPPER")["custom"], true);
    let c = json_of(app.get(&format!("/api/models/{id}/versions/{v}/collision")).await, 200).await;
    let i = c["interferences"].as_array().expect("interferences");
    assert_eq!(i.len(), 1, "{c:#}");
    assert_eq!((i[0]["a"].as_str(), i[0]["b"].as_str()), (Some("BASE"), Some("LINK_UPPER")));
    let depth = i[0]["depth"].as_f64().expect("depth");
    // The base box's top is at y = 0.09 m; the upper link's box reaches below it.
    assert!(depth > 0.001 && depth < 0.05, "{depth}");
    assert!((i[0]["point_a"][1].as_f64().expect("y") - 0.09).abs() < 1e-9, "{c:#}");
    let gap = i[0]["point_a"][1].as_f64().expect("ya") - i[0]["point_b"][1].as_f64().expect("yb");
    assert!((gap - depth).abs() < 1e-9, "the witness points are `depth` apart along the normal");

    // Refusals name the pair; nothing is stored.
    for (body, what) in [
        (json!({"pairs": [{"a": "BASE", "b": "NOPE", "allowed": true}]}), "NOPE is not a body with a collision shape"),
        (json!({"pairs": [{"a": "BASE", "b": "BASE", "allowed": true}]}), "two bodies"),
        (json!({"pairs": [{"a": "BASE", "b": "RootPart_ARM", "allowed": true}]}), "RootPart_ARM is not a body with a collision shape"),
        (
            json!({"pairs": [{"a": "BASE", "b": "LINK_FORE", "allowed": true}, {"a": "LINK_FORE", "b": "BASE", "allowed": false}]}),
            "given twice",
        ),
    ] {
        let p = json_of(put(body).await.expect("put"), 422).await;
        assert!(p["detail"].as_str().expect("detail").contains(what), "{p:#}");
        assert!(p["errors"][0]["field"].as_str().expect("field").starts_with("pairs["), "{p:#}");
    }
    let p = json_of(put(json!({"pairs": [{"a": "BASE"}]})).await.expect("put"), 400).await;
    assert!(p["detail"].as_str().expect("detail").contains("missing field"), "{p:#}");
    assert_eq!(pair(&json_of(app.get(&base).await, 200).await, "BASE", "LINK_FORE")["custom"], false);

    // Back to the default.
    let m = json_of(put(json!({"pairs": [{"a": "BASE", "b": "LINK_UPPER", "allowed": null}]})).await.expect("put"), 200).await;
    assert_eq!(pair(&m, "BASE", "LINK_UPPER")["custom"], false);

    // A motion that swings the fore link into the base: first contact at about 0.52 s.
    let motion = json!({"name": "swing", "keyframes": [{"kind": "joints", "values": {}}, {"kind": "joints", "values": {"BASE_LINK": 3.0, "LINK_LINK": 2.7}}]});
    let r = app.client.post(app.url(&format!("/api/models/{id}/motions"))).json(&motion).send().await.expect("post");
    let mid = json_of(r, 201).await["id"].as_str().expect("id").to_string();
    let url = format!("/api/models/{id}/motions/{mid}/collisions");
    let s = json_of(app.get(&url).await, 200).await;
    assert_eq!(s["rate_hz"], 1000.0);
    let first = &s["first_contact"];
    assert_eq!((first["a"].as_str(), first["b"].as_str()), (Some("BASE"), Some("LINK_FORE")), "{s:#}");
    let t = first["time"].as_f64().expect("time");
    assert!((0.4..0.7).contains(&t), "{t}");
    let p = pair(&s, "BASE", "LINK_FORE");
    assert!(p["max_depth"].as_f64().expect("depth") > 0.0);
    assert!(p["min_distance"].as_f64().expect("min") < 0.0);
    assert!(s["guarantee"].as_str().expect("guarantee").contains("samples"));
    // The same motion with the pair allowed: nothing is checked.
    json_of(put(json!({"pairs": [{"a": "BASE", "b": "LINK_FORE", "allowed": true}]})).await.expect("put"), 200).await;
    let s = json_of(app.get(&url).await, 200).await;
    assert_eq!(s["first_contact"], Value::Null);
    assert_eq!(s["pairs"], json!([]));

    // A new version keeps the edit (keyed by names); a package regenerated now declares the
    // pair unchecked in its contact model. Its meshes are unchanged: every shape comes from the
    // service's shape cache, none is computed.
    let before = app.shape_cache_stats();
    assert_eq!((before.misses, before.hits), (3, 0), "the first version computed the three links' shapes: {before:?}");
    let (_, v2, job2) = app.upload_version_ok(&id, bundle, &[]).await;
    assert_eq!(app.wait_for_job(&job2).await["status"], "succeeded");
    let after = app.shape_cache_stats();
    assert_eq!((after.misses, after.hits), (3, 3), "the new version computed no shape: {after:?}");
    let m = json_of(app.get(&base).await, 200).await;
    assert_eq!(pair(&m, "BASE", "LINK_FORE")["allowed"], true);
    assert_eq!(pair(&m, "BASE", "LINK_FORE")["custom"], true);
    let zip = app.package(&id, v2).await.bytes().await.expect("zip");
    let mut z = zip::ZipArchive::new(std::io::Cursor::new(zip.to_vec())).expect("zip");
    let mut mech = String::new();
    let name = z.file_names().find(|n| n.ends_with("/Mechatronics.mo")).expect("Mechatronics").to_string();
    std::io::Read::read_to_string(&mut z.by_name(&name).expect("entry"), &mut mech).expect("utf-8");
    assert!(mech.contains("0 of 3 pairs checked"), "no pair is checked now:\n{mech}");
    let mut shape_file = String::new();
    let name = z.file_names().find(|n| n.ends_with("/Resources/Collision/contact.txt")).expect("the shape file").to_string();
    std::io::Read::read_to_string(&mut z.by_name(&name).expect("entry"), &mut shape_file).expect("utf-8");
    let allowed: Vec<&str> = shape_file.lines().filter(|l| l.starts_with("allow ")).collect();
    assert_eq!(allowed, ["allow 1 2", "allow 1 3", "allow 2 3"], "the C code reads every pair as allowed:\n{shape_file}");
    assert!(z.file_names().any(|n| n.ends_with("/Resources/Collision/LINK_FORE.obj")));

    // Unknown things are 404s.
    json_of(app.get(&format!("/api/models/{id}/versions/9/collision")).await, 404).await;
    json_of(app.get(&format!("/api/models/{id}/motions/nope/collisions")).await, 404).await;
    json_of(app.get("/api/models/nope/collision-matrix").await, 404).await;
}

/// A generated three-link arm (box visuals, two revolute joints): the base and the fore link are
/// checked against each other.
fn box_arm() -> Vec<u8> {
    let inertial = r#"<inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>"#;
    let link = |name: &str, z: f64| {
        format!(
            r#"<link name="{name}">{inertial}<visual><origin xyz="0 0 {z}"/><geometry><box size="0.05 0.05 0.2"/></geometry></visual></link>"#
        )
    };
    let joint = |name: &str, parent: &str, child: &str| {
        format!(
            r#"<joint name="{name}" type="revolute"><parent link="{parent}"/><child link="{child}"/><origin xyz="0 0 0.2"/><axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="10" velocity="2"/></joint>"#
        )
    };
    let urdf = format!(
        r#"<robot name="boxarm">{}{}{}{}{}</robot>"#,
        link("base", 0.1),
        link("upper", 0.1),
        link("fore", 0.1),
        joint("shoulder", "base", "upper"),
        joint("elbow", "upper", "fore")
    );
    cad2mo_engine::pipeline::back::bundle::write_zip(&[("boxarm/boxarm.urdf".into(), urdf.into_bytes())]).expect("zip")
}

/// A legal motion too long to check is refused before any sampling, naming the limit; a short
/// one on the same arm is checked.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn motion_checks_have_a_budget() {
    let app = TestApp::spawn().await;
    let (id, _, job) = app.upload_model_ok(box_arm(), &[]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");
    let check = |seconds: f64| {
        let app = &app;
        let id = id.clone();
        async move {
            let motion = json!({"name": format!("hold {seconds}"), "keyframes": [
                {"kind": "joints", "values": {}},
                {"kind": "joints", "values": {"shoulder": 0.5}, "duration": seconds}]});
            let r = app.client.post(app.url(&format!("/api/models/{id}/motions"))).json(&motion).send().await.expect("post");
            let mid = json_of(r, 201).await["id"].as_str().expect("id").to_string();
            let start = std::time::Instant::now();
            let r = app.get(&format!("/api/models/{id}/motions/{mid}/collisions")).await;
            (r, start.elapsed())
        }
    };
    // 700 s at 1 kHz: under the 2 M samples, but 2.1 M body poses (3 bodies).
    let (r, took) = check(700.0).await;
    let p = json_of(r, 422).await;
    let detail = p["detail"].as_str().expect("detail");
    assert!(detail.contains("700001 samples × 3 bodies") && detail.contains("limit of 2000000 body poses"), "{p:#}");
    assert_eq!(p["errors"][0]["field"], "motion", "{p:#}");
    assert!(took < std::time::Duration::from_secs(2), "refused before sampling: {took:?}");
    // 2,100 s: over the trajectory's 2 M samples.
    let p = json_of(check(2100.0).await.0, 422).await;
    assert!(p["detail"].as_str().expect("detail").contains("2100001 samples is more than the limit of 2000000 samples"), "{p:#}");
    // 2 s: checked (one pair: the base and the fore link).
    let s = json_of(check(2.0).await.0, 200).await;
    assert_eq!(s["samples"], 2001, "{s:#}");
    assert_eq!(s["pairs"].as_array().map(Vec::len), Some(1), "{s:#}");
}
