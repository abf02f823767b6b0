//! API tests of the motor library: every route, its successes and its failures, through the
//! `TestApp` methods of tests/support/app_library.rs (the real service on port 0 with a fresh,
//! seeded SQLite database per test).

use cad2mo_engine::library::seed;
use cad2mo_tests::app::TestApp;
use serde_json::{json, Value};

async fn json_of(r: reqwest::Response) -> Value {
    r.json().await.expect("json body")
}

/// Asserts a problem document with `status` and returns it.
async fn problem(r: reqwest::Response, status: u16) -> Value {
    assert_eq!(r.status(), status, "status");
    let ct = r.headers().get("content-type").and_then(|v| v.to_str().ok()).unwrap_or("").to_string();
    assert_eq!(ct, "application/problem+json");
    let p = json_of(r).await;
    assert_eq!(p["status"], status, "{p}");
    p
}

/// The fields of a problem's `errors`.
fn fields(p: &Value) -> Vec<String> {
    p["errors"].as_array().map(|a| a.iter().map(|e| e["field"].as_str().unwrap_or("").to_string()).collect()).unwrap_or_default()
}

fn error_for<'a>(p: &'a Value, field: &str) -> &'a str {
    p["errors"]
        .as_array()
        .and_then(|a| a.iter().find(|e| e["field"] == field))
        .and_then(|e| e["message"].as_str())
        .unwrap_or_else(|| panic!("no error for {field} in {p}"))
}

fn gear_class(name: &str) -> Value {
    json!({
        "name": name,
        "domain": "gear",
        "modelica_class": "cad2mo.Drives.Gears.Efficiency",
        "description": "A test gear",
        "parameters": [
            {"name": "ratio", "type": "Real", "unit": "1", "editable": true, "default": 1, "comment": "motor/joint"},
            {"name": "eta", "type": "Real", "unit": "1", "min": 0, "max": 1, "editable": true, "default": {"value": 90, "unit": "%"}},
            {"name": "L", "type": "Real", "unit": "H", "min": 0, "editable": false},
            {"name": "label", "type": "String", "editable": false}
        ]
    })
}

fn re40_body() -> Value {
    json!({
        "class_id": seed::DC_MOTOR,
        "name": "maxon RE 40 (test copy)",
        "source": "maxon RE 40 148877 datasheet, nominal values",
        "values": {
            "R": 0.317, "L": {"value": 82, "unit": "uH"}, "k": {"value": 30.2, "unit": "mNm/A"},
            "J": {"value": 142, "unit": "g.cm2"}, "d": 0, "V_max": 24, "I_max": 5.77, "Tc": 0.001
        }
    })
}

// ---------------------------------------------------------------------------------------------
// Seed and lists

#[tokio::test]
async fn a_fresh_app_has_the_seeded_library() {
    let app = TestApp::spawn().await;
    let r = app.library_classes().await;
    assert_eq!(r.status(), 200);
    let classes = json_of(r).await;
    let classes = classes.as_array().expect("array");
    assert!(classes.len() >= 6, "{classes:?}");
    let dc = classes.iter().find(|c| c["id"] == seed::DC_MOTOR).expect("DC motor class");
    assert_eq!(dc["modelica_class"], "cad2mo.Drives.Motors.DCPermanentMagnet");
    assert_eq!(dc["domain"], "motor");
    let names: Vec<&str> = dc["parameters"].as_array().expect("params").iter().filter_map(|p| p["name"].as_str()).collect();
    for n in ["R", "L", "k", "J", "d", "V_max", "I_max"] {
        assert!(names.contains(&n), "{n} in {names:?}");
    }
    let r_param = &dc["parameters"][0];
    assert_eq!(r_param["unit"], "Ohm");
    assert_eq!(r_param["editable"], false);

    let motors = json_of(app.library_instances("?domain=motor").await).await;
    // 5 motors of the first seed (4 DC, 1 MSL), 14 catalogue DC motors (8 FAULHABER, 6 maxon) and
    // 30 AC servo motors (15 Yaskawa Σ-7 models, each without and with holding brake).
    assert_eq!(motors.as_array().expect("array").len(), 49, "{motors}");
    let servos = json_of(app.library_instances(&format!("?class_id={}", seed::AC_SERVO)).await).await;
    assert_eq!(servos.as_array().expect("array").len(), 30, "{servos}");
    let ours = json_of(app.library_instances(&format!("?class_id={}", seed::DC_MOTOR)).await).await;
    let ours = ours.as_array().expect("array");
    assert_eq!(ours.len(), 18);
    assert!(ours.iter().all(|i| i["class_id"] == seed::DC_MOTOR && i["domain"] == "motor"));
    let gears = json_of(app.library_instances("?domain=gear").await).await;
    assert!(gears.as_array().expect("array").iter().all(|i| i["domain"] == "gear"));
    let all = json_of(app.library_instances("").await).await;
    assert!(all.as_array().expect("array").len() > ours.len());
    let none = json_of(app.library_instances("?domain=nothing").await).await;
    assert_eq!(none, json!([]));

    let re40 = json_of(app.library_instance(seed::MAXON_RE40).await).await;
    assert_eq!(re40["values"]["L"], 8.23e-5);
    assert_eq!(re40["values"]["k"], 0.0302);
    assert!(re40["source"].as_str().expect("source").contains("148877"));
}

