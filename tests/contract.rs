//! The HTTP contract, fuzzed: schemathesis (PyPI) generates requests from `openapi.yaml` against
//! the real service and fails on any 5xx or any difference between the contract and the server
//! (status codes, content types, headers, response schemas, valid requests refused, invalid ones
//! accepted, auth ignored). The service requires tokens (as beyond loopback), and real resources
//! exist (a converted model with two versions, a drive, library items) so the fuzzer reaches them
//! through path parameters from a generated `schemathesis.toml`.
//!
//! Bounded: a few examples per operation and a fixed seed (`CAD2MO_CONTRACT_EXAMPLES` and
//! `CAD2MO_CONTRACT_SEED` override them). Skips with a NOTICE when schemathesis is not installed
//! (neither the `schemathesis` script nor `python3 -m schemathesis.cli` runs), unless
//! `CAD2MO_REQUIRE_TOOLS=1`.

use std::process::Command;
use std::time::Instant;

use cad2mo_tests::app::{zip_dir, TestApp};
use cad2mo_tests::common::{tools_required, workspace_root};
use serde_json::{json, Value};

/// Why a stored motion may not plan (the stateful phase stores motions with made-up joints).
const PLANNABLE: &str = "the stored motion must be plannable on the latest version (its joints exist, its targets are reachable)";

/// What a motion's JSON Schema cannot say.
const MOTION_RULES: &str = "a unique printable name, at least 2 keyframes, durations and dwells between 0 and 3600 s, rotation matrices";

/// Examples per operation and phase.
const EXAMPLES: u32 = 15;

/// The schemathesis command: its script on PATH, else the module of `python3` (pip may install
/// the script where PATH does not look).
fn schemathesis() -> Option<Vec<&'static str>> {
    [vec!["schemathesis"], vec!["python3", "-m", "schemathesis.cli"]]
        .into_iter()
        .find(|cmd| Command::new(cmd[0]).args(&cmd[1..]).arg("--version").output().is_ok_and(|o| o.status.success()))
}

/// A client that sends the token (and nothing else the fuzzer would not send).
fn token_client(token: &str) -> reqwest::Client {
    let mut headers = reqwest::header::HeaderMap::new();
    let value = reqwest::header::HeaderValue::from_str(&format!("Bearer {token}")).expect("header");
    headers.insert(reqwest::header::AUTHORIZATION, value);
    reqwest::Client::builder().default_headers(headers).build().expect("client")
}

async fn json_of(r: reqwest::Response, status: u16) -> Value {
    let got = r.status().as_u16();
    let text = r.text().await.expect("body");
    assert_eq!(got, status, "{text}");
    serde_json::from_str(&text).expect("json")
}

/// The id of the first seeded instance of `class_path`.
async fn seeded_instance(app: &TestApp, class_path: &str) -> String {
    let classes = json_of(app.get("/api/library/classes").await, 200).await;
    let class = classes.as_array().expect("classes").iter().find(|c| c["modelica_class"] == class_path).expect("class");
    let list = json_of(app.get(&format!("/api/library/instances?class_id={}", class["id"].as_str().expect("id"))).await, 200).await;
    list[0]["id"].as_str().expect("a seeded instance").to_string()
}

/// An operation of the spec, its parameters (`path.id`, `body.class_id`, ...) and, when a valid
/// request may still be refused with 422 for a reason JSON Schema cannot state, that reason.
type Operation<'a> = (&'static str, Vec<(&'static str, &'a String)>, &'static str);

const CLASS_RULES: &str = "min <= max, defaults within the limits, unique parameter names";

