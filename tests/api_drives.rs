//! Drives and re-export: assign motors, gears and controllers from the library to joints; upload
//! a new CAD version where one joint was removed and one body renamed; the new package keeps the
//! drive of every joint that still exists (the renamed body keeps its Modelica name) and reports
//! the orphan.

use cad2mo_tests::app::{zip_dir, TestApp};
use cad2mo_tests::common::{modelica_syntax_errors, msl_check, workspace_root};
use serde_json::{json, Value};

fn rotated_frames() -> (Vec<u8>, Vec<u8>) {
    let dir = workspace_root().join("tests/in/rotated_frames");
    let v1 = zip_dir(&dir);
    // Version 2: TOOL renamed to TOOLX in CAD, and the joint RootPart--BRACKET removed.
    let tmp = tempfile::tempdir().expect("tempdir");
    for entry in std::fs::read_dir(&dir).expect("ls").flatten() {
        let p = entry.path();
        let name = p.file_name().expect("name").to_owned();
        if p.extension().is_some_and(|e| e == "xml") {
            let mut xml = std::fs::read_to_string(&p).expect("xml");
            xml = xml.replace("<name>\"TOOL\"</name>", "<name>\"TOOLX\"</name>").replace("SLIDER--TOOL\"", "SLIDER--TOOLX\"");
            let start = xml.find("<SimpleJoint>\n        <name>\"RootPart--BRACKET\"").expect("joint to remove");
            let end = start + xml[start..].find("</SimpleJoint>").expect("end") + "</SimpleJoint>".len();
            xml.replace_range(start..end, "");
            std::fs::write(tmp.path().join(name), xml).expect("write");
        } else if p.is_file() {
            std::fs::copy(&p, tmp.path().join(name)).expect("copy");
        } else if p.is_dir() {
            let sub = tmp.path().join(&name);
            std::fs::create_dir_all(&sub).expect("mkdir");
            for f in std::fs::read_dir(&p).expect("ls").flatten() {
                std::fs::copy(f.path(), sub.join(f.file_name())).expect("copy");
            }
        }
    }
    (v1, zip_dir(tmp.path()))
}

async fn instance_of(app: &TestApp, domain: &str, class_path: &str) -> String {
    let classes: Value = app.get("/api/library/classes").await.json().await.expect("classes");
    let class = classes
        .as_array()
        .expect("class list")
        .iter()
        .find(|c| c["modelica_class"] == class_path)
        .unwrap_or_else(|| panic!("seeded class {class_path}"));
    let list: Value = app.get(&format!("/api/library/instances?domain={domain}")).await.json().await.expect("instances");
    list.as_array()
        .expect("instances")
        .iter()
        .find(|i| i["class_id"] == class["id"])
        .and_then(|i| i["id"].as_str())
        .expect("a seeded instance")
        .to_string()
}

async fn put_drive(app: &TestApp, model: &str, joint: &str, body: &Value) -> reqwest::Response {
    app.client.put(app.url(&format!("/api/models/{model}/drives/{joint}"))).json(body).send().await.expect("put")
}

async fn unzip_text(bytes: &[u8], suffix: &str) -> String {
    let mut z = zip::ZipArchive::new(std::io::Cursor::new(bytes.to_vec())).expect("zip");
    let name = z.file_names().find(|n| n.ends_with(suffix)).expect("file in zip").to_string();
    let mut s = String::new();
    std::io::Read::read_to_string(&mut z.by_name(&name).expect("entry"), &mut s).expect("utf8");
    s
}

