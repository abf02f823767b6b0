//! API tests of models, versions, conversion jobs, downloads and diffs: the real service on port
//! 0 with a fresh database per test, driven through `TestApp` (tests/support/app_models.rs).

use std::io::{Read, Write};
use std::path::Path;
use std::sync::Arc;

use cad2mo_engine::pipeline::back::bundle::write_zip;
use cad2mo_tests::app::{heavy_pendulum, zip_dir, TestApp};
use cad2mo_tests::app_models::{problem, upload_form};
use cad2mo_tests::common::workspace_root;
use serde_json::Value;

fn case(name: &str) -> std::path::PathBuf {
    workspace_root().join("tests/in").join(name)
}

fn pendulum() -> Vec<u8> {
    zip_dir(&case("pendulum"))
}

/// The pendulum with its revolute removed and the link renamed `ROD`.
fn pendulum_edited() -> Vec<u8> {
    let dir = case("pendulum");
    let xml = std::fs::read_to_string(dir.join("PENDULUM.xml")).expect("xml");
    let start = xml.find("<SimpleJoint>").expect("first joint");
    let end = xml[start..].find("</SimpleJoint>").expect("joint end") + start + "</SimpleJoint>".len();
    assert!(xml[start..end].contains("RootPart--LINK"), "the first joint is the revolute");
    let mut edited = format!("{}{}", &xml[..start], &xml[end..]);
    assert_eq!(edited.matches("<name>\"LINK\"</name>").count(), 1);
    edited = edited.replace("<name>\"LINK\"</name>", "<name>\"ROD\"</name>");
    let stl = std::fs::read(dir.join("meshes/LINK_prt.stl")).expect("stl");
    write_zip(&[("PENDULUM.xml".into(), edited.into_bytes()), ("meshes/LINK_prt.stl".into(), stl)]).expect("zip")
}

fn zip_entries(bytes: &[u8]) -> Vec<String> {
    let z = zip::ZipArchive::new(std::io::Cursor::new(bytes.to_vec())).expect("a valid zip");
    z.file_names().map(str::to_string).collect()
}

fn header(r: &reqwest::Response, name: &str) -> String {
    r.headers().get(name).and_then(|v| v.to_str().ok()).unwrap_or_default().to_string()
}

async fn json(r: reqwest::Response, status: u16) -> Value {
    let got = r.status().as_u16();
    let text = r.text().await.expect("body");
    assert_eq!(got, status, "{text}");
    serde_json::from_str(&text).expect("json")
}

#[tokio::test]
async fn upload_convert_and_download() {
    let app = TestApp::spawn().await;
    let r = app.upload_model(pendulum(), "pendulum.zip", &[]).await;
    assert_eq!(r.status(), 202);
    let location = header(&r, "location");
    let body: Value = r.json().await.expect("json");
    assert_eq!(body["version"], 1);
    let (model_id, job_id) = (body["model_id"].as_str().expect("id"), body["job_id"].as_str().expect("job"));
    assert_eq!(location, format!("/api/jobs/{job_id}"));

    let job = app.wait_for_job(job_id).await;
    assert_eq!(job["status"], "succeeded", "{job:#}");
    assert_eq!((job["kind"].as_str(), job["model_id"].as_str(), job["version"].as_i64()), (Some("convert"), Some(model_id), Some(1)));
    assert!(job.get("error").is_none());
    for t in ["created_at", "started_at", "finished_at"] {
        assert!(job[t].as_str().is_some_and(|s| s.ends_with('Z')), "{t} in {job}");
    }

    let r = app.package(model_id, 1).await;
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "content-type"), "application/zip");
    assert_eq!(header(&r, "content-disposition"), "attachment; filename=\"PENDULUM-v1.zip\"");
    let zip = r.bytes().await.expect("bytes");
    let entries = zip_entries(&zip);
    assert!(entries.iter().any(|e| e == "PENDULUM/Mechanics.mo"), "{entries:?}");
    assert!(entries.iter().any(|e| e == "report.json"));

    let r = app.report(model_id, 1).await;
    assert_eq!(header(&r, "content-type"), "application/json");
    let report = json(r, 200).await;
    assert_eq!(report["package_name"], "PENDULUM");
    assert_eq!(report["bodies"].as_array().map(Vec::len), Some(2));
    // The report is the one inside the package.
    let mut z = zip::ZipArchive::new(std::io::Cursor::new(zip.to_vec())).expect("zip");
    let mut inner = String::new();
    z.by_name("report.json").expect("report.json").read_to_string(&mut inner).expect("read");
    assert_eq!(serde_json::from_str::<Value>(&inner).expect("json"), report);

    // The URDF beside the package: the package's own `<Pkg>/<Pkg>.urdf`, linked from the version.
    let r = app.get(&format!("/api/models/{model_id}/versions/1/robot.urdf")).await;
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "content-type"), "application/xml");
    assert_eq!(header(&r, "content-disposition"), "attachment; filename=\"PENDULUM-v1.urdf\"");
    let urdf = r.text().await.expect("text");
    let mut inner = String::new();
    z.by_name("PENDULUM/PENDULUM.urdf").expect("urdf in the package").read_to_string(&mut inner).expect("read");
    assert_eq!(urdf, inner);
    assert!(urdf.contains("<robot name=\"PENDULUM\">") && urdf.contains("<link name=\"LINK\">"), "{urdf}");

    let v = json(app.version(model_id, 1).await, 200).await;
    assert_eq!(v["links"]["urdf"], format!("/api/models/{model_id}/versions/1/robot.urdf"));
    assert_eq!(v["status"], "succeeded");
    assert_eq!(v["job_id"], job_id);
    assert_eq!(v["bundle"]["name"], "pendulum.zip");
    assert_eq!(v["bundle"]["size"], pendulum().len());
    assert_eq!(v["summary"]["bodies"], 2);
    assert_eq!(v["summary"]["joints"], 2);
    assert_eq!(v["summary"]["package_name"], "PENDULUM");
    // No gravity uploaded: stored as none, the source's convention (SimMechanics: -y) applies.
    assert_eq!(v["options"]["gravity"], serde_json::Value::Null);
    assert!(v.get("error").is_none());

    // The model is named after the assembly when no name is given.
    let m = json(app.model(model_id).await, 200).await;
    assert_eq!(m["name"], "PENDULUM");
}