// ---------------------------------------------------------------------------------------------
// Classes

#[tokio::test]
async fn class_create_read_update_delete() {
    let app = TestApp::spawn().await;
    let r = app.create_library_class(&gear_class("Test gear")).await;
    assert_eq!(r.status(), 201);
    let location = r.headers().get("location").and_then(|v| v.to_str().ok()).expect("location").to_string();
    let created = json_of(r).await;
    let id = created["id"].as_str().expect("id").to_string();
    assert_eq!(location, format!("/api/library/classes/{id}"));
    assert_eq!(created["parameters"][1]["default"], 0.9);
    assert_eq!(created["parameters"][3]["type"], "String");

    let got = json_of(app.get(&location).await).await;
    assert_eq!(got, created);
    let list = json_of(app.library_classes().await).await;
    assert!(list.as_array().expect("array").iter().any(|c| c["id"] == id.as_str()));

    let mut changed = gear_class("Test gear, renamed");
    changed["description"] = json!("changed");
    let r = app.update_library_class(&id, &changed).await;
    assert_eq!(r.status(), 200);
    let updated = json_of(r).await;
    assert_eq!(updated["name"], "Test gear, renamed");
    assert_eq!(updated["id"], id.as_str());
    assert_eq!(json_of(app.library_class(&id).await).await, updated);

    let r = app.delete_library_class(&id).await;
    assert_eq!(r.status(), 204);
    problem(app.library_class(&id).await, 404).await;
    problem(app.delete_library_class(&id).await, 404).await;
}

#[tokio::test]
async fn an_invalid_class_lists_every_problem() {
    let app = TestApp::spawn().await;
    let body = json!({
        "name": "",
        "domain": "Motor!",
        "modelica_class": "NotAPath",
        "parameters": [
            {"name": "L", "type": "Real", "unit": "mH"},
            {"name": "L", "type": "Real", "unit": "H"},
            {"name": "x", "type": "Double"},
            {"name": "eta", "type": "Real", "unit": "1", "min": 1, "max": 0},
            {"name": "ratio", "type": "Real", "unit": "1", "default": "one"}
        ]
    });
    let p = problem(app.create_library_class(&body).await, 422).await;
    let f = fields(&p);
    for want in [
        "name",
        "domain",
        "modelica_class",
        "parameters[0].unit",
        "parameters[1].name",
        "parameters[2].type",
        "parameters[3].max",
        "parameters[4].default",
    ] {
        assert!(f.iter().any(|x| x == want), "{want} missing in {f:?}");
    }
    assert!(error_for(&p, "parameters[0].unit").contains("\"H\""));
}