#[tokio::test]
async fn drives_survive_a_cad_change_and_reexport() {
    let app = TestApp::spawn().await;
    let (v1, v2) = rotated_frames();
    let (model, _, job) = app.upload_model_ok(v1, &[]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");

    let drives: Value = app.get(&format!("/api/models/{model}/drives")).await.json().await.expect("drives");
    let joints: Vec<&str> = drives["joints"].as_array().expect("joints").iter().filter_map(|j| j["name"].as_str()).collect();
    assert!(joints.contains(&"RootPart_BRACKET") && joints.contains(&"SLIDER_TOOL"), "{joints:?}");

    let motor = instance_of(&app, "motor", "cad2mo.Drives.Motors.DCPermanentMagnet").await;
    let gear = instance_of(&app, "gear", "Modelica.Mechanics.Rotational.Components.IdealGear").await;
    let controller = instance_of(&app, "controller", "cad2mo.Drives.Controllers.CascadePPI").await;
    let body = json!({
        "motor_instance": motor, "gear_instance": gear, "controller_instance": controller,
        "overrides": {"gear": {"ratio": 100}},
        "reference": {"kind": "table", "points": [[0, 0.5], [1, 0.8]]}
    });
    for joint in ["RootPart_BRACKET", "SLIDER_TOOL"] {
        let r = put_drive(&app, &model, joint, &body).await;
        assert_eq!(r.status(), 200, "{}", r.text().await.unwrap_or_default());
    }
    // Refusals: an out-of-range override, a nameplate override, the wrong domain, an unknown joint.
    let bad =
        json!({"motor_instance": motor, "gear_instance": gear, "controller_instance": controller, "overrides": {"gear": {"ratio": "x"}}});
    assert_eq!(put_drive(&app, &model, "SLIDER_TOOL", &bad).await.status(), 422);
    let nameplate =
        json!({"motor_instance": motor, "gear_instance": gear, "controller_instance": controller, "overrides": {"motor": {"R": 1.0}}});
    let r = put_drive(&app, &model, "SLIDER_TOOL", &nameplate).await;
    assert_eq!(r.status(), 422);
    assert_eq!(r.headers()["content-type"], "application/problem+json");
    let swapped = json!({"motor_instance": gear, "gear_instance": motor, "controller_instance": controller});
    let p: Value = put_drive(&app, &model, "SLIDER_TOOL", &swapped).await.json().await.expect("problem");
    assert!(p["errors"].as_array().expect("errors").len() >= 2, "{p}");
    assert_eq!(put_drive(&app, &model, "NO_SUCH_JOINT", &body).await.status(), 404);
    // Within the library's limits but refused by the generator (efficiency 0): the 422 names the
    // parameter's field, so the drive editor shows it at its control.
    let lossy = instance_of(&app, "gear", "cad2mo.Drives.Gears.Efficiency").await;
    let eta0 =
        json!({"motor_instance": motor, "gear_instance": lossy, "controller_instance": controller, "overrides": {"gear": {"eta": 0}}});
    let r = put_drive(&app, &model, "RootPart_BRACKET", &eta0).await;
    assert_eq!(r.status(), 422);
    let p: Value = r.json().await.expect("problem");
    assert_eq!(p["errors"][0]["field"], "overrides.gear.eta", "{p}");
    assert!(p["errors"][0]["message"].as_str().is_some_and(|m| m.contains("must be in (0, 1]")), "{p}");
    let one: Value = app.get(&format!("/api/models/{model}/drives/SLIDER_TOOL")).await.json().await.expect("drive");
    assert_eq!(one["overrides"]["gear"]["ratio"], 100);
    assert_eq!(one["reference"]["kind"], "table");
    assert_eq!(app.get(&format!("/api/models/{model}/drives/NOPE")).await.status(), 404);
    let r = app
        .client
        .put(app.url(&format!("/api/models/{model}/drives/SLIDER_TOOL")))
        .body("{")
        .header("content-type", "application/json")
        .send()
        .await
        .expect("put");
    assert_eq!(r.status(), 400);
    assert_eq!(r.headers()["content-type"], "application/problem+json");

    // Re-export v1 with the drives: Mechatronics.mo drives both joints with ratio 100.
    let r = app.client.post(app.url(&format!("/api/models/{model}/reexport"))).send().await.expect("reexport");
    assert_eq!(r.status(), 202);
    let queued: Value = r.json().await.expect("json");
    assert_eq!(app.wait_for_job(queued["job_id"].as_str().expect("job")).await["status"], "succeeded");
    let pkg = app.package(&model, 1).await.bytes().await.expect("zip");
    let mech = unzip_text(&pkg, "/Mechatronics.mo").await;
    assert!(mech.contains("drive_RootPart_BRACKET") && mech.contains("drive_SLIDER_TOOL"), "{mech}");
    assert!(mech.contains("ratio=100"), "{mech}");
    assert!(mech.contains("connect(drive_SLIDER_TOOL.flange, SLIDER_TOOL.drive)"), "{mech}");

    // Version 2: the removed joint's drive is orphaned, the renamed body's joint keeps its name.
    let (_, version, job) = app.upload_version_ok(&model, v2, &[]).await;
    assert_eq!(version, 2);
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");
    let report: Value = app.report(&model, 2).await.json().await.expect("report");
    assert_eq!(report["drives"]["active"], json!(["SLIDER_TOOL"]));
    assert_eq!(report["drives"]["orphaned"], json!(["RootPart_BRACKET"]));
    let tool = report["bodies"].as_array().expect("bodies").iter().find(|b| b["cad_name"] == "TOOLX").expect("renamed body");
    assert_eq!(tool["modelica_name"], "TOOL", "a renamed body keeps its Modelica name");
    let drives: Value = app.get(&format!("/api/models/{model}/drives")).await.json().await.expect("drives");
    let status: Vec<(String, String)> = drives["drives"]
        .as_array()
        .expect("drives")
        .iter()
        .map(|d| (d["joint"].as_str().unwrap_or_default().to_string(), d["status"].as_str().unwrap_or_default().to_string()))
        .collect();
    assert!(status.contains(&("RootPart_BRACKET".into(), "orphaned".into())), "{status:?}");
    assert!(status.contains(&("SLIDER_TOOL".into(), "active".into())), "{status:?}");

    // The v2 package: Mechatronics works with the new Mechanics and passes the checks.
    let pkg = app.package(&model, 2).await.bytes().await.expect("zip");
    let mech = unzip_text(&pkg, "/Mechatronics.mo").await;
    assert!(mech.contains("drive_SLIDER_TOOL") && !mech.contains("drive_RootPart_BRACKET"), "{mech}");
    let mechanics = unzip_text(&pkg, "/Mechanics.mo").await;
    assert!(mechanics.contains(" SLIDER_TOOL("), "the joint keeps its name in Mechanics");
    let dir = tempfile::tempdir().expect("tempdir");
    let mut z = zip::ZipArchive::new(std::io::Cursor::new(pkg.to_vec())).expect("zip");
    z.extract(dir.path()).expect("extract");
    if let Some(Err(msg)) = msl_check(dir.path()) {
        panic!("msl-check: {msg}");
    }
    if let Some(errors) = modelica_syntax_errors(dir.path()) {
        assert!(errors.is_empty(), "{errors:?}");
    }

    // Batch re-export of every model; deleting a drive.
    let r = app.client.post(app.url("/api/reexport")).send().await.expect("batch");
    assert_eq!(r.status(), 202);
    let batch: Value = r.json().await.expect("json");
    assert_eq!(batch["jobs"].as_array().expect("jobs").len(), 1, "{batch}");
    for j in batch["jobs"].as_array().expect("jobs") {
        assert_eq!(app.wait_for_job(j["job_id"].as_str().expect("id")).await["status"], "succeeded");
    }
    let r = app.client.delete(app.url(&format!("/api/models/{model}/drives/RootPart_BRACKET"))).send().await.expect("delete");
    assert_eq!(r.status(), 204);
    let r = app.client.delete(app.url(&format!("/api/models/{model}/drives/RootPart_BRACKET"))).send().await.expect("delete");
    assert_eq!(r.status(), 404);
    assert_eq!(app.get("/api/models/nope/drives").await.status(), 404);
}