#[tokio::test]
async fn versions_list_get_delete() {
    let app = TestApp::spawn().await;
    let (id, v1, job1) = app.upload_model_ok(pendulum(), &[("name", "My pendulum")]).await;
    assert_eq!(v1, 1);
    let options = [("package_name", "Pend"), ("gravity", "0,0,-9.81"), ("lump_welds", "true")];
    let (id2, v2, job2) = app.upload_version_ok(&id, pendulum(), &options).await;
    assert_eq!((id2.as_str(), v2), (id.as_str(), 2));
    assert_eq!(app.wait_for_job(&job1).await["status"], "succeeded");
    assert_eq!(app.wait_for_job(&job2).await["status"], "succeeded");

    let list = json(app.models().await, 200).await;
    let list = list.as_array().expect("array");
    assert_eq!(list.len(), 1);
    assert_eq!(list[0]["id"], id.as_str());
    assert_eq!(list[0]["name"], "My pendulum");
    assert_eq!(list[0]["latest_version"], serde_json::json!({"version": 2, "status": "succeeded"}));

    let m = json(app.model(&id).await, 200).await;
    assert_eq!(m["versions"].as_array().map(Vec::len), Some(2));
    let v = json(app.version(&id, 2).await, 200).await;
    assert_eq!(v["options"], serde_json::json!({"package_name": "Pend", "gravity": [0.0, 0.0, -9.81], "lump_welds": true}));
    assert_eq!(v["summary"]["package_name"], "Pend");
    let r = app.package(&id, 2).await;
    assert!(zip_entries(&r.bytes().await.expect("bytes")).iter().any(|e| e == "Pend/Mechanics.mo"));

    // Delete version 1; numbers are never reused.
    assert_eq!(app.delete_version(&id, 1).await.status(), 204);
    problem(app.version(&id, 1).await, 404).await;
    problem(app.delete_version(&id, 1).await, 404).await;
    problem(app.job(&job1).await, 404).await;
    let versions = json(app.versions(&id).await, 200).await;
    assert_eq!(versions.as_array().map(|a| a.iter().map(|v| v["version"].as_i64()).collect::<Vec<_>>()), Some(vec![Some(2)]));
    let (_, v3, job3) = app.upload_version_ok(&id, pendulum(), &[]).await;
    assert_eq!(v3, 3);
    app.wait_for_job(&job3).await;

    // Delete the model: versions and jobs go with it.
    assert_eq!(app.delete_model(&id).await.status(), 204);
    problem(app.model(&id).await, 404).await;
    problem(app.versions(&id).await, 404).await;
    problem(app.job(&job2).await, 404).await;
    problem(app.delete_model(&id).await, 404).await;
    assert_eq!(json(app.models().await, 200).await, serde_json::json!([]));
}

#[tokio::test]
async fn the_original_bundle_round_trips() {
    let app = TestApp::spawn().await;
    let bundle = pendulum();
    let r = app.upload_model(bundle.clone(), "C:\\exports\\my \"pendulum\".zip", &[]).await;
    let (id, _, job) = cad2mo_tests::app_models::accepted(r).await;
    let r = app.bundle(&id, 1).await;
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "content-type"), "application/zip");
    assert_eq!(header(&r, "content-disposition"), "attachment; filename=\"my__pendulum_.zip\"");
    assert_eq!(r.bytes().await.expect("bytes").to_vec(), bundle);
    app.wait_for_job(&job).await;
}

