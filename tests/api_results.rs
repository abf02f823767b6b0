//! Simulation results through the REST API: a result of the generated 6-axis arm (joint angles
//! only, as filtered result files are) uploaded to its version; poses from our kinematics, at the
//! CAD pose where the file's joints are at their start values; variables, series, refusals.

use cad2mo_engine::results::write::trajectory;
use cad2mo_tests::app::{json_of, TestApp};
use serde_json::Value;

#[path = "../engine/benches/support/gen.rs"]
#[allow(dead_code)]
mod gen;

async fn upload(app: &TestApp, path: &str, name: &str, bytes: Vec<u8>) -> reqwest::Response {
    let part = reqwest::multipart::Part::bytes(bytes).file_name(name.to_string());
    let form = reqwest::multipart::Form::new().part("file", part);
    app.client.post(app.url(path)).multipart(form).send().await.expect("upload")
}

fn f32_at(b: &[u8], k: usize) -> f64 {
    f64::from(f32::from_le_bytes([b[k], b[k + 1], b[k + 2], b[k + 3]]))
}

#[tokio::test]
async fn results_upload_poses_series_and_refusals() {
    let app = TestApp::spawn().await;
    let zip =
        cad2mo_engine::pipeline::back::bundle::write_zip(&[("arm.xml".to_string(), gen::serial_arm_xml(6).into_bytes())]).expect("zip");
    let (id, _, job) = app.upload_model_ok(zip, &[]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");
    let joints = json_of(app.get(&format!("/api/models/{id}/joints")).await, 200).await;
    let names: Vec<(String, f64)> = joints["joints"]
        .as_array()
        .expect("joints")
        .iter()
        .map(|j| (j["name"].as_str().expect("name").to_string(), j["q0"].as_f64().expect("q0")))
        .collect();

    // Joint angles over 2 s: at t = 0 every joint is at its start value (the CAD pose), then
    // joint 1 turns at 0.5 rad/s.
    let time: Vec<f64> = (0..=200).map(|i| f64::from(i) * 0.01).collect();
    let series: Vec<(String, Vec<f64>)> = names
        .iter()
        .enumerate()
        .map(|(k, (n, q0))| (format!("{n}.phi"), time.iter().map(|t| if k == 0 { q0 + 0.5 * t } else { *q0 }).collect()))
        .collect();
    let base = format!("/api/models/{id}/versions/1/results");
    let r = upload(&app, &base, "arm_res.mat", trajectory(&time, &series, false)).await;
    let res = json_of(r, 201).await;
    let rid = res["id"].as_str().expect("id").to_string();
    assert_eq!((res["variables"].as_u64(), res["instants"].as_u64()), (Some(7), Some(201)));
    assert_eq!((res["start"].as_f64(), res["stop"].as_f64(), res["precision"].as_str()), (Some(0.0), Some(2.0), Some("float64")));
    assert_eq!(res["from_frames"].as_array().map(Vec::len), Some(0));
    let bodies: Vec<String> = res["bodies"].as_array().expect("bodies").iter().map(|b| b.as_str().expect("b").to_string()).collect();
    assert_eq!(res["from_joints"].as_array().map(Vec::len), Some(bodies.len()));
    assert_eq!(json_of(app.get(&base).await, 200).await.as_array().map(Vec::len), Some(1));

    // Poses: at t = 0 each body's frame is its CAD CS1 frame.
    let r = app.get(&format!("/api/results/{rid}/poses")).await;
    assert_eq!(r.status(), 200);
    assert_eq!(r.headers()["content-type"], "application/octet-stream");
    let b = r.bytes().await.expect("bytes");
    assert_eq!(&b[..4], b"C2MP");
    let nb = u32::from_le_bytes([b[8], b[9], b[10], b[11]]) as usize;
    let steps = u32::from_le_bytes([b[12], b[13], b[14], b[15]]) as usize;
    assert_eq!((nb, steps), (bodies.len(), 201));
    assert_eq!(b.len(), 16 + steps * (4 + 28 * nb));
    let frames = joints["frames"].as_array().expect("frames");
    let mut checked = 0;
    for (k, body) in bodies.iter().enumerate() {
        let Some(cs1) = frames.iter().find(|f| f["body"] == body.as_str() && f["name"] == "CS1") else { continue };
        let at = 16 + 4 + 28 * k;
        for c in 0..3 {
            let want = cs1["position"][c].as_f64().expect("p");
            assert!((f32_at(&b, at + 4 * c) - want).abs() < 1e-5, "{body}: {c}");
        }
        checked += 1;
    }
    assert!(checked >= 5, "{checked} bodies checked");
    // At t = 2 s the first joint has turned 1 rad: a body beyond it has moved.
    let last = 16 + (steps - 1) * (4 + 28 * nb) + 4 + 28 * (nb - 1);
    let first = 16 + 4 + 28 * (nb - 1);
    assert!((f32_at(&b, last) - f32_at(&b, first)).abs() + (f32_at(&b, last + 4) - f32_at(&b, first + 4)).abs() > 1e-2);

    // Variables and decimated series.
    let v = json_of(app.get(&format!("/api/results/{rid}/variables?search=PHI&limit=3")).await, 200).await;
    assert_eq!((v["total"].as_u64(), v["variables"].as_array().map(Vec::len)), (Some(6), Some(3)));
    let n0 = format!("{}.phi", names[0].0);
    let s = json_of(app.get(&format!("/api/results/{rid}/series?name={n0}&width=20")).await, 200).await;
    let ys = s["variables"][0]["y"].as_array().expect("y");
    assert!(ys.len() <= 40 && ys.len() >= 20, "{}", ys.len());
    assert!((ys.last().and_then(Value::as_f64).expect("y") - (names[0].1 + 1.0)).abs() < 1e-12);
    json_of(app.get(&format!("/api/results/{rid}/series?name=nope")).await, 404).await;
    json_of(app.get(&format!("/api/results/{rid}/series?name={n0}&width=1")).await, 400).await;

    // Refusals name the file; nothing is stored.
    let p = json_of(upload(&app, &base, "noise.mat", (0..100u8).collect()).await, 422).await;
    assert!(p["detail"].as_str().expect("detail").contains("noise.mat"), "{p:#}");
    let other = trajectory(&[0.0, 1.0], &[("robot.axis1.phi".into(), vec![0.0, 1.0])], true);
    let p = json_of(upload(&app, &base, "robot.mat", other).await, 422).await;
    let d = p["detail"].as_str().expect("detail");
    assert!(d.contains("robot.mat") && d.contains("another model") && d.contains("robot"), "{d}");
    let mut v5 = b"MATLAB 5.0 MAT-file, Platform: GLNXA64, Created on: Tue Nov 24 2026".to_vec();
    v5.resize(200, b' ');
    let p = json_of(upload(&app, &base, "v5.mat", v5).await, 422).await;
    assert!(p["detail"].as_str().expect("detail").contains("MATLAB v5"), "{p:#}");
    json_of(upload(&app, &format!("/api/models/{id}/versions/9/results"), "x.mat", vec![1]).await, 404).await;
    assert_eq!(json_of(app.get(&base).await, 200).await.as_array().map(Vec::len), Some(1));

    // Delete.
    assert_eq!(app.client.delete(app.url(&format!("/api/results/{rid}"))).send().await.expect("del").status(), 204);
    json_of(app.get(&format!("/api/results/{rid}")).await, 404).await;
}

/// A result of any Modelica model: Dymola's visual shapes (here a box moving along x, and MSL's
/// RobotR3 from the fixtures when present) and its frames.
#[tokio::test]
async fn standalone_results_show_dymola_shapes() {
    let app = TestApp::spawn().await;
    let time = [0.0, 1.0, 2.0];
    let c = |v: f64| vec![v; 3];
    let mut series: Vec<(String, Vec<f64>)> = vec![("b.shape.Form".into(), c((987_000.0 + 103.0) * 1e20))];
    for (what, v) in [("rxvisobj", [1.0, 0.0, 0.0]), ("ryvisobj", [0.0, 1.0, 0.0]), ("size", [0.4, 0.1, 0.1])] {
        for (k, x) in v.iter().enumerate() {
            series.push((format!("b.shape.{what}[{}]", k + 1), c(*x)));
        }
    }
    series.push(("b.shape.rvisobj[1]".into(), vec![0.0, 1.0, 2.0]));
    series.push(("b.shape.rvisobj[2]".into(), c(0.0)));
    series.push(("b.shape.rvisobj[3]".into(), c(0.0)));
    series.push(("b.shape.Material".into(), c(((99.0 * 100.0 + 99.0) * 100.0) * 10.0)));
    let r = upload(&app, "/api/results", "box.mat", trajectory(&time, &series, true)).await;
    let res = json_of(r, 201).await;
    assert_eq!((res["model_id"].clone(), res["shapes"].as_u64(), res["frames"].as_u64()), (Value::Null, Some(1), Some(0)));
    let rid = res["id"].as_str().expect("id").to_string();
    let s = json_of(app.get(&format!("/api/results/{rid}/shapes")).await, 200).await;
    assert_eq!(s["shapes"][0]["kind"], "cylinder");
    assert_eq!(s["shapes"][0]["color"], serde_json::json!([255, 255, 0]));
    let b = app.get(&format!("/api/results/{rid}/shape-poses")).await.bytes().await.expect("bytes");
    assert_eq!(&b[..4], b"C2MS");
    assert_eq!(f32_at(&b, 20 + 2 * (4 + 48) + 4), 2.0, "origin x at t = 2");
    json_of(app.get(&format!("/api/results/{rid}/poses")).await, 409).await;
    let p = json_of(upload(&app, "/api/results", "noise.mat", (0..100u8).collect()).await, 422).await;
    assert!(p["detail"].as_str().expect("detail").contains("noise.mat"));
    if let Some(dir) = cad2mo_tests::common::fixtures_dir("standalone_results_show_dymola_shapes") {
        if let Ok(bytes) = std::fs::read(dir.join("mat/lbl-srg+BuildingsPy/fullRobot.mat")) {
            let res = json_of(upload(&app, "/api/results", "fullRobot.mat", bytes).await, 201).await;
            assert_eq!((res["variables"].as_u64(), res["instants"].as_u64()), (Some(5902), Some(97)));
            assert!(res["shapes"].as_u64().expect("shapes") >= 7, "{res:#}");
        }
    }
    let list = json_of(app.get("/api/results").await, 200).await;
    assert!(!list.as_array().expect("list").is_empty());
}

/// A result upload beyond `--max-upload` is a 413 problem saying the limit, before the body is
/// read (a declared 2 GB answers at once) or while it is read; nothing is stored.
#[tokio::test]
async fn oversized_result_uploads_are_413() {
    let limit = 64 * 1024;
    let app = TestApp::spawn_with(|s| s.max_upload = limit).await;
    let r = upload(&app, "/api/results", "big.mat", vec![0u8; limit as usize * 2]).await;
    assert_eq!(r.status(), 413);
    assert_eq!(r.headers()["content-type"], "application/problem+json");
    let p: Value = r.json().await.expect("problem");
    assert!(p["detail"].as_str().expect("detail").contains(&limit.to_string()), "{p}");

    // A declared 2 GB: refused from the headers, without waiting for a byte of the body.
    let addr = app.address.trim_start_matches("http://").to_string();
    let answer = tokio::task::spawn_blocking(move || {
        use std::io::{Read, Write};
        let mut s = std::net::TcpStream::connect(&addr).expect("connect");
        s.set_read_timeout(Some(std::time::Duration::from_secs(10))).expect("timeout");
        let head = format!(
            "POST /api/results HTTP/1.1\r\nHost: {addr}\r\nX-Requested-With: cad2mo\r\nContent-Type: multipart/form-data; boundary=b\r\nContent-Length: 2147483648\r\n\r\n"
        );
        s.write_all(head.as_bytes()).expect("send");
        let mut buf = vec![0u8; 4096];
        let n = s.read(&mut buf).expect("an answer before the body");
        String::from_utf8_lossy(&buf[..n]).to_string()
    })
    .await
    .expect("join");
    assert!(answer.starts_with("HTTP/1.1 413"), "{answer}");
    assert!(answer.contains("application/problem+json"), "{answer}");
    assert_eq!(json_of(app.get("/api/results").await, 200).await, serde_json::json!([]), "nothing stored");
}

/// A result with a non-finite value is refused at upload naming the matrix, row and column (and
/// nothing is stored); a stored row whose summary no longer reads is left out of the list, which
/// answers for everyone else.
#[tokio::test]
async fn non_finite_results_are_refused_and_one_bad_stored_result_spoils_no_list() {
    let app = TestApp::spawn().await;
    let x = |v: Vec<f64>| vec![("x".to_string(), v)];
    let bad_time = trajectory(&[0.0, 1.0, f64::NAN, 3.0], &x(vec![0.0, 1.0, 2.0, 3.0]), false);
    let p = json_of(upload(&app, "/api/results", "nan.mat", bad_time).await, 422).await;
    let detail = p["detail"].as_str().expect("detail");
    assert!(detail.contains("nan.mat: matrix \"data_2\" row 1, column 3 holds NaN (variable \"time\" at time instant 3)"), "{p:#}");
    assert_eq!(p["errors"][0]["field"], "file", "{p:#}");
    let bad_value = trajectory(&[0.0, 1.0, 2.0], &x(vec![0.0, f64::INFINITY, 2.0]), true);
    let p = json_of(upload(&app, "/api/results", "inf.mat", bad_value).await, 422).await;
    assert!(p["detail"].as_str().expect("detail").contains("row 2, column 2 holds inf (variable \"x\" at time instant 2)"), "{p:#}");
    assert_eq!(json_of(app.get("/api/results").await, 200).await, serde_json::json!([]), "nothing stored");

    let good = json_of(upload(&app, "/api/results", "good.mat", trajectory(&[0.0, 1.0], &x(vec![0.0, 1.0]), false)).await, 201).await;
    // A row stored before these checks, whose summary does not read back (a null start time).
    let store = cad2mo_server::store::Store::open(app.database_url()).await.expect("store");
    let poisoned = cad2mo_server::store::results::insert(&store, None, None, "old.mat", 10, &"0".repeat(64), r#"{"start": null}"#)
        .await
        .expect("insert");
    let list = json_of(app.get("/api/results").await, 200).await;
    let ids: Vec<&str> = list.as_array().expect("list").iter().filter_map(|r| r["id"].as_str()).collect();
    assert_eq!(ids, [good["id"].as_str().expect("id")], "the bad row is left out, the list answers: {list:#}");
    // That item alone answers an error, and can be deleted.
    assert_eq!(app.get(&format!("/api/results/{}", poisoned.id)).await.status().as_u16(), 500);
    let r = app.client.delete(app.url(&format!("/api/results/{}", poisoned.id))).send().await.expect("delete");
    assert_eq!(r.status().as_u16(), 204);
}