#[tokio::test]
async fn class_conflicts_and_unknown_ids() {
    let app = TestApp::spawn().await;
    // The name of a seeded class is taken.
    let p = problem(app.create_library_class(&gear_class("Ideal gear")).await, 409).await;
    assert!(p["detail"].as_str().expect("detail").contains("Ideal gear"), "{p}");
    // Renaming onto a taken name too.
    let r = app.create_library_class(&gear_class("Mine")).await;
    let id = json_of(r).await["id"].as_str().expect("id").to_string();
    problem(app.update_library_class(&id, &gear_class("Ideal gear")).await, 409).await;
    // A class with instances cannot be deleted.
    let p = problem(app.delete_library_class(seed::DC_MOTOR).await, 409).await;
    let detail = p["detail"].as_str().expect("detail");
    // 18 instances: the first five by name are named, then how many more.
    assert!(detail.contains("18 instance(s)") && detail.contains("Faulhaber 1331 T 006 SR") && detail.contains("and 13 more"), "{detail}");
    assert_eq!(app.library_class(seed::DC_MOTOR).await.status(), 200);
    // Unknown ids.
    let unknown = "00000000-0000-4000-8000-000000000000";
    problem(app.library_class(unknown).await, 404).await;
    problem(app.library_class("not-a-uuid").await, 404).await;
    problem(app.update_library_class(unknown, &gear_class("X")).await, 404).await;
    problem(app.delete_library_class(unknown).await, 404).await;
}

#[tokio::test]
async fn a_class_change_carries_its_instances_over_or_changes_nothing() {
    let app = TestApp::spawn().await;
    let class = json_of(app.library_class(seed::EFFICIENCY_GEAR).await).await;
    // A new parameter without default: the existing gear instance cannot follow.
    let mut body = class.clone();
    body["parameters"].as_array_mut().expect("params").push(json!({"name": "play", "type": "Real", "unit": "rad"}));
    let p = problem(app.update_library_class(seed::EFFICIENCY_GEAR, &body).await, 422).await;
    assert!(fields(&p).iter().any(|f| f.contains("play")), "{p}");
    assert_eq!(json_of(app.library_class(seed::EFFICIENCY_GEAR).await).await, class, "unchanged");
    // With a default (given in mrad) it can.
    let last = body["parameters"].as_array().expect("params").len() - 1;
    body["parameters"][last]["default"] = json!({"value": 1, "unit": "mrad"});
    let r = app.update_library_class(seed::EFFICIENCY_GEAR, &body).await;
    assert_eq!(r.status(), 200);
    let gear = json_of(app.library_instance(seed::MAXON_GP42C_74).await).await;
    assert_eq!(gear["values"]["play"], 0.001);
    assert_eq!(gear["values"]["eta"], 0.72);
}

// ---------------------------------------------------------------------------------------------
// Instances

#[tokio::test]
async fn instance_create_read_update_delete_with_unit_conversion() {
    let app = TestApp::spawn().await;
    let r = app.create_library_instance(&re40_body()).await;
    assert_eq!(r.status(), 201);
    let location = r.headers().get("location").and_then(|v| v.to_str().ok()).expect("location").to_string();
    let created = json_of(r).await;
    let id = created["id"].as_str().expect("id").to_string();
    assert_eq!(location, format!("/api/library/instances/{id}"));
    // 82 uH stored as 8.2e-5 H; 30.2 mNm/A as 0.0302 N.m/A; 142 g.cm2 as 1.42e-5 kg.m2.
    assert_eq!(created["values"]["L"], 8.2e-5);
    assert_eq!(created["values"]["k"], 0.0302);
    assert_eq!(created["values"]["J"], 1.42e-5);
    assert_eq!(created["class_name"], "DC permanent-magnet motor");
    assert_eq!(created["modelica_class"], "cad2mo.Drives.Motors.DCPermanentMagnet");
    assert_eq!(json_of(app.get(&location).await).await, created);
    let listed = json_of(app.library_instances(&format!("?class_id={}", seed::DC_MOTOR)).await).await;
    assert!(listed.as_array().expect("array").iter().any(|i| i["id"] == id.as_str()));

    // Editable values, name and source change; the GET body can be sent back as it is.
    let mut body = created.clone();
    body["name"] = json!("maxon RE 40 (renamed)");
    body["source"] = json!("new source");
    body["values"]["Tc"] = json!({"value": 2, "unit": "ms"});
    body["values"]["L"] = json!({"value": 0.082, "unit": "mH"});
    let r = app.update_library_instance(&id, &body).await;
    assert_eq!(r.status(), 200);
    let updated = json_of(r).await;
    assert_eq!(updated["values"]["Tc"], 0.002);
    assert_eq!(updated["values"]["L"], 8.2e-5);
    assert_eq!(updated["name"], "maxon RE 40 (renamed)");
    assert_eq!(updated["source"], "new source");

    assert_eq!(app.delete_library_instance(&id).await.status(), 204);
    problem(app.library_instance(&id).await, 404).await;
    problem(app.delete_library_instance(&id).await, 404).await;
}