#[tokio::test]
async fn diff_between_versions() {
    let app = TestApp::spawn().await;
    let (id, _, j1) = app.upload_model_ok(pendulum(), &[]).await;
    let (_, v2, j2) = app.upload_version_ok(&id, pendulum_edited(), &[]).await;
    assert_eq!(app.wait_for_job(&j1).await["status"], "succeeded");
    let job2 = app.wait_for_job(&j2).await;
    assert_eq!(job2["status"], "succeeded", "{job2:#}");

    let d = json(app.diff(&id, 1, v2).await, 200).await;
    assert_eq!((d["model_id"].as_str(), d["from"].as_i64(), d["to"].as_i64()), (Some(id.as_str()), Some(1), Some(2)));
    // The revolute is gone.
    let removed = d["joints"]["removed"].as_array().expect("removed");
    assert_eq!(removed.len(), 1, "{d:#}");
    assert_eq!(removed[0]["node_id"], "23:-:PENDULUM/RootPart");
    assert_eq!(removed[0]["cad_name"], "RootPart--LINK");
    assert_eq!(d["joints"]["added"], serde_json::json!([]));
    assert_eq!(d["bodies"]["added"], serde_json::json!([]));
    assert_eq!(d["bodies"]["removed"], serde_json::json!([]));
    // The link is renamed in CAD (same node ID): its CAD name changes, its Modelica name is kept
    // (drives and user code refer to it), physics does not change.
    let changed = d["bodies"]["changed"].as_array().expect("changed");
    assert_eq!(changed.len(), 1, "{d:#}");
    assert_eq!(changed[0]["node_id"], "23");
    let changes = changed[0]["changes"].as_array().expect("changes");
    let cad = changes.iter().find(|c| c["field"] == "cad_name").expect("cad_name change");
    assert_eq!((cad["old"].as_str(), cad["new"].as_str()), (Some("LINK"), Some("ROD")));
    assert!(changes.iter().all(|c| c["field"] != "modelica_name"), "{changes:?}");
    assert!(changes.iter().all(|c| c["field"] != "mass" && c["field"] != "cg_world"), "{changes:?}");

    // The other way round, the joint is added.
    let back = json(app.diff(&id, 2, 1).await, 200).await;
    assert_eq!(back["joints"]["added"][0]["node_id"], "23:-:PENDULUM/RootPart");
    assert_eq!(back["joints"]["removed"], serde_json::json!([]));
    // A version against itself: nothing.
    let same = json(app.diff(&id, 1, 1).await, 200).await;
    assert_eq!(same["bodies"]["changed"], serde_json::json!([]));
    assert_eq!(same["joints"]["changed"], serde_json::json!([]));

    problem(app.diff(&id, 1, 9).await, 404).await;
    problem(app.diff("nope", 1, 2).await, 404).await;
    problem(app.get(&format!("/api/models/{id}/diff")).await, 400).await;
    problem(app.get(&format!("/api/models/{id}/diff?from=a&to=2")).await, 400).await;
}

/// A zip with the given entries (names taken as they are).
fn raw_zip(entries: &[(&str, &[u8])], level: Option<i64>) -> Vec<u8> {
    let mut out = std::io::Cursor::new(Vec::new());
    let mut z = zip::ZipWriter::new(&mut out);
    let opts = zip::write::SimpleFileOptions::default().compression_method(zip::CompressionMethod::Deflated).compression_level(level);
    for (name, bytes) in entries {
        z.start_file(*name, opts).expect("start");
        z.write_all(bytes).expect("write");
    }
    z.finish().expect("finish");
    out.into_inner()
}