/// TOML basic string.
fn toml_str(s: &str) -> String {
    serde_json::to_string(s).expect("string")
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_service_keeps_its_contract() {
    let Some(schemathesis) = schemathesis() else {
        assert!(!tools_required(), "schemathesis is required (CAD2MO_REQUIRE_TOOLS=1); pip install 'schemathesis>=4,<5'");
        println!("NOTICE: schemathesis not installed; contract fuzzing skipped (pip install 'schemathesis>=4,<5')");
        return;
    };
    // Tokens required, as beyond loopback. Upload checks never wait long enough to matter: the
    // fuzzer sends one request at a time, and the 503 it could get is in the contract anyway.
    let mut app = TestApp::spawn_with(|s| {
        s.force_auth = true;
        s.max_checks = 4;
    })
    .await;
    let url = app.database_url().to_string();
    let store = cad2mo_server::store::Store::open(&url).await.expect("store");
    let token = cad2mo_server::store::tokens::create(&store, "contract", None).await.expect("token");
    app.client = token_client(&token);

    // A converted model with two versions and a drive; a model to delete and one to delete a version of.
    let bundle = zip_dir(&workspace_root().join("tests/in/rotated_frames"));
    let (model, _, job) = app.upload_model_ok(bundle.clone(), &[]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");
    let (_, version, job2) = app.upload_version_ok(&model, bundle.clone(), &[]).await;
    assert_eq!(app.wait_for_job(&job2).await["status"], "succeeded");
    let (spare_model, _, spare_job) = app.upload_model_ok(bundle.clone(), &[("name", "spare")]).await;
    let (_, spare_version, spare_job2) = app.upload_version_ok(&spare_model, bundle.clone(), &[]).await;
    assert_eq!(spare_version, version);
    let (doomed_model, _, doomed_job) = app.upload_model_ok(bundle.clone(), &[("name", "doomed")]).await;
    for job in [spare_job, spare_job2, doomed_job] {
        app.wait_for_job(&job).await;
    }
    let drives = json_of(app.get(&format!("/api/models/{model}/drives")).await, 200).await;
    let joint = drives["joints"]
        .as_array()
        .expect("joints")
        .iter()
        .find(|j| j["kind"] == "revolute")
        .and_then(|j| j["name"].as_str())
        .expect("a revolute joint")
        .to_string();
    let motor = seeded_instance(&app, "cad2mo.Drives.Motors.DCPermanentMagnet").await;
    let gear = seeded_instance(&app, "Modelica.Mechanics.Rotational.Components.IdealGear").await;
    let controller = seeded_instance(&app, "cad2mo.Drives.Controllers.CascadePPI").await;
    let drive = json!({"motor_instance": motor, "gear_instance": gear, "controller_instance": controller});
    let r = app.client.put(app.url(&format!("/api/models/{model}/drives/{joint}"))).json(&drive).send().await.expect("put");
    json_of(r, 200).await;
    // Motions: one to read and change, a spare to delete.
    let mut motion_ids = Vec::new();
    for name in ["Contract motion", "Contract spare motion"] {
        let body =
            json!({"name": name, "keyframes": [{"kind": "joints", "values": {}}, {"kind": "joints", "values": {joint.clone(): 0.1}}]});
        let r = app.client.post(app.url(&format!("/api/models/{model}/motions"))).json(&body).send().await.expect("post");
        motion_ids.push(json_of(r, 201).await["id"].as_str().expect("id").to_string());
    }

    // Results: one to read, a spare to delete (joint coordinates only).
    let joints = json_of(app.get(&format!("/api/models/{model}/joints")).await, 200).await;
    let series: Vec<(String, Vec<f64>)> = joints["joints"]
        .as_array()
        .expect("joints")
        .iter()
        .map(|j| {
            let field = if j["kind"] == "prismatic" { "s" } else { "phi" };
            let q0 = j["q0"].as_f64().expect("q0");
            (format!("{}.{field}", j["name"].as_str().expect("name")), vec![q0, q0 + 0.01])
        })
        .collect();
    let mat = cad2mo_engine::results::write::trajectory(&[0.0, 1.0], &series, false);
    let mut result_ids = Vec::new();
    for _ in 0..2 {
        let form = reqwest::multipart::Form::new().part("file", reqwest::multipart::Part::bytes(mat.clone()).file_name("r.mat"));
        let r = app.client.post(app.url(&format!("/api/models/{model}/versions/1/results"))).multipart(form).send().await.expect("post");
        result_ids.push(json_of(r, 201).await["id"].as_str().expect("id").to_string());
    }

    // Library items: a class with an instance to read and change, and spares to delete.
    let class_body = json!({
        "name": "Contract gear", "domain": "gear", "modelica_class": "Modelica.Mechanics.Rotational.Components.IdealGear",
        "parameters": [{"name": "ratio", "type": "Real", "min": 1, "max": 1000, "editable": true, "default": 10}]
    });
    let r = app.client.post(app.url("/api/library/classes")).json(&class_body).send().await.expect("post");
    let class = json_of(r, 201).await["id"].as_str().expect("id").to_string();
    let mut spare_class_body = class_body.clone();
    spare_class_body["name"] = json!("Contract spare");
    let r = app.client.post(app.url("/api/library/classes")).json(&spare_class_body).send().await.expect("post");
    let spare_class = json_of(r, 201).await["id"].as_str().expect("id").to_string();
    let mut instances = Vec::new();
    for name in ["Contract instance", "Contract spare instance"] {
        let body = json!({"class_id": class, "name": name, "values": {"ratio": 50}});
        let r = app.client.post(app.url("/api/library/instances")).json(&body).send().await.expect("post");
        instances.push(json_of(r, 201).await["id"].as_str().expect("id").to_string());
    }

    // Parameters of real resources (deletions get the spares), and the operations whose valid
    // requests depend on more than JSON Schema can say.
    // Bundles are sent as application/zip, which schemathesis sends like application/octet-stream.
    let dir = tempfile::tempdir().expect("tempdir");
    let hooks = dir.path().join("hooks.py");
    std::fs::write(&hooks, "import schemathesis\n\nschemathesis.serializer.alias(\"application/zip\", \"application/octet-stream\")\n")
        .expect("write hooks");
    // ST302 (a 404 right after a create; `--exclude-checks` below) is off: its heuristic reads every pinned parameter below
    // as a link from the create, and once a spare is deleted by an earlier phase its 404 is
    // reported as a lost resource (seen on library classes and motions; each create -> delete pair
    // it printed answers 201 -> 204 when replayed alone). tests/api_library.rs and the other API
    // tests check create -> read -> delete themselves.
    let mut config = format!("# Generated by tests/contract.rs\nhooks = {}\n\n[parameters]\n", toml_str(&hooks.to_string_lossy()));
    for (k, v) in [("path.model_id", &model), ("path.joint", &joint), ("path.job_id", &job)] {
        config += &format!("{} = {}\n", toml_str(k), toml_str(v));
    }
    config += &format!("\"path.version\" = {version}\n\"query.from\" = 1\n\"query.to\" = {version}\n\n");
    let no = "false".to_string();
    let operations: [Operation; 36] = [
        ("getResult", vec![("path.result_id", &result_ids[0])], ""),
        ("deleteResult", vec![("path.result_id", &result_ids[1])], ""),
        ("listResultVariables", vec![("path.result_id", &result_ids[0])], ""),
        ("getResultSeries", vec![("path.result_id", &result_ids[0])], ""),
        ("getResultPoses", vec![("path.result_id", &result_ids[0])], ""),
        ("getResultShapes", vec![("path.result_id", &result_ids[0])], ""),
        ("getResultShapePoses", vec![("path.result_id", &result_ids[0])], ""),
        ("uploadStandaloneResult", vec![], "the file must be a MAT v4 result"),
        ("uploadResult", vec![], "the file must be a MAT v4 result whose variables name the version's bodies or joints"),
        ("getMotion", vec![("path.motion_id", &motion_ids[0])], ""),
        ("putMotion", vec![("path.motion_id", &motion_ids[0])], MOTION_RULES),
        ("deleteMotion", vec![("path.motion_id", &motion_ids[1])], ""),
        ("getTrajectory", vec![("path.motion_id", &motion_ids[0])], PLANNABLE),
        ("getSizing", vec![("path.motion_id", &motion_ids[0])], PLANNABLE),
        ("getMotionCollisions", vec![("path.motion_id", &motion_ids[0])], PLANNABLE),
        ("putCollisionMatrix", vec![], "both bodies of a pair must have collision shapes, differ, and appear once"),
        ("createMotion", vec![], MOTION_RULES),
        (
            "putScene",
            vec![],
            "rotations orthonormal, names unique and not a body's, sizes within 0.1 mm .. 1 km, fields fitting the shape and kind, meshes uploaded first",
        ),
        (
            "putSceneMesh",
            vec![],
            "the body must be an STL, OBJ or COLLADA mesh (file= names its format) of at most 200,000 triangles, not flat; the name an identifier",
        ),
        ("putJointLimits", vec![], "position limits must contain the CAD pose, rates must be > 0"),
        ("deleteModel", vec![("path.model_id", &doomed_model)], ""),
        ("deleteVersion", vec![("path.model_id", &spare_model)], ""),
        ("getLibraryClass", vec![("path.id", &class)], ""),
        ("updateLibraryClass", vec![("path.id", &class)], CLASS_RULES),
        ("deleteLibraryClass", vec![("path.id", &spare_class)], ""),
        ("getLibraryInstance", vec![("path.id", &instances[0])], ""),
        ("updateLibraryInstance", vec![("path.id", &instances[0])], "values must fit the class's parameters"),
        ("deleteLibraryInstance", vec![("path.id", &instances[1])], ""),
        ("createLibraryClass", vec![], CLASS_RULES),
        ("createLibraryInstance", vec![("body.class_id", &class)], "values must fit the class's parameters"),
        (
            "putDrive",
            vec![("body.motor_instance", &motor), ("body.gear_instance", &gear), ("body.controller_instance", &controller)],
            "overrides must fit the classes, the reference's times must not decrease",
        ),
        ("createModel", vec![], "the bundle must be a CAD export zip"),
        ("createVersion", vec![], "the bundle must be a CAD export zip"),
        ("importLibrary", vec![], "the body must be a library XML file (docs/library-xml.md)"),
        ("solveIk", vec![], "the frame must be a CAD frame of the model, the rotation a rotation matrix, seeds its joints"),
        (
            // Live runs are paced to the wall clock (up to 60 s each): tests/api_live.rs runs one.
            "runSimulation",
            vec![("body.live", &no)],
            "motion_id must be a motion of the model, start must name its independent joints, tool a CAD frame; max_tool_error needs a tool",
        ),
    ];
    for (id, params, semantic) in operations {
        config += &format!("[[operations]]\ninclude-operation-id = {}\n", toml_str(id));
        // Booleans as TOML booleans, the rest as strings.
        let value = |v: &str| if v == "false" || v == "true" { v.to_string() } else { toml_str(v) };
        let list: Vec<String> = params.iter().map(|(k, v)| format!("{} = {}", toml_str(k), value(v))).collect();
        config += &format!("parameters = {{ {} }}\n", list.join(", "));
        if !semantic.is_empty() {
            // Its 422 (documented) says why; every other refusal of a valid request still fails.
            config += &format!("# 422 for valid JSON/multipart/XML: {semantic}\n[operations.checks.positive_data_acceptance]\n");
            config += "expected-statuses = [\"2xx\", \"401\", \"403\", \"404\", \"409\", \"422\", \"503\"]\n";
        }
        config += "\n";
    }
    // A WebSocket is no request and response: tests/api_live.rs drives it with a real client.
    config += "[[operations]]\ninclude-operation-id = \"watchVersionLive\"\nenabled = false\n\n";
    let config_path = dir.path().join("schemathesis.toml");
    std::fs::write(&config_path, &config).expect("write config");

    let examples = std::env::var("CAD2MO_CONTRACT_EXAMPLES").ok().and_then(|v| v.parse().ok()).unwrap_or(EXAMPLES);
    let seed = std::env::var("CAD2MO_CONTRACT_SEED").ok().and_then(|v| v.parse::<u64>().ok()).unwrap_or(1);
    let spec_url = app.url("/openapi.yaml");
    let auth = format!("Authorization: Bearer {token}");
    let started = Instant::now();
    let out = tokio::task::spawn_blocking(move || {
        Command::new(schemathesis[0])
            .args(&schemathesis[1..])
            .arg("--config-file")
            .arg(&config_path)
            .args([
                "--no-color",
                "run",
                &spec_url,
                "-H",
                &auth,
                "--checks",
                "all",
                "--exclude-checks",
                "ensure_resource_availability",
                "--no-shrink",
            ])
            .args(["--seed", &seed.to_string()])
            .args(["-n", &examples.to_string()])
            .args(["--generation-database", "none", "--report-dir"])
            .arg(dir.path().join("report"))
            .current_dir(dir.path())
            .output()
            .expect("run schemathesis")
    })
    .await
    .expect("join");
    let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr)).replace(&token, "TOKEN");
    println!("{text}");
    println!("schemathesis took {:.1} s", started.elapsed().as_secs_f64());
    assert!(out.status.success(), "schemathesis found differences between openapi.yaml and the service:\n{text}\nconfig:\n{config}");
}