#[tokio::test]
async fn an_invalid_instance_lists_every_bad_value() {
    let app = TestApp::spawn().await;
    let mut body = re40_body();
    let v = &mut body["values"];
    v["L"] = json!({"value": 82, "unit": "rpm"}); // incompatible unit
    v["R"] = json!(-1); // out of range
    v["k"] = json!("0.03"); // wrong type
    v["J"] = json!({"value": 1, "unit": "stone"}); // unknown unit
    v.as_object_mut().expect("values").remove("V_max"); // missing
    v["Kt"] = json!(1); // unknown parameter
    body["name"] = json!("  ");
    let p = problem(app.create_library_instance(&body).await, 422).await;
    let f = fields(&p);
    for want in ["name", "values.L", "values.R", "values.k", "values.J", "values.V_max", "values.Kt"] {
        assert!(f.iter().any(|x| x == want), "{want} missing in {f:?}");
    }
    assert_eq!(f.len(), 7, "{p}");
    assert!(error_for(&p, "values.L").contains("cannot be converted"), "{p}");
    assert!(error_for(&p, "values.L").starts_with("L"), "{p}");
    assert!(error_for(&p, "values.R").contains("minimum"), "{p}");
    assert!(error_for(&p, "values.k").contains("expected a number"), "{p}");
    assert!(error_for(&p, "values.V_max").contains("no value"), "{p}");

    // An out-of-range efficiency on its own: the detail names it.
    let body = json!({
        "class_id": seed::EFFICIENCY_GEAR, "name": "too good", "values": {"ratio": 10, "eta": {"value": 120, "unit": "%"}}
    });
    let p = problem(app.create_library_instance(&body).await, 422).await;
    assert_eq!(fields(&p), ["values.eta"]);
    assert!(p["detail"].as_str().expect("detail").contains("eta"), "{p}");

    // No such class.
    let mut body = re40_body();
    body["class_id"] = json!("00000000-0000-4000-8000-000000000000");
    let p = problem(app.create_library_instance(&body).await, 422).await;
    assert_eq!(fields(&p), ["class_id"]);
}

#[tokio::test]
async fn nameplate_values_cannot_be_edited() {
    let app = TestApp::spawn().await;
    let re40 = json_of(app.library_instance(seed::MAXON_RE40).await).await;
    let mut body = re40.clone();
    body["values"]["R"] = json!(0.299);
    body["values"]["J"] = json!({"value": 142, "unit": "g.cm2"});
    body["values"]["Tc"] = json!(0.002);
    let p = problem(app.update_library_instance(seed::MAXON_RE40, &body).await, 422).await;
    assert_eq!(fields(&p), ["values.R", "values.J"]);
    let msg = error_for(&p, "values.R");
    assert!(msg.contains("nameplate") && msg.contains("new instance"), "{msg}");
    assert_eq!(json_of(app.library_instance(seed::MAXON_RE40).await).await, re40, "unchanged");

    // The class cannot change either.
    let mut body = re40.clone();
    body["class_id"] = json!(seed::MSL_DC_MACHINE);
    let p = problem(app.update_library_instance(seed::MAXON_RE40, &body).await, 422).await;
    assert_eq!(fields(&p), ["class_id"]);
}

