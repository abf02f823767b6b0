//! Closed-loop simulations through the REST API (issue 28) on a generated 2-axis arm with a
//! drive on every joint: the answer and its stored copy, the MAT v4 result read back through the
//! results routes (poses from the file's frames equal FK of the simulated joint angles), every
//! 422 naming its field, the bound on runs at once and cancellation when the client goes away.

use std::time::Duration;

use cad2mo_tests::app::{json_of, TestApp};
use serde_json::{json, Value};

#[path = "../engine/benches/support/gen.rs"]
#[allow(dead_code)]
mod gen;

fn arm_zip(n: usize) -> Vec<u8> {
    cad2mo_engine::pipeline::back::bundle::write_zip(&[("arm.xml".to_string(), gen::serial_arm_xml(n).into_bytes())]).expect("zip")
}

async fn instance(app: &TestApp, class_path: &str, name: Option<&str>) -> String {
    let classes = json_of(app.get("/api/library/classes").await, 200).await;
    let class = classes.as_array().expect("classes").iter().find(|c| c["modelica_class"] == class_path).expect("class");
    let list = json_of(app.get(&format!("/api/library/instances?class_id={}", class["id"].as_str().expect("id"))).await, 200).await;
    let list = list.as_array().expect("instances");
    let i = match name {
        Some(n) => list.iter().find(|i| i["name"] == n).unwrap_or_else(|| panic!("no instance {n}")),
        None => &list[0],
    };
    i["id"].as_str().expect("id").to_string()
}