/// Every upload refusal names the bundle, creates nothing, and is a problem document.
#[tokio::test]
async fn bad_bundles_are_refused_with_problems() {
    let app = TestApp::spawn().await;

    let p = problem(app.upload_model(b"this is not a zip".to_vec(), "notes.zip", &[]).await, 422).await;
    assert!(p["detail"].as_str().expect("detail").contains("notes.zip"), "{p}");
    assert_eq!(p["errors"][0]["field"], "bundle");

    let xml = std::fs::read(case("pendulum").join("PENDULUM.xml")).expect("xml");
    let traversal = raw_zip(&[("PENDULUM.xml", &xml), ("../../evil.stl", b"solid x\nendsolid x\n")], None);
    let p = problem(app.upload_model(traversal, "evil.zip", &[]).await, 422).await;
    let detail = p["detail"].as_str().expect("detail");
    assert!(detail.contains("evil.zip") && detail.contains("unsafe path"), "{p}");

    let zeros = vec![0u8; 16 << 20];
    let bomb = raw_zip(&[("PENDULUM.xml", &xml), ("zeros.stl", &zeros)], Some(9));
    let p = problem(app.upload_model(bomb, "bomb.zip", &[]).await, 422).await;
    let detail = p["detail"].as_str().expect("detail");
    assert!(detail.contains("bomb.zip") && detail.contains("zip bomb"), "{p}");

    let p = problem(app.upload_model(zip_dir(&case("broken_dangling_ref")), "dangling.zip", &[]).await, 422).await;
    assert_eq!(p["type"], "/problems/conversion-failed");
    let d = &p["diagnostics"][0];
    assert_eq!(d["file"], "BROKEN.xml", "{p}");
    assert!(d["line"].as_u64().is_some_and(|l| l > 0), "{p}");
    assert!(d["column"].as_u64().is_some_and(|c| c > 0), "{p}");
    assert!(d["message"].as_str().expect("message").contains("9999"), "{p}");

    let p = problem(app.upload_model(zip_dir(&case("broken_unknown_unit")), "unit.zip", &[]).await, 422).await;
    assert!(p["diagnostics"][0]["message"].as_str().expect("message").contains("furlong"), "{p}");
    assert!(p["diagnostics"][0]["line"].as_u64().is_some_and(|l| l > 0), "{p}");

    // Bad options.
    let p = problem(app.upload_model(pendulum(), "p.zip", &[("gravity", "0,-9.81")]).await, 422).await;
    assert_eq!(p["errors"][0]["field"], "gravity");
    let p = problem(app.upload_model(pendulum(), "p.zip", &[("package_name", "model")]).await, 422).await;
    assert_eq!(p["errors"][0]["field"], "package_name");
    let p = problem(app.upload_model(pendulum(), "p.zip", &[("lump_welds", "maybe")]).await, 422).await;
    assert_eq!(p["errors"][0]["field"], "lump_welds");
    let p = problem(app.upload_model(pendulum(), "p.zip", &[("colour", "red")]).await, 422).await;
    assert_eq!(p["errors"][0]["field"], "colour");

    // No bundle part; not multipart at all.
    let form = reqwest::multipart::Form::new().text("name", "x");
    let p = problem(app.post_model_form(form).await, 422).await;
    assert_eq!(p["errors"][0]["field"], "bundle");
    let r = app.client.post(app.url("/api/models")).json(&serde_json::json!({"bundle": "x"})).send().await.expect("request");
    problem(r, 400).await;

    // Nothing was created.
    assert_eq!(json(app.models().await, 200).await, serde_json::json!([]));
}