#[tokio::test]
async fn instance_conflicts_and_unknown_ids() {
    let app = TestApp::spawn().await;
    let mut body = re40_body();
    body["name"] = json!("maxon RE 40 148877 (24 V)");
    let p = problem(app.create_library_instance(&body).await, 409).await;
    assert!(p["detail"].as_str().expect("detail").contains("maxon RE 40 148877 (24 V)"), "{p}");
    // Renaming onto a taken name.
    let id = json_of(app.create_library_instance(&re40_body()).await).await["id"].as_str().expect("id").to_string();
    let mut mine = json_of(app.library_instance(&id).await).await;
    mine["name"] = json!("Faulhaber 1331 T 024 SR");
    problem(app.update_library_instance(&id, &mine).await, 409).await;
    // Unknown ids.
    let unknown = "00000000-0000-4000-8000-000000000000";
    problem(app.library_instance(unknown).await, 404).await;
    problem(app.update_library_instance(unknown, &mine).await, 404).await;
    problem(app.delete_library_instance(unknown).await, 404).await;
}

#[tokio::test]
async fn bodies_that_are_not_the_expected_json_are_problems() {
    let app = TestApp::spawn().await;
    let post = reqwest::Method::POST;
    let p = problem(app.library_raw(post.clone(), "/api/library/instances", "application/json", "{\"name\": ").await, 400).await;
    assert!(p["detail"].as_str().expect("detail").contains("malformed JSON"), "{p}");
    let p = problem(app.library_raw(post.clone(), "/api/library/classes", "text/plain", "{}").await, 400).await;
    assert!(p["detail"].as_str().expect("detail").contains("Content-Type"), "{p}");
    // Well-formed JSON of the wrong shape: the field is named.
    let p = problem(app.create_library_class(&json!({"name": 5, "domain": "gear", "modelica_class": "a.b"})).await, 422).await;
    assert_eq!(fields(&p), ["name"], "{p}");
    let p = problem(app.create_library_instance(&json!({"class_id": seed::DC_MOTOR, "name": "x"})).await, 422).await;
    assert!(error_for(&p, "body").contains("values"), "{p}");
    let p = problem(
        app.library_raw(reqwest::Method::PUT, &format!("/api/library/instances/{}", seed::MAXON_RE40), "application/json", "{,}").await,
        400,
    )
    .await;
    assert_eq!(p["type"], "/problems/bad-request");
}

// ---------------------------------------------------------------------------------------------
// XML

async fn export_text(app: &TestApp) -> String {
    let r = app.export_library().await;
    assert_eq!(r.status(), 200);
    let ct = r.headers().get("content-type").and_then(|v| v.to_str().ok()).unwrap_or("").to_string();
    assert!(ct.starts_with("application/xml"), "{ct}");
    r.text().await.expect("text")
}

/// Deletes every instance, then every class, through the API.
async fn empty_library(app: &TestApp) {
    for i in json_of(app.library_instances("").await).await.as_array().expect("array") {
        assert_eq!(app.delete_library_instance(i["id"].as_str().expect("id")).await.status(), 204);
    }
    for c in json_of(app.library_classes().await).await.as_array().expect("array") {
        assert_eq!(app.delete_library_class(c["id"].as_str().expect("id")).await.status(), 204);
    }
    assert_eq!(json_of(app.library_classes().await).await, json!([]));
}

#[tokio::test]
async fn export_then_import_into_an_empty_library_gives_the_same_library() {
    let a = TestApp::spawn().await;
    // Beyond the seed: a class with text and string parameters, an instance with awkward values.
    let class = json_of(a.create_library_class(&gear_class("Gear <\"odd\"> & co")).await).await;
    let body = json!({
        "class_id": class["id"], "name": "odd gear", "source": "line 1\nline 2 & <3>",
        "values": {"ratio": -0.1, "eta": 0.30000000000000004, "L": 1e-300, "label": "  spaced\ttext  "}
    });
    assert_eq!(a.create_library_instance(&body).await.status(), 201);
    let exported = export_text(&a).await;
    assert!(exported.contains("<motorLibrary version=\"1\">"));

    let b = TestApp::spawn().await;
    empty_library(&b).await;
    let r = b.import_library(exported.clone()).await;
    assert_eq!(r.status(), 200);
    let counts = json_of(r).await;
    let classes = json_of(a.library_classes().await).await;
    let instances = json_of(a.library_instances("").await).await;
    assert_eq!(counts["classes_created"], classes.as_array().expect("array").len());
    assert_eq!(counts["instances_created"], instances.as_array().expect("array").len());
    assert_eq!(counts["classes_updated"], 0);

    // Exactly the same: the XML, and ids, names, values and flags through the JSON API.
    assert_eq!(export_text(&b).await, exported);
    assert_eq!(json_of(b.library_classes().await).await, classes);
    assert_eq!(json_of(b.library_instances("").await).await, instances);

    // Importing the same file again updates everything and changes nothing.
    let counts = json_of(b.import_library(exported.clone()).await).await;
    assert_eq!(counts["classes_created"], 0);
    assert_eq!(counts["instances_updated"], instances.as_array().expect("array").len());
    assert_eq!(export_text(&b).await, exported);
}

