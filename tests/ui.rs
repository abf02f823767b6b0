//! The browser UI: its static files as the service serves them, the browser-side kinematics
//! (node --test), and an end-to-end run in a real headless Chromium driven by playwright-core
//! (`web/e2e/ui.mjs`): upload, 3D pixels, picking, joint sliders, anaglyph, report, drives with a
//! refused and an accepted gear ratio, the regenerated package, the motor library (edit, export,
//! re-import), a slow conversion's progress and a narrow window. Screenshots go to `target/ui-screenshots/`.
//!
//! Chromium, Node and the npm packages are installed by the README's test command; without them
//! these tests print a notice and pass, unless `CAD2MO_REQUIRE_TOOLS=1` (which that command sets).

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::Command;

use cad2mo_tests::app::{heavy_pendulum, zip_dir, TestApp};
use cad2mo_tests::common::{tools_required, workspace_root};

fn web_dir() -> PathBuf {
    workspace_root().join("web")
}

/// `Some(reason)` when the browser test cannot run here.
fn missing_tools() -> Option<String> {
    let chromium = std::env::var("CHROMIUM").unwrap_or_else(|_| "/usr/bin/chromium".into());
    if !Path::new(&chromium).exists() {
        return Some(format!("no Chromium at {chromium}"));
    }
    if !web_dir().join("node_modules/playwright-core").exists() {
        return Some("web/node_modules has no playwright-core (run npm ci in web/)".into());
    }
    if Command::new("node").arg("--version").output().is_err() {
        return Some("no node".into());
    }
    None
}

fn skip_or_fail(why: &str) {
    assert!(!tools_required(), "the UI tests need their tools: {why}");
    println!("skipping the browser UI test: {why}");
}

#[tokio::test]
async fn static_files_have_types_caching_and_etags() {
    let app = TestApp::spawn().await;
    let client = reqwest::Client::new();
    let index = client.get(app.url("/")).send().await.expect("GET /");
    if index.status() == 503 {
        // Built without npm: the page says why, the API still works.
        let text = index.text().await.expect("body");
        assert!(text.contains("not built"), "{text}");
        skip_or_fail("the UI is not built into this binary");
        return;
    }
    assert_eq!(index.status(), 200);
    let h = index.headers().clone();
    assert!(h["content-type"].to_str().expect("type").starts_with("text/html"));
    assert_eq!(h["cache-control"], "no-cache");
    assert!(h["content-security-policy"].to_str().expect("csp").contains("default-src 'self'"));
    let html = index.text().await.expect("html");
    // The page carries no data: everything comes from the API.
    assert!(!html.contains("/api/"), "index.html has no data or API paths baked in");
    let script = html.split("src=\"").nth(1).and_then(|s| s.split('"').next()).expect("a script");
    assert!(script.starts_with("/assets/") && script.ends_with(".js"), "{script}");

    let js = client.get(app.url(script)).send().await.expect("GET script");
    assert_eq!(js.status(), 200);
    let etag = js.headers()["etag"].clone();
    assert!(js.headers()["content-type"].to_str().expect("type").contains("javascript"));
    assert_eq!(js.headers()["cache-control"], "public, max-age=31536000, immutable");
    assert!(js.headers().get("content-encoding").is_none(), "no gzip unless asked");
    assert!(!js.bytes().await.expect("js").is_empty());
    let again = client.get(app.url(script)).header("If-None-Match", etag.clone()).send().await.expect("revalidate");
    assert_eq!(again.status(), 304);
    // Gzipped for clients that take it: the same bytes once inflated, its own ETag.
    let gz = client.get(app.url(script)).header("Accept-Encoding", "gzip").send().await.expect("gzip");
    assert_eq!(gz.headers()["content-encoding"], "gzip");
    assert_eq!(gz.headers()["vary"], "accept-encoding");
    assert_ne!(gz.headers()["etag"], etag);
    let packed = gz.bytes().await.expect("gz body");
    let mut unpacked = Vec::new();
    flate2::read::GzDecoder::new(&packed[..]).read_to_end(&mut unpacked).expect("gunzip");
    let plain = client.get(app.url(script)).send().await.expect("plain").bytes().await.expect("body");
    assert_eq!(unpacked, plain.to_vec());
    assert!(packed.len() * 2 < plain.len(), "{} -> {}", plain.len(), packed.len());

    let css = html.split("href=\"").find_map(|s| s.split('"').next().filter(|p| p.ends_with(".css"))).expect("a stylesheet");
    let css = client.get(app.url(css)).send().await.expect("GET css");
    assert!(css.headers()["content-type"].to_str().expect("type").starts_with("text/css"));
    let icon = client.get(app.url("/favicon.svg")).send().await.expect("icon");
    assert_eq!(icon.headers()["content-type"], "image/svg+xml");

    let missing = client.get(app.url("/assets/nothing.js")).send().await.expect("404");
    assert_eq!(missing.status(), 404);
    assert_eq!(missing.headers()["content-type"], "application/problem+json");
}