/// An arm of `n` axes with a drive on each joint and a motion moving every joint by 0.2 rad;
/// returns (model id, joint names, motion id).
async fn driven_arm(app: &TestApp, n: usize) -> (String, Vec<String>, String) {
    let (id, _, job) = app.upload_model_ok(arm_zip(n), &[("gravity", "0,0,-9.81")]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");
    let base = format!("/api/models/{id}");
    let j = json_of(app.get(&format!("{base}/joints")).await, 200).await;
    let names: Vec<String> =
        j["joints"].as_array().expect("joints").iter().map(|x| x["name"].as_str().expect("name").to_string()).collect();
    let motor = instance(app, "cad2mo.Drives.Motors.DCPermanentMagnet", Some("maxon RE 40 148877 (24 V)")).await;
    let gear = instance(app, "Modelica.Mechanics.Rotational.Components.IdealGear", Some("Ideal gear 100:1")).await;
    let controller = instance(app, "cad2mo.Drives.Controllers.CascadePPI", None).await;
    for name in &names {
        let drive = json!({"motor_instance": motor, "gear_instance": gear, "controller_instance": controller});
        json_of(app.client.put(app.url(&format!("{base}/drives/{name}"))).json(&drive).send().await.expect("put"), 200).await;
    }
    let values: serde_json::Map<String, Value> = names.iter().map(|n| (n.clone(), json!(0.2))).collect();
    let motion = json!({"name": "move", "keyframes": [{"kind": "joints", "values": {}}, {"kind": "joints", "values": values, "interpolation": "quintic", "duration": 1.0}]});
    let m = json_of(app.client.post(app.url(&format!("{base}/motions"))).json(&motion).send().await.expect("post"), 201).await;
    (id, names, m["id"].as_str().expect("id").to_string())
}

async fn simulate(app: &TestApp, model_id: &str, body: &Value) -> reqwest::Response {
    app.client.post(app.url(&format!("/api/models/{model_id}/simulations"))).json(body).send().await.expect("post")
}

fn fields(p: &Value) -> Vec<String> {
    p["errors"].as_array().expect("errors").iter().map(|e| e["field"].as_str().expect("field").to_string()).collect()
}

#[tokio::test]
async fn a_simulation_answers_stores_its_result_and_refuses_bad_input_by_field() {
    let app = TestApp::spawn().await;
    let (id, names, mid) = driven_arm(&app, 2).await;

    let body = json!({"duration": 1.2, "drives": true, "motion_id": mid, "max_joint_error": 1e-6});
    let sim = json_of(simulate(&app, &id, &body).await, 201).await;
    println!("2-axis arm, 1.2 s with drives: {} steps, {} s", sim["steps"], sim["wall_time_s"]);
    let drives = sim["drives"].as_array().expect("drives");
    assert_eq!(drives.len(), 2, "{sim:#}");
    assert_eq!(sim["motion_id"], mid.as_str());
    assert_eq!(sim["keyframes"].as_array().expect("keyframes").len(), 2, "{sim:#}");
    for (d, name) in drives.iter().zip(&names) {
        assert_eq!(d["joint"], name.as_str());
        let max = d["max_error"].as_f64().expect("max");
        assert!(max > 0.0 && max < 0.2, "{d:#}");
        assert!(d["max_current"].as_f64().expect("i") <= d["i_max"].as_f64().expect("I_max") * (1.0 + 1e-3), "{d:#}");
        assert_eq!(d["at_keyframes"].as_array().expect("at keyframes").len(), 2);
    }
    // 1 µrad is tighter than any real drive tracks a moving reference: the verdict says so.
    assert_eq!(sim["ok"], false, "{sim:#}");
    assert!(sim["reasons"][0].as_str().expect("reason").contains("joint error"), "{sim:#}");
    assert!(sim["solver"].as_str().expect("solver").contains("rtol 1e-6"), "{sim:#}");
    // Stored with the motion.
    let sid = sim["id"].as_str().expect("id");
    let again = json_of(app.get(&format!("/api/models/{id}/simulations/{sid}")).await, 200).await;
    assert_eq!(again["drives"], sim["drives"]);
    let of_motion = json_of(app.get(&format!("/api/models/{id}/simulations?motion_id={mid}")).await, 200).await;
    assert_eq!(of_motion.as_array().expect("list").len(), 1);
    json_of(app.get(&format!("/api/models/{id}/simulations/nope")).await, 404).await;

    // The result: read like an uploaded one, every body's pose from its frame_a, which agrees
    // with FK of the file's joint angles.
    let rid = sim["result_id"].as_str().expect("result id");
    let r = json_of(app.get(&format!("/api/results/{rid}")).await, 200).await;
    assert!(r["missing"].as_array().expect("missing").is_empty() && r["from_joints"].as_array().expect("fj").is_empty(), "{r:#}");
    assert_eq!(r["joints_found"].as_array().expect("joints").len(), 2, "{r:#}");
    assert!(r["checks"]["kinematics"].as_f64().expect("kinematics") < 1e-12, "{r:#}");
    let v = json_of(app.get(&format!("/api/results/{rid}/variables?search=drive_{}.motor.i", names[0])).await, 200).await;
    assert!(v.to_string().contains(&format!("drive_{}.motor.i", names[0])), "{v:#}");
    let list = json_of(app.get(&format!("/api/models/{id}/versions/1/results")).await, 200).await;
    assert!(list.as_array().expect("results").iter().any(|x| x["id"] == rid), "{list:#}");

    // A passive run (drives off) under gravity: the arm falls far from the reference-free start.
    let passive = json_of(simulate(&app, &id, &json!({"duration": 0.2, "drives": false})).await, 201).await;
    assert!(passive["drives"].as_array().expect("drives").is_empty());
    assert_eq!(passive["undriven"].as_array().expect("undriven").len(), 2);

    // Bad input: a 422 naming each field.
    let other = app.upload_model_ok(arm_zip(2), &[]).await.0;
    let om = json!({"name": "other", "keyframes": [{"kind": "joints", "values": {}}, {"kind": "joints", "values": {}, "duration": 1.0}]});
    let om = json_of(app.client.post(app.url(&format!("/api/models/{other}/motions"))).json(&om).send().await.expect("post"), 201).await;
    let cases = [
        (json!({"duration": -1.0}), vec!["duration"]),
        (json!({"duration": 1e9}), vec!["duration"]),
        (json!({"duration": 1.0, "max_joint_error": 0}), vec!["max_joint_error"]),
        (json!({"duration": 1.0, "start": {"NOPE": 0.1}}), vec!["start.NOPE"]),
        (json!({"duration": 1.0, "motion_id": om["id"]}), vec!["motion_id"]),
        (json!({"duration": 1.0, "tool": "NOPE"}), vec!["tool"]),
        (json!({"duration": 1.0, "max_tool_error": 0.001}), vec!["max_tool_error"]),
    ];
    for (body, want) in cases {
        let p = json_of(simulate(&app, &id, &body).await, 422).await;
        assert_eq!(fields(&p), want, "{body}: {p:#}");
    }
    json_of(simulate(&app, &id, &json!({"duration": 1.0, "speed": 2})).await, 400).await;
    json_of(simulate(&app, "nope", &json!({"duration": 1.0})).await, 404).await;
    // A tool frame's error, judged against a tolerance.
    let tool = json!({"duration": 1.2, "motion_id": mid, "tool": "TOOL", "max_tool_error": 1.0});
    let t = json_of(simulate(&app, &id, &tool).await, 201).await;
    let e = t["tool"]["max_position_error"].as_f64().expect("tool error");
    assert!(e > 0.0 && e < 0.1, "{t:#}");
    assert_eq!(t["ok"], true, "{t:#}");
}

/// One run at a time (`--workers 1`): a second is refused (503) while the first runs, and a run
/// whose client went away stops at once and frees its place.
#[tokio::test]
async fn runs_are_bounded_and_cancelled_when_the_client_goes_away() {
    let app = TestApp::spawn_with(|s| s.workers = 1).await;
    let (id, _, mid) = driven_arm(&app, 6).await;
    let long = json!({"duration": 60.0, "motion_id": mid});
    let short = json!({"duration": 0.05});
    // A long run whose client gives up after 0.3 s.
    let url = app.url(&format!("/api/models/{id}/simulations"));
    let r = app.client.post(&url).json(&long).timeout(Duration::from_millis(300)).send().await;
    assert!(r.is_err(), "the long run should still be running: {:?}", r.map(|r| r.status()));
    tokio::time::sleep(Duration::from_millis(200)).await;
    // Cancelled: its place is free.
    json_of(simulate(&app, &id, &short).await, 201).await;
    // While a long run runs, another is refused.
    let client = app.client.clone();
    let (u, l) = (url.clone(), long.clone());
    let running = tokio::spawn(async move { client.post(&u).json(&l).timeout(Duration::from_millis(600)).send().await });
    tokio::time::sleep(Duration::from_millis(300)).await;
    let p = json_of(simulate(&app, &id, &short).await, 503).await;
    assert_eq!(p["type"], "/problems/busy", "{p:#}");
    assert!(p["detail"].as_str().expect("detail").contains("simulation(s) are running"), "{p:#}");
    assert!(running.await.expect("task").is_err());
}