#[tokio::test]
async fn a_broken_import_changes_nothing() {
    let app = TestApp::spawn().await;
    let before = export_text(&app).await;
    // Renamed instance (would be an update) plus bad values further down: nothing is applied.
    let broken = before
        .replace("name=\"maxon RE 40 148877 (24 V)\"", "name=\"renamed\"")
        .replace("<value param=\"eta\">0.72</value>", "<value param=\"eta\">1.5</value>")
        .replace("<value param=\"R\">0.317</value>", "<value param=\"R\" unit=\"rpm\">0.317</value>");
    assert_ne!(broken, before);
    let p = problem(app.import_library(broken).await, 422).await;
    let f = fields(&p);
    assert_eq!(f.len(), 2, "{p}");
    assert!(f.iter().any(|x| x.contains("<value param=\"R\">")), "{f:?}");
    assert!(f.iter().all(|x| x.starts_with("line ")), "{f:?}");
    assert!(f.iter().any(|x| x.contains("<value param=\"eta\">")), "{f:?}");
    assert!(p["detail"].as_str().expect("detail").contains("nothing changed"), "{p}");
    assert_eq!(export_text(&app).await, before);

    // Not XML at all, or not a library.
    let p = problem(app.import_library("<motorLibrary version=\"1\"><class></motorLibrary>").await, 422).await;
    assert!(fields(&p).iter().any(|f| f.starts_with("line 1")), "{p}");
    problem(app.import_library("<robots/>").await, 422).await;
    problem(app.import_library(vec![0xff_u8, 0xfe, 0x00]).await, 422).await;
    assert_eq!(export_text(&app).await, before);

    // A valid change is applied and counted.
    let renamed = before.replace("name=\"maxon RE 40 148877 (24 V)\"", "name=\"RE 40, renamed by import\"");
    let counts = json_of(app.import_library(renamed).await).await;
    assert_eq!(counts["instances_updated"], json_of(app.library_instances("").await).await.as_array().expect("array").len());
    assert_eq!(json_of(app.library_instance(seed::MAXON_RE40).await).await["name"], "RE 40, renamed by import");
}

/// A listing larger than the response cache's cap (16 MiB) is served (uncached), not a 500.
#[tokio::test]
async fn a_library_above_the_cache_cap_still_lists() {
    let app = TestApp::spawn().await;
    let url = app.database_url().to_string();
    let store = cad2mo_server::store::Store::open(&url).await.expect("store");
    let (re40, _) = cad2mo_server::store::library::get_instance(&store, seed::MAXON_RE40).await.expect("get").expect("seeded");
    let source = "datasheet ".repeat(1_000); // 10,000 characters, the most a source may have
    let n = 1_800; // 18 MB of sources
    for k in 0..n {
        let inst = cad2mo_engine::library::Instance {
            id: cad2mo_engine::library::new_id(),
            name: format!("RE 40 copy {k}"),
            source: source.clone(),
            ..re40.clone()
        };
        let done = cad2mo_server::store::library::insert_instance(&store, &re40.class_id, |_| Ok(inst)).await.expect("insert");
        assert!(matches!(done, cad2mo_server::store::library::Change::Done(_)));
    }
    for round in 0..2 {
        let r = app.library_instances("").await;
        assert_eq!(r.status(), 200, "round {round}");
        let body = r.bytes().await.expect("body");
        assert!(body.len() > 16 * 1024 * 1024, "{} bytes", body.len());
        let list: Value = serde_json::from_slice(&body).expect("json");
        assert!(list.as_array().expect("array").len() > n, "round {round}");
    }
    // Small listings are still served (and cached) as before.
    assert_eq!(app.library_instances("?domain=gear").await.status(), 200);
}