#[test]
fn browser_kinematics_unit_tests() {
    if let Some(why) = missing_tools() {
        skip_or_fail(&why);
        return;
    }
    let out = Command::new("node").args(["--test", "src/"]).current_dir(web_dir()).output().expect("node --test");
    assert!(out.status.success(), "{}\n{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
}

/// A copy of a zip with one text entry edited.
fn rewrite_zip(zip: &[u8], entry: &str, edit: impl FnOnce(&mut String)) -> Vec<u8> {
    use std::io::Write;
    let mut input = zip::ZipArchive::new(std::io::Cursor::new(zip)).expect("zip");
    let mut out = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let mut edit = Some(edit);
    for i in 0..input.len() {
        let mut f = input.by_index(i).expect("entry");
        let name = f.name().to_string();
        let mut bytes = Vec::new();
        f.read_to_end(&mut bytes).expect("read entry");
        if name == entry {
            let mut text = String::from_utf8(bytes).expect("utf-8");
            edit.take().expect("one entry")(&mut text);
            bytes = text.into_bytes();
        }
        out.start_file(name, zip::write::SimpleFileOptions::default()).expect("start");
        out.write_all(&bytes).expect("write");
    }
    assert!(edit.is_none(), "{entry} is in the zip");
    out.finish().expect("finish").into_inner()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn end_to_end_in_chromium() {
    if let Some(why) = missing_tools() {
        skip_or_fail(&why);
        return;
    }
    let app = TestApp::spawn().await;
    if app.get("/").await.status() == 503 {
        skip_or_fail("the UI is not built into this binary");
        return;
    }
    let work = tempfile::tempdir().expect("tempdir");
    let bundle = work.path().join("arm.zip");
    let arm = workspace_root().join("tests/in/arm_subsystems");
    std::fs::write(&bundle, zip_dir(&arm)).expect("bundle");
    // Version 2: the CAD change removed the joint BASE--LINK (the first joint, which gets a drive)...
    let v2 = rewrite_zip(&std::fs::read(&bundle).expect("bundle"), "ARM_SIM_MODEL.xml", |xml| {
        let start = xml.find("<SimpleJoint>\n        <name>\"BASE--LINK\"").expect("the joint to remove");
        let end = start + xml[start..].find("</SimpleJoint>").expect("its end") + "</SimpleJoint>".len();
        xml.replace_range(start..end, "");
        // ... and made the fore link heavier.
        assert_eq!(xml.matches("<mass>0.31752</mass>").count(), 1);
        *xml = xml.replace("<mass>0.31752</mass>", "<mass>0.5</mass>");
    });
    let broken = work.path().join("broken.zip");
    std::fs::write(&broken, zip_dir(&workspace_root().join("tests/in/broken_truncated"))).expect("broken bundle");
    let heavy = work.path().join("heavy.zip");
    std::fs::write(&heavy, heavy_pendulum(1_000_000)).expect("heavy bundle");
    let bundle_v2 = work.path().join("arm-v2.zip");
    std::fs::write(&bundle_v2, v2).expect("bundle v2");
    let shots = workspace_root().join("target/ui-screenshots");
    std::fs::create_dir_all(&shots).expect("screenshot folder");
    let downloads = work.path().join("downloads");
    std::fs::create_dir_all(&downloads).expect("downloads");

    // The live view's sender: the C source packages ship, compiled into the test harness.
    let harness = cad2mo_tests::live::build_harness(cad2mo_engine::pipeline::back::modelica::mechatronics::live::C_SOURCE, work.path())
        .map(|p| p.display().to_string())
        .unwrap_or_default();
    let url = app.url("");
    let (bundle_s, shots_s, downloads_s) = (bundle.clone(), shots.clone(), downloads.clone());
    let out = tokio::task::spawn_blocking(move || {
        Command::new("node")
            .arg("e2e/ui.mjs")
            .current_dir(web_dir())
            .env("CAD2MO_URL", url.trim_end_matches('/'))
            .env("CAD2MO_BUNDLE", bundle_s)
            .env("CAD2MO_BUNDLE_V2", bundle_v2)
            .env("CAD2MO_BUNDLE_BROKEN", broken)
            .env("CAD2MO_BUNDLE_HEAVY", heavy)
            .env("CAD2MO_SCREENSHOTS", shots_s)
            .env("CAD2MO_DOWNLOADS", downloads_s)
            .env("CAD2MO_LIVE_HARNESS", harness)
            .output()
            .expect("node e2e/ui.mjs")
    })
    .await
    .expect("e2e task");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "the browser test failed:\n{stderr}\n{}", String::from_utf8_lossy(&out.stdout));
    let stdout = String::from_utf8_lossy(&out.stdout);
    let result: serde_json::Value = serde_json::from_str(stdout.lines().last().expect("a result line")).expect("result JSON");
    let joint = result["joint"].as_str().expect("joint");

    // The package the UI downloaded drives the chosen joint through a gear with ratio 100.
    let zip = std::fs::read(result["package"].as_str().expect("package path")).expect("downloaded package");
    let mut archive = zip::ZipArchive::new(std::io::Cursor::new(zip)).expect("a zip");
    let name = archive.file_names().find(|n| n.ends_with("/Mechatronics.mo")).expect("Mechatronics.mo").to_string();
    let mut mech = String::new();
    archive.by_name(&name).expect("entry").read_to_string(&mut mech).expect("utf-8");
    let start = mech.find(&format!(" drive_{joint}(")).unwrap_or_else(|| panic!("no drive for {joint} in\n{mech}"));
    let decl = &mech[start..start + mech[start..].find("\"Drive of joint").expect("end of the declaration")];
    let gear = &decl[decl.find(" gear(").expect("a gear")..];
    let ratio: f64 = gear
        .split("ratio=")
        .nth(1)
        .and_then(|r| r.split([',', ')']).next())
        .and_then(|r| r.trim().parse().ok())
        .unwrap_or_else(|| panic!("no gear ratio in\n{decl}"));
    assert_eq!(ratio, 100.0, "the drive of {joint} has gear ratio 100:\n{decl}");
    assert!(mech.contains(&format!("connect(drive_{joint}.flange, {joint}.drive)")), "the drive is connected to {joint}:\n{mech}");

    // The exported library is the XML the UI downloaded, with the edited gain.
    let xml = std::fs::read_to_string(result["library"].as_str().expect("library path")).expect("library");
    assert!(xml.contains("RobotR3 axis controller"));
    // The Live tab followed the C sender's known motion (web/e2e/live.mjs checked the meshes'
    // poses against it, mid-stream, paused, a recorded frame back, replayed and after the end).
    let live = &result["live"];
    println!("live view: {live}");
    if live.get("skipped").is_none() {
        assert_eq!(live["sent"], 151, "the harness sent 3 s at 50 Hz: {live}");
        assert!(live["frames"].as_u64().is_some_and(|n| n > 0), "the page received frames: {live}");
        assert!(live["worst"].as_f64().is_some_and(|d| d < 1e-4), "the meshes followed the motion: {live}");
        // The dock player replayed the recording: paused, a frame back, 0.25x, then live again.
        assert!(live["recorded"].as_u64().is_some_and(|n| n > 0), "the frames were recorded: {live}");
        assert!(live["back"].as_f64().zip(live["mid"].as_f64()).is_some_and(|(b, m)| b < m), "one frame back: {live}");
        for png in ["24-live-paused", "24b-live-replay", "25-live-ended"] {
            assert!(shots.join(format!("{png}.png")).exists(), "screenshot {png}");
        }
    }
    // The Collision tab and the motion's check (web/e2e/collision.mjs): an interference made by
    // checking a joined pair, and the first contact of a motion that swings a link into the base.
    let collision = &result["collision"];
    println!("collisions: {collision}");
    assert!(collision["interference"]["depth"].as_f64().is_some_and(|d| d > 0.0), "an interference with its depth: {collision}");
    assert!(collision["first_contact"]["time"].as_f64().is_some_and(|t| t > 0.0), "the motion's first contact: {collision}");
    assert!(collision["min_distance"].as_f64().is_some_and(|d| d < 0.0), "the pair penetrates along the motion: {collision}");
    // The Modelica diagram tab (web/e2e/diagram.mjs): every body drawn, lines, the drive shown.
    let diagram = &result["diagram"];
    println!("diagram: {diagram}");
    assert!(diagram["components"].as_u64().is_some_and(|n| n >= 6), "components drawn: {diagram}");
    assert!(diagram["drives"].as_u64().is_some_and(|n| n >= 1), "the saved drive in the Mechatronics diagram: {diagram}");
    // The Scene tab (web/e2e/scene.mjs): a box moved by a real gizmo drag, placed by numbers in a
    // link, undone and redone, saved, and its interference with the link named.
    let scene = &result["scene"];
    println!("scene: {scene}");
    assert!(scene["dragged"][0].as_f64().is_some_and(|x| x > 0.0), "the gizmo moved the box along +x: {scene}");
    assert!(scene["link"].as_str().is_some_and(|l| !l.is_empty()), "the box's interference names a link: {scene}");
    // Made moving at a velocity, saved, the page reloaded: the values are back (scene.mjs asserts).
    assert!(scene["kind_seconds"].as_f64().is_some(), "the kind step ran: {scene}");
    for png in [
        "1-models-empty",
        "2-model-3d",
        "6-drives-refused",
        "6b-drives-refused-at-field",
        "7-drives-saved",
        "8-library",
        "10-model-versions",
        "12-narrow-model",
        "15-job-progress",
        "26-collision-interference",
        "27-collision-motion",
        "13f-narrow-collision",
        "28-modelica-diagram",
        "29-mechatronics-diagram",
        "34-scene-gizmo",
        "35-scene-interference",
        "36-scene-dropped",
        "37-scene-mesh-placed",
        "38-scene-kind",
    ] {
        assert!(shots.join(format!("{png}.png")).exists(), "screenshot {png}");
    }
    app.stop().await;
}

/// The joint sliders show what the Modelica model would do: for golden cases, every movable
/// coordinate of a tree joint outside loops is moved from its start value, the emitted
/// `Mechanics.mo` is walked at those values (tests/support/fk.rs, MSL semantics) and the
/// browser's kinematics (web/src/viewer/kinematics.js, from the report alone) must put every
/// body's CS1 frame at the same pose.
#[test]
fn browser_kinematics_match_the_modelica_model() {
    use cad2mo_tests::fk::{forward_kinematics, parse_mechanics, pose_error};
    use nalgebra::{Isometry3, Matrix3, Rotation3, Translation3, UnitQuaternion};
    if let Some(why) = missing_tools() {
        skip_or_fail(&why);
        return;
    }
    let cases = ["composite_joint", "rotated_frames", "arm_subsystems", "pendulum", "inch_lbm", "vrml_assembly"];
    let mut inputs = Vec::new();
    let mut expected = Vec::new();
    for case in cases {
        let dir = workspace_root().join("tests/out").join(case);
        let report: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).expect("report")).expect("json");
        let mut mo = std::fs::read_to_string(dir.join("Mechanics.mo")).expect("Mechanics.mo");
        let mut q = serde_json::Map::new();
        let mut n = 0;
        for j in report["joints"].as_array().expect("joints") {
            if j["in_tree"] != true || j["in_loop"] == true {
                continue;
            }
            for (k, e) in j["elements"].as_array().expect("elements").iter().enumerate() {
                let (var, d) = match e["kind"].as_str() {
                    Some("revolute") => ("phi", 0.37 + 0.21 * n as f64),
                    Some("prismatic") => ("s", 0.013 + 0.007 * n as f64),
                    _ => continue,
                };
                n += 1;
                let name = e["modelica_name"].as_str().expect("element name");
                let value = e["initial_q"].as_f64().expect("q0") + d;
                // Move the element in the Modelica text: its `phi(start=…` / `s(start=…`.
                let decl = mo.find(&format!(" {name}(\n")).unwrap_or_else(|| panic!("{case}: no declaration of {name}"));
                let key = format!("{var}(start=");
                let at = decl + mo[decl..].find(&key).expect("start value") + key.len();
                let end = at + mo[at..].find(',').expect("end of start value");
                mo.replace_range(at..end, &format!("{value:?}"));
                q.insert(format!("{}#{k}", j["modelica_name"].as_str().expect("joint")), value.into());
            }
        }
        assert!(n > 0, "{case} has movable tree joints");
        let model = parse_mechanics(&mo).unwrap_or_else(|e| panic!("{case}: {e}"));
        let poses = forward_kinematics(&model).unwrap_or_else(|e| panic!("{case}: {e}"));
        expected.push((case, poses));
        inputs.push(serde_json::json!({"report": report, "q": q}));
    }
    let work = tempfile::tempdir().expect("tempdir");
    let input = work.path().join("cases.json");
    std::fs::write(&input, serde_json::to_vec(&inputs).expect("json")).expect("write");
    let out = Command::new("node").arg("e2e/fk.mjs").arg(&input).current_dir(web_dir()).output().expect("node e2e/fk.mjs");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let browser: Vec<serde_json::Map<String, serde_json::Value>> = serde_json::from_slice(&out.stdout).expect("poses");
    let mut compared = 0;
    for ((case, poses), got) in expected.iter().zip(&browser) {
        for (body, m) in got {
            let Some(want) = poses.get(&format!("{body}.frame_a")) else { continue };
            let m: Vec<f64> = m.as_array().expect("matrix").iter().map(|x| x.as_f64().expect("number")).collect();
            // three.js matrices are column-major.
            let r = Matrix3::new(m[0], m[4], m[8], m[1], m[5], m[9], m[2], m[6], m[10]);
            let pose = Isometry3::from_parts(
                Translation3::new(m[12], m[13], m[14]),
                UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix(&r)),
            );
            let (dp, da) = pose_error(want, &pose);
            assert!(dp < 1e-9 && da < 1e-9, "{case}: {body} is {dp:e} m / {da:e} rad away from the Modelica pose");
            compared += 1;
        }
    }
    assert!(compared >= 15, "compared {compared} body poses");
}