#[tokio::test]
async fn oversized_uploads_are_413() {
    let limit = 16 * 1024;
    let app = TestApp::spawn_with(|s| s.max_upload = limit).await;
    let big: Vec<u8> = (0..(limit as usize * 2)).map(|i| (i * 7919 % 251) as u8).collect();
    let p = problem(app.upload_model(big.clone(), "big.zip", &[]).await, 413).await;
    assert!(p["detail"].as_str().expect("detail").contains(&limit.to_string()), "{p}");

    // Without a Content-Length (chunked), the limit still holds while reading.
    let addr = app.address.trim_start_matches("http://").to_string();
    let (status, content_type) = tokio::task::spawn_blocking(move || chunked_upload(&addr, &big)).await.expect("join");
    assert_eq!(status, 413);
    assert_eq!(content_type, "application/problem+json");

    // Under the limit is fine.
    let (_, _, job) = app.upload_model_ok(pendulum(), &[]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");
}

/// Sends a multipart upload with `Transfer-Encoding: chunked` over a plain socket and returns
/// the answer's status and content type.
fn chunked_upload(addr: &str, bundle: &[u8]) -> (u16, String) {
    let boundary = "cad2moBoundary";
    let mut body = format!(
        "--{boundary}\r\nContent-Disposition: form-data; name=\"bundle\"; filename=\"big.zip\"\r\nContent-Type: application/zip\r\n\r\n"
    )
    .into_bytes();
    body.extend_from_slice(bundle);
    body.extend_from_slice(format!("\r\n--{boundary}--\r\n").as_bytes());
    let mut s = std::net::TcpStream::connect(addr).expect("connect");
    let head = format!(
        "POST /api/models HTTP/1.1\r\nHost: {addr}\r\nX-Requested-With: cad2mo\r\nContent-Type: multipart/form-data; boundary={boundary}\r\nTransfer-Encoding: chunked\r\nConnection: close\r\n\r\n"
    );
    let mut request = head.into_bytes();
    for chunk in body.chunks(4096) {
        request.extend_from_slice(format!("{:x}\r\n", chunk.len()).as_bytes());
        request.extend_from_slice(chunk);
        request.extend_from_slice(b"\r\n");
    }
    request.extend_from_slice(b"0\r\n\r\n");
    // The server may answer and close before reading everything: a failed write is fine.
    let _ = s.write_all(&request);
    let mut answer = Vec::new();
    let _ = s.read_to_end(&mut answer);
    let text = String::from_utf8_lossy(&answer);
    let status = text.split_whitespace().nth(1).and_then(|s| s.parse().ok()).expect("a status line");
    let content_type =
        text.lines().find_map(|l| l.to_ascii_lowercase().strip_prefix("content-type:").map(|v| v.trim().to_string())).unwrap_or_default();
    (status, content_type)
}

#[tokio::test]
async fn unknown_things_are_404() {
    let app = TestApp::spawn().await;
    problem(app.model("nope").await, 404).await;
    problem(app.versions("nope").await, 404).await;
    problem(app.version("nope", 1).await, 404).await;
    problem(app.package("nope", 1).await, 404).await;
    problem(app.report("nope", 1).await, 404).await;
    problem(app.bundle("nope", 1).await, 404).await;
    problem(app.job("nope").await, 404).await;
    problem(app.delete_model("nope").await, 404).await;
    problem(app.upload_version("nope", pendulum(), "p.zip", &[]).await, 404).await;
    let (id, _, job) = app.upload_model_ok(pendulum(), &[]).await;
    problem(app.version(&id, 2).await, 404).await;
    problem(app.version(&id, "abc").await, 404).await;
    problem(app.package(&id, 7).await, 404).await;
    problem(app.get(&format!("/api/models/{id}/versions/7/robot.urdf")).await, 404).await;
    problem(app.get("/api/models/nope/versions/1/robot.urdf").await, 404).await;
    app.wait_for_job(&job).await;
}

async fn open_store(dir: &Path) -> cad2mo_server::store::Store {
    let url = cad2mo_tests::app::database_url_for(dir).await;
    cad2mo_server::store::Store::open(&url).await.expect("store")
}

/// A job interrupted mid-conversion: downloads answer 409 until it is done, and a restart
/// finishes it.
#[tokio::test]
async fn interrupted_jobs_resume_after_a_restart() {
    let app = TestApp::spawn().await;
    let (id, _, job) = app.upload_model_ok(pendulum(), &[]).await;
    // A second upload, and a stop before the workers can be sure to have finished it.
    let (id2, _, job2) = app.upload_model_ok(pendulum_edited(), &[]).await;
    let dir = app.stop().await;

    // Whatever the workers managed, make the first job look like a crash in the middle.
    let store = open_store(dir.path()).await;
    assert!(cad2mo_server::store::models::mark_interrupted(&store.pool, &job).await.expect("mark"));
    assert!(!cad2mo_server::store::models::mark_interrupted(&store.pool, "nope").await.expect("mark"));
    store.pool.close().await;

    // The restarted server re-queues and finishes it.
    let app = TestApp::spawn_in(dir, |_| {}).await;
    let first = app.wait_for_job(&job).await;
    assert_eq!(first["status"], "succeeded", "{first:#}");
    assert_eq!(app.wait_for_job(&job2).await["status"], "succeeded");
    let r = app.package(&id, 1).await;
    assert_eq!(r.status(), 200);
    assert!(zip_entries(&r.bytes().await.expect("bytes")).iter().any(|e| e == "PENDULUM/Mechanics.mo"));
    assert_eq!(json(app.report(&id2, 1).await, 200).await["package_name"], "PENDULUM");

    // The database is intact: both models, each with its version.
    let models = json(app.models().await, 200).await;
    assert_eq!(models.as_array().map(Vec::len), Some(2));
    for m in models.as_array().expect("array") {
        assert_eq!(m["latest_version"]["status"], "succeeded");
    }

    // Interrupt again while this server runs: its workers do not see it, downloads say 409.
    // Both jobs this time: a stop with several jobs running charges none of them (crash
    // accounting), so however the first restart went, neither is quarantined here.
    let store = open_store(app.data_dir()).await;
    assert!(cad2mo_server::store::models::mark_interrupted(&store.pool, &job).await.expect("mark"));
    assert!(cad2mo_server::store::models::mark_interrupted(&store.pool, &job2).await.expect("mark"));
    store.pool.close().await;
    let p = problem(app.package(&id, 1).await, 409).await;
    assert!(p["detail"].as_str().expect("detail").contains(&job), "{p}");
    problem(app.report(&id, 1).await, 409).await;
    problem(app.get(&format!("/api/models/{id}/versions/1/robot.urdf")).await, 409).await;
    problem(app.diff(&id, 1, 1).await, 409).await;
    assert_eq!(json(app.job(&job).await, 200).await["status"], "running");
    let dir = app.stop().await;
    let app = TestApp::spawn_in(dir, |_| {}).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");
    assert_eq!(app.wait_for_job(&job2).await["status"], "succeeded");
    assert_eq!(app.package(&id, 1).await.status(), 200);
}

/// A conversion that fails in the worker (here: a version whose stored bundle has broken XML,
/// queued through the store behind the upload check's back) keeps its problem: on the job, the
/// version and downloads. (Replacing a stored blob's bytes instead is caught on read: blobs are
/// verified against their hash.)
#[tokio::test]
async fn failed_conversions_keep_their_problem() {
    let app = TestApp::spawn().await;
    let dir = app.stop().await;
    let broken = zip_dir(&case("broken_dangling_ref"));
    let sha = cad2mo_server::store::blobs::Blobs::new(dir.path()).expect("blobs").put(&broken).expect("put");
    let store = open_store(dir.path()).await;
    let version = cad2mo_server::store::models::NewVersion {
        bundle_name: "bundle.zip",
        bundle_sha256: &sha,
        bundle_size: broken.len() as i64,
        options_json: "{}",
        triangles: None,
        bundle_bytes: None,
    };
    let created = cad2mo_server::store::models::create_model(&store.pool, "PENDULUM", &version).await.expect("queued");
    let (id, job) = (created.model_id, created.job_id);
    store.pool.close().await;

    let app = TestApp::spawn_in(dir, |_| {}).await;
    let done = app.wait_for_job(&job).await;
    assert_eq!(done["status"], "failed");
    assert_eq!(done["error"]["type"], "/problems/conversion-failed", "{done:#}");
    assert!(done["error"]["diagnostics"][0]["message"].as_str().expect("message").contains("9999"));
    assert!(done["finished_at"].is_string());

    let p = problem(app.package(&id, 1).await, 422).await;
    assert_eq!(p, done["error"]);
    problem(app.report(&id, 1).await, 422).await;
    problem(app.get(&format!("/api/models/{id}/versions/1/robot.urdf")).await, 422).await;
    problem(app.diff(&id, 1, 1).await, 409).await;
    let v = json(app.version(&id, 1).await, 200).await;
    assert_eq!((v["status"].as_str(), &v["error"]), (Some("failed"), &done["error"]));
    assert!(v.get("summary").is_none());
    assert_eq!(json(app.models().await, 200).await[0]["latest_version"]["status"], "failed");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn twenty_uploads_at_once() {
    let app = Arc::new(TestApp::spawn().await);
    let bundle = pendulum();
    let mut tasks = tokio::task::JoinSet::new();
    for i in 0..20 {
        let (app, bundle) = (app.clone(), bundle.clone());
        tasks.spawn(async move {
            let name = format!("pendulum {i}");
            let r = app.post_model_form(upload_form(bundle, "p.zip", &[("name", &name)])).await;
            let (id, _, job) = cad2mo_tests::app_models::accepted(r).await;
            let done = app.wait_for_job(&job).await;
            assert_eq!(done["status"], "succeeded", "{done:#}");
            assert_eq!(app.package(&id, 1).await.status(), 200);
            id
        });
    }
    let mut ids = Vec::new();
    while let Some(id) = tasks.join_next().await {
        ids.push(id.expect("task"));
    }
    ids.sort();
    ids.dedup();
    assert_eq!(ids.len(), 20);
    assert_eq!(json(app.models().await, 200).await.as_array().map(Vec::len), Some(20));
}

/// A queued job says where it stands, a running one how far it is: its stages in order, its
/// fraction never going back, and neither once it has finished.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn jobs_report_queue_position_and_progress() {
    let app = TestApp::spawn_with(|s| s.workers = 1).await;
    let heavy: Value = app.upload_model(heavy_pendulum(300_000), "heavy.zip", &[]).await.json().await.expect("json");
    let light: Value = app.upload_model(pendulum(), "light.zip", &[]).await.json().await.expect("json");
    let (heavy_job, light_job) = (heavy["job_id"].as_str().expect("job"), light["job_id"].as_str().expect("job"));

    // One worker, busy with the heavy job for seconds (once its dispatcher has claimed it: on
    // PostgreSQL the claim takes a moment): the light one waits, first in line.
    let claimed_by = std::time::Instant::now() + std::time::Duration::from_secs(20);
    loop {
        let h: Value = app.job(heavy_job).await.json().await.expect("json");
        if h["status"] != "queued" || std::time::Instant::now() > claimed_by {
            break;
        }
        tokio::time::sleep(std::time::Duration::from_millis(20)).await;
    }
    let queued: Value = app.job(light_job).await.json().await.expect("json");
    assert_eq!(queued["status"], "queued", "{queued:#}");
    assert_eq!(queued["queue"], serde_json::json!({"ahead": 0, "running": 1}), "{queued:#}");
    assert!(queued.get("progress").is_none());

    let order = ["xml", "meshes", "vrml", "analysis", "modelica", "collision", "shapes", "report", "package", "storing"];
    let mut seen: Vec<(usize, f64)> = Vec::new();
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(120);
    let done = loop {
        let job: Value = app.job(heavy_job).await.json().await.expect("json");
        if job["status"] != "running" {
            if job["status"] == "succeeded" || job["status"] == "failed" {
                break job;
            }
            continue;
        }
        assert!(job.get("queue").is_none(), "{job:#}");
        if let Some(p) = job.get("progress") {
            let stage = order.iter().position(|s| *s == p["stage"]).unwrap_or_else(|| panic!("unknown stage in {p}"));
            let fraction = p["fraction"].as_f64().expect("fraction");
            assert!((0.0..=1.0).contains(&fraction), "{p}");
            assert!(p["done"].as_u64() <= p["total"].as_u64() && p["total"].as_u64() >= Some(1), "{p}");
            assert!(p["label"].as_str().is_some_and(|l| !l.is_empty()), "{p}");
            if let Some(&(s, f)) = seen.last() {
                assert!(stage >= s && fraction >= f, "progress went back: {:?} then {p}", seen);
            }
            seen.push((stage, fraction));
        }
        assert!(std::time::Instant::now() < deadline, "the heavy job takes over 120 s");
        tokio::time::sleep(std::time::Duration::from_millis(5)).await;
    };
    assert_eq!(done["status"], "succeeded", "{done:#}");
    assert!(done.get("progress").is_none() && done.get("queue").is_none(), "{done:#}");
    let stages: std::collections::BTreeSet<usize> = seen.iter().map(|s| s.0).collect();
    assert!(stages.len() >= 2, "watched the heavy job in several stages: {seen:?}");
    assert_eq!(app.wait_for_job(light_job).await["status"], "succeeded");
}

/// Upload checks are bounded: with one check at a time and a slow one in flight, another upload
/// waits briefly, then gets 503 with Retry-After; once the slow one is done uploads work again.
#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn uploads_beyond_the_check_bound_get_503() {
    let app = Arc::new(
        TestApp::spawn_with(|s| {
            s.max_checks = 1;
            // Short, so that a light upload arriving during the heavy check is refused even
            // though the optimised engine checks 400,000 triangles in a fraction of a second.
            s.check_wait = std::time::Duration::from_millis(20);
        })
        .await,
    );
    let heavy = heavy_pendulum(400_000);
    let slow = {
        let app = app.clone();
        tokio::spawn(async move {
            let started = std::time::Instant::now();
            let r = app.upload_model(heavy, "heavy.zip", &[]).await;
            (r.status().as_u16(), started.elapsed())
        })
    };
    // Light uploads, one after the other, until one arrives while the heavy check runs.
    let mut refused = None;
    let mut accepted = 0;
    while !slow.is_finished() {
        let r = app.upload_model(pendulum(), "light.zip", &[]).await;
        if r.status() == 503 {
            let retry = header(&r, "retry-after");
            refused = Some((retry, problem(r, 503).await));
            break;
        }
        assert_eq!(r.status(), 202, "{}", r.text().await.unwrap_or_default());
        accepted += 1;
        tokio::time::sleep(std::time::Duration::from_millis(20)).await;
    }
    let (retry, p) = refused.expect("an upload during the heavy check was refused");
    assert!(retry.parse::<u64>().is_ok_and(|s| s >= 1), "Retry-After: {retry:?}");
    assert_eq!(p["type"], "/problems/busy", "{p}");
    let (status, took) = slow.await.expect("join");
    assert_eq!(status, 202, "the heavy upload itself is accepted (took {took:?}, {accepted} light ones before)");
    // Free again.
    let (_, _, job) = app.upload_model_ok(pendulum(), &[]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");
}

/// A job whose conversion kills the service (simulated: left `running`, alone, by a "crash"
/// after each start) is run until it has stopped the service MAX_ABORTS times, then quarantined:
/// failed with a clear problem, not run again, listed by `GET /api/jobs`.
#[tokio::test]
async fn a_job_that_keeps_stopping_the_service_is_failed() {
    let max = cad2mo_server::jobs::MAX_ABORTS;
    let app = TestApp::spawn().await;
    let (id, _, job) = app.upload_model_ok(pendulum(), &[]).await;
    app.wait_for_job(&job).await;
    let mut dir = app.stop().await;
    for stops in 1..=max {
        let store = open_store(dir.path()).await;
        assert!(cad2mo_server::store::models::mark_interrupted(&store.pool, &job).await.expect("mark"));
        store.pool.close().await;
        let app = TestApp::spawn_in(dir, |_| {}).await;
        let done = app.wait_for_job(&job).await;
        if stops < max {
            assert_eq!(done["status"], "succeeded", "after {stops} stop(s) it runs: {done:#}");
            assert_eq!(app.get("/api/jobs").await.json::<serde_json::Value>().await.expect("json")["quarantined"], serde_json::json!([]));
        } else {
            assert_eq!(done["status"], "failed", "after {stops} stops it is not run: {done:#}");
            assert_eq!(done["error"]["type"], "/problems/conversion-aborted", "{done:#}");
            let detail = done["error"]["detail"].as_str().expect("detail");
            assert!(detail.contains(&format!("stopped the service {max} times")), "{detail}");
            let p = problem(app.package(&id, 1).await, 422).await;
            assert_eq!(p, done["error"]);
            let list: serde_json::Value = app.get("/api/jobs").await.json().await.expect("json");
            assert_eq!(list["quarantined"][0]["id"], job.as_str(), "{list:#}");
            // A new version is a new job: it runs.
            let (_, _, job2) = app.upload_version_ok(&id, pendulum(), &[]).await;
            assert_eq!(app.wait_for_job(&job2).await["status"], "succeeded");
        }
        dir = app.stop().await;
    }
}

/// A deep URDF chain (20,000 links, a few hundred KB) is refused at upload with the link limit
/// named; nothing is stored and the service answers on.
#[tokio::test]
async fn a_urdf_chain_over_the_link_limit_is_refused_at_upload() {
    use std::fmt::Write as _;
    let app = TestApp::spawn().await;
    let mut u = String::from("<robot name=\"deep\">");
    for i in 0..20_000 {
        let _ = write!(u, "<link name=\"l{i}\"/>");
    }
    for i in 1..20_000 {
        let _ = write!(
            u,
            "<joint name=\"j{i}\" type=\"revolute\"><parent link=\"l{}\"/><child link=\"l{i}\"/><axis xyz=\"0 0 1\"/></joint>",
            i - 1
        );
    }
    u.push_str("</robot>");
    let bundle = write_zip(&[("deep/deep.urdf".into(), u.into_bytes())]).expect("zip");
    let p = problem(app.upload_model(bundle, "deep.zip", &[]).await, 422).await;
    assert!(p["detail"].as_str().expect("detail").contains("more than 10000 links"), "{p}");
    assert_eq!(json(app.get("/api/models").await, 200).await, serde_json::json!([]));
    assert_eq!(app.get("/api/health").await.status().as_u16(), 200);
}

/// A graceful stop (Ctrl-C, SIGTERM) while a job runs alone is no crash: the job goes back to
/// the queue uncharged. Stopped so MAX_ABORTS times mid-run, it still converts at the next start
/// and is not quarantined (a kill, `stop`, would have charged each stop: see the test above).
#[tokio::test]
async fn graceful_stops_during_a_lone_job_are_not_counted_as_aborts() {
    let max = cad2mo_server::jobs::MAX_ABORTS;
    let app = TestApp::spawn_with(|s| s.workers = 1).await;
    let (_, _, job) = app.upload_model_ok(cad2mo_tests::app::heavy_pendulum(400_000), &[]).await;
    let mut app = app;
    for stop in 1..=max {
        // Wait until the job runs, then stop.
        let deadline = std::time::Instant::now() + std::time::Duration::from_secs(30);
        loop {
            let j: serde_json::Value = app.job(&job).await.json().await.expect("json");
            if j["status"] == "running" {
                break;
            }
            assert_ne!(j["status"], "succeeded", "stop {stop}: the job finished before the stop; make it heavier");
            assert!(std::time::Instant::now() < deadline, "not running: {j:#}");
            tokio::time::sleep(std::time::Duration::from_millis(20)).await;
        }
        let dir = app.stop_gracefully().await;
        let store = open_store(dir.path()).await;
        let row = cad2mo_server::store::models::get_job(&store.pool, &job).await.expect("job").expect("row");
        assert_eq!(row.status, "queued", "stop {stop}: put back in the queue");
        store.pool.close().await;
        app = TestApp::spawn_in(dir, |s| s.workers = 1).await;
    }
    let done = app.wait_for_job_within(&job, std::time::Duration::from_secs(120)).await;
    assert_eq!(done["status"], "succeeded", "{done:#}");
    assert_eq!(app.get("/api/jobs").await.json::<serde_json::Value>().await.expect("json")["quarantined"], serde_json::json!([]));
}