/// Models render in the UI: our VRML assembly (colours and geometry matches from VRML) and the
/// four-bar (a closed loop), and, when `../shared` is there, real CAD exports written by others:
/// the self-contained iCub left hand (XML + STL, upper-case names resolved case-insensitively)
/// and the 29-body LEGS mechanism (XML only, closed loops). Each must draw where its meshes
/// project, list every body, and link its report into the 3D view. On the hand (11 joints with
/// long names) `web/e2e/workspace.mjs` checks the workspace (issue 30): on every tab at 1440×900
/// and 390×844 no control or table out of its panel or the window, the 3D view and Play on screen
/// together, the unit choice in the keyframe table and plots, exact typed slider values, four
/// viewports, side-by-side stereo and dual output (the right eye in a second window) drawn
/// (pixels), the measuring tool, Enter VR disabled with its reason (no WebXR in headless
/// Chromium); the hand's and LEGS' diagrams have an icon per component, names ≥ 9 px high or
/// hidden and no two names overlapping, and the hand's Mechatronics diagram short contact force
/// wires; PR2 (30 moving joints) gets the same reach checks at both sizes.
#[test]
fn models_render_in_chromium() {
    if let Some(why) = missing_tools() {
        skip_or_fail(&why);
        return;
    }
    let rt = tokio::runtime::Builder::new_multi_thread().worker_threads(2).enable_all().build().expect("runtime");
    let app = rt.block_on(TestApp::spawn());
    if rt.block_on(app.get("/")).status() == 503 {
        skip_or_fail("the UI is not built into this binary");
        return;
    }
    let work = tempfile::tempdir().expect("tempdir");
    let mut bundles = Vec::new();
    for case in ["vrml_assembly", "fourbar"] {
        let zip = work.path().join(format!("{case}.zip"));
        std::fs::write(&zip, zip_dir(&workspace_root().join("tests/in").join(case))).expect("zip");
        bundles.push(zip);
    }
    if let Some(fixtures) = cad2mo_tests::common::fixtures_dir("models_render_in_chromium (real exports)") {
        let hand = work.path().join("left_hand_mk3.zip");
        std::fs::write(&hand, zip_dir(&fixtures.join("stl/robotology+icub-models-generator/25e4033/left_hand_mk3"))).expect("zip");
        let legs_dir = work.path().join("legs");
        std::fs::create_dir_all(&legs_dir).expect("mkdir");
        std::fs::copy(fixtures.join("xml/robotology+simmechanics-to-urdf/a83a61f/LEGS_MECHANISM.xml"), legs_dir.join("LEGS_MECHANISM.xml"))
            .expect("copy");
        let legs = work.path().join("legs_mechanism.zip");
        std::fs::write(&legs, zip_dir(&legs_dir)).expect("zip");
        // PR2 (URDF, 82 links, 81 joints of which 30 move, 10 mimic): the workspace at the scale of 40+ joints.
        // Its meshes are named package://example-robot-data/robots/pr2_description/..., so the
        // bundle keeps that folder.
        let pr2_dir = fixtures.join("urdf/Gepetto+example-robot-data/39aa9437/robots/pr2_description");
        let files: Vec<(String, Vec<u8>)> = cad2mo_tests::common::files_with_ext(&pr2_dir, &[""])
            .into_iter()
            .map(|p| {
                let rel = p.strip_prefix(&pr2_dir).expect("under dir").to_string_lossy().replace('\\', "/");
                (format!("robots/pr2_description/{rel}"), std::fs::read(&p).expect("read"))
            })
            .collect();
        let pr2 = work.path().join("pr2.zip");
        std::fs::write(&pr2, cad2mo_engine::pipeline::back::bundle::write_zip(&files).expect("zip")).expect("zip");
        // The Onshape arm (issue 31): a second-generation export whose 16 parts are STEP files.
        let arm = work.path().join("onshape_arm.zip");
        std::fs::write(&arm, zip_dir(&fixtures.join("xml2/ErroujiOussama+Arm-Robot/8d2b4829/Simulation/Simscape"))).expect("zip");
        bundles.extend([hand, legs, pr2, arm]);
    }
    let shots = workspace_root().join("target/ui-screenshots");
    std::fs::create_dir_all(&shots).expect("screenshot folder");
    let out = Command::new("node")
        .arg("e2e/render.mjs")
        .args(&bundles)
        .current_dir(web_dir())
        .env("CAD2MO_URL", app.url("").trim_end_matches('/'))
        .env("CAD2MO_SCREENSHOTS", &shots)
        .output()
        .expect("node e2e/render.mjs");
    assert!(out.status.success(), "{}\n{}", String::from_utf8_lossy(&out.stderr), String::from_utf8_lossy(&out.stdout));
    let results: Vec<serde_json::Value> =
        serde_json::from_str(String::from_utf8_lossy(&out.stdout).lines().last().expect("result")).expect("json");
    assert_eq!(results.len(), bundles.len());
    assert_eq!(results[0]["meshes"], 3, "the VRML assembly's three parts are drawn: {}", results[0]);
    assert_eq!(results[1]["loops"], 1, "the four-bar's loop is reported: {}", results[1]);
    if let Some(hand) = results.get(2) {
        assert!(hand["meshes"].as_u64().expect("meshes") >= 10, "the hand's meshes are drawn: {hand}");
        assert!(results[3]["bodies"].as_u64().expect("bodies") >= 29, "{}", results[3]);
        // The workspace on the hand (web/e2e/workspace.mjs asserted the bounding boxes of every
        // tab at both sizes): every tab was checked, the 3D view and Play were on screen together.
        let ws = &hand["workspace"];
        for size in ["wide", "narrow"] {
            assert_eq!(ws[size]["viewAndPlay"]["play"], true, "{size}: {ws}");
            assert_eq!(ws[size]["tabs"].as_object().map(|t| t.len()), Some(9), "{size}: every tab checked: {ws}");
        }
        assert_eq!(ws["viewports"]["quad"].as_array().map(|q| q.len()), Some(4), "four viewports drawn: {ws}");
        // Dual output stereo: the left eye here, the right eye drawn in a second window.
        assert!(ws["viewports"]["dual"]["right"].as_f64().is_some_and(|s| s > 0.1), "the second window draws the right eye: {ws}");
        assert!(ws["viewports"]["distance"].as_f64().is_some_and(|d| d > 0.0), "a measured distance: {ws}");
        assert!(ws["viewports"]["collisionShapes"].as_u64().is_some_and(|n| n >= 10), "the hand's collision shapes shown: {ws}");
        for r in &results[2..4] {
            assert_eq!(r["diagram"]["icons"], r["diagram"]["components"], "an icon per diagram component: {r}");
        }
        // Immersive VR: headless Chromium offers none, so Enter VR is disabled with the reason.
        assert_eq!(ws["vr"]["xr"], "unsupported", "Enter VR disabled without WebXR: {ws}");
        assert!(ws["vr"]["reason"].as_str().is_some_and(|r| !r.is_empty()), "the reason is its tooltip: {ws}");
        // The hand's contact forces stand beside their bodies in the Mechatronics diagram.
        let contacts = &hand["diagram"]["contacts"];
        assert!(contacts["forces"].as_u64().is_some_and(|n| n >= 10), "the hand's contact forces drawn: {contacts}");
        // PR2's workspace at 1440×900: the same reach checks on every tab with 30 moving joints.
        let pr2 = &results[4];
        assert!(pr2["axes"].as_u64().is_some_and(|n| n >= 30), "PR2's 30 moving joints are drawn: {pr2}");
        assert!(pr2["bodies"].as_u64().is_some_and(|n| n >= 40), "PR2's bodies are listed: {pr2}");
        let ws = &pr2["workspace"];
        for size in ["wide", "narrow"] {
            assert_eq!(ws[size]["viewAndPlay"]["play"], true, "PR2 {size}: {ws}");
            assert_eq!(ws[size]["tabs"].as_object().map(|t| t.len()), Some(9), "PR2 {size}: every tab checked: {ws}");
        }
        // The Onshape arm: every body drawn from its STEP part, each coloured one in its colour
        // (checkModelPixels: at least 20 pixels of its chromaticity inside its own screen box).
        let arm = &results[5];
        assert!(arm["bodies"].as_u64().is_some_and(|n| n >= 16), "{arm}");
        assert_eq!(arm["meshes"], arm["bodies"], "every body of the Onshape arm has its STEP shape: {arm}");
        let seen =
            arm["pixels"]["colours"].as_array().map_or(0, |c| c.iter().filter(|b| b["found"].as_u64().is_some_and(|n| n >= 20)).count());
        assert!(seen >= 11, "the arm's blue and green parts are drawn in their colours: {arm}");
        for png in [
            "render-onshape_arm",
            "ws-pr2-1440-motion",
            "ws-pr2-1440-drives",
            "ws-pr2-390-motion",
            "ws-pr2-390-drives",
            "diagram-left_hand_mk3-mechatronics",
            "ws-hand-1440-motion",
            "ws-hand-390-motion",
            "ws-hand-1440-drives",
            "ws-hand-quad",
            "ws-hand-sbs",
            "ws-hand-dual",
            "ws-hand-dual-right-eye",
            "ws-hand-collision-shapes",
            "diagram-left_hand_mk3",
            "diagram-legs_mechanism",
        ] {
            assert!(shots.join(format!("{png}.png")).exists(), "screenshot {png}");
        }
    }
    println!("{}", serde_json::Value::Array(results));
    rt.block_on(app.stop());
}
