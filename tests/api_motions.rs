//! Joint limits, motions, trajectories and live IK through the REST API on a generated 6-axis arm
//! (and a second CAD version with one joint fewer: limits orphaned, the motion refused by name).

use cad2mo_tests::app::{json_of, TestApp};
use serde_json::{json, Value};

#[path = "../engine/benches/support/gen.rs"]
#[allow(dead_code)]
mod gen;

fn arm_zip(n: usize) -> Vec<u8> {
    cad2mo_engine::pipeline::back::bundle::write_zip(&[("arm.xml".to_string(), gen::serial_arm_xml(n).into_bytes())]).expect("zip")
}

async fn seeded_instance(app: &TestApp, class_path: &str) -> String {
    let classes = json_of(app.get("/api/library/classes").await, 200).await;
    let class = classes.as_array().expect("classes").iter().find(|c| c["modelica_class"] == class_path).expect("class");
    let list = json_of(app.get(&format!("/api/library/instances?class_id={}", class["id"].as_str().expect("id"))).await, 200).await;
    list[0]["id"].as_str().expect("a seeded instance").to_string()
}

async fn instance_named(app: &TestApp, name: &str) -> String {
    let list = json_of(app.get("/api/library/instances").await, 200).await;
    let i = list.as_array().expect("instances").iter().find(|i| i["name"] == name).unwrap_or_else(|| panic!("no instance {name}"));
    i["id"].as_str().expect("id").to_string()
}

#[tokio::test]
async fn limits_motions_trajectories_and_ik() {
    let app = TestApp::spawn().await;
    let (id, _, job) = app.upload_model_ok(arm_zip(6), &[("gravity", "0,0,-9.81")]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");
    let base = format!("/api/models/{id}");

    // Joints with default limits, and the tool frame at the CAD pose.
    let j = json_of(app.get(&format!("{base}/joints")).await, 200).await;
    let joints = j["joints"].as_array().expect("joints");
    assert_eq!(joints.len(), 6, "{j:#}");
    let names: Vec<String> = joints.iter().map(|x| x["name"].as_str().expect("name").to_string()).collect();
    assert_eq!(joints[0]["limits"], joints[0]["defaults"]);
    assert_eq!(joints[0]["limits"]["speed"], 3.0);
    assert_eq!(joints[0]["custom"], false);
    let tool = j["frames"].as_array().expect("frames").iter().find(|f| f["node_id"] == "TOOL").expect("tool frame").clone();
    let p0: Vec<f64> = tool["position"].as_array().expect("p").iter().map(|v| v.as_f64().expect("f")).collect();

    // Limits: edited, refused when impossible, unknown joints 404.
    let url = |j: &str| app.url(&format!("{base}/joints/{j}/limits"));
    let r = app.client.put(url(&names[1])).json(&json!({"position": [-2.0, 2.0], "speed": 1.5})).send().await.expect("put");
    let v = json_of(r, 200).await;
    assert_eq!(
        (v["custom"].clone(), v["limits"]["speed"].clone(), v["limits"]["acceleration"].clone()),
        (json!(true), json!(1.5), json!(15.0))
    );
    let r = app.client.put(url(&names[1])).json(&json!({"position": [1.0, -1.0], "jerk": 0})).send().await.expect("put");
    let p = json_of(r, 422).await;
    let fields: Vec<&str> = p["errors"].as_array().expect("errors").iter().map(|e| e["field"].as_str().expect("f")).collect();
    assert_eq!(fields, ["position", "jerk"], "{p:#}");
    json_of(app.client.put(url("NOPE")).json(&json!({"speed": 1})).send().await.expect("put"), 404).await;

    // A motion: start, a PTP joint keyframe, a tool keyframe 5 cm away solved by IK.
    let motion = json!({"name": "pick", "keyframes": [
        {"kind": "joints", "values": {}},
        {"kind": "joints", "values": {names[0].clone(): 0.5}, "interpolation": "ptp", "dwell": 0.1},
        {"kind": "tool", "frame": "TOOL", "position": [p0[0], p0[1] + 0.05, p0[2] - 0.05], "rotation": null, "interpolation": "jerk"}
    ]});
    let created = json_of(app.client.post(app.url(&format!("{base}/motions"))).json(&motion).send().await.expect("post"), 201).await;
    let mid = created["id"].as_str().expect("id").to_string();
    assert_eq!(created["spec"]["keyframes"][1]["interpolation"], "ptp");
    json_of(app.client.post(app.url(&format!("{base}/motions"))).json(&motion).send().await.expect("post"), 409).await;
    let t = json_of(app.get(&format!("{base}/motions/{mid}/trajectory?rate=200")).await, 200).await;
    let n = t["t"].as_array().expect("t").len();
    let duration = t["duration"].as_f64().expect("duration");
    assert_eq!(n, (duration * 200.0 - 1e-9).ceil() as usize + 1);
    assert_eq!(t["joints"].as_array().expect("joints").len(), 6);
    for key in ["q", "qd", "qdd", "tau"] {
        assert!(t[key].as_array().expect(key).iter().all(|a| a.as_array().expect("axis").len() == n), "{key}");
    }
    let ik = &t["keyframes"][2]["ik"];
    assert!(ik["position_error"].as_f64().expect("err") < 1e-6, "{ik}");
    // The first joint's motion respects the edited speed limit of the second joint? Its own: 3.
    let qd0_max = t["qd"][0].as_array().expect("qd").iter().map(|v| v.as_f64().expect("f").abs()).fold(0.0, f64::max);
    assert!(qd0_max <= 3.0 + 1e-9, "{qd0_max}");
    let qd1_max = t["qd"][1].as_array().expect("qd").iter().map(|v| v.as_f64().expect("f").abs()).fold(0.0, f64::max);
    assert!(qd1_max <= 1.5 + 1e-6, "{qd1_max}");
    // Gravity (-z, the upload's) loads the shoulder joint (axis y) while the arm rests at the start.
    assert!(t["tau"][1][0].as_f64().expect("tau").abs() > 1e-3, "{}", t["tau"][1][0]);
    json_of(app.get(&format!("{base}/motions/{mid}/trajectory?rate=0")).await, 400).await;

    // Live IK.
    let r = app
        .client
        .post(app.url(&format!("{base}/ik")))
        .json(&json!({"frame": "TOOL", "position": [p0[0], p0[1], p0[2] - 0.02]}))
        .send()
        .await
        .expect("ik");
    let v = json_of(r, 200).await;
    assert_eq!(v["success"], true, "{v:#}");
    let r =
        app.client.post(app.url(&format!("{base}/ik"))).json(&json!({"frame": "NOPE", "position": [0, 0, 0]})).send().await.expect("ik");
    assert_eq!(json_of(r, 422).await["errors"][0]["field"], "frame");
    // A target beyond any reach: a 422 naming the bound, never `position_error: null`.
    let r = app
        .client
        .post(app.url(&format!("{base}/ik")))
        .json(&json!({"frame": "TOOL", "position": [1e308, 0, 0]}))
        .send()
        .await
        .expect("ik");
    let p = json_of(r, 422).await;
    assert_eq!(p["errors"][0]["field"], "position", "{p:#}");
    assert!(p["errors"][0]["message"].as_str().expect("message").contains("within ±1000000 m"), "{p:#}");
    let r =
        app.client.post(app.url(&format!("{base}/ik"))).json(&json!({"frame": "TOOL", "position": [1e6, 0, 0]})).send().await.expect("ik");
    let v = json_of(r, 200).await;
    assert!(v["success"] == false && v["position_error"].as_f64().is_some_and(|e| e > 9e5), "{v:#}");
    // 100,000 keyframes (3 MB of JSON): too large, 413 naming the limit, not a 400.
    let many: Vec<Value> = (0..100_000).map(|_| json!({"kind": "joints", "values": {}})).collect();
    let r =
        app.client.post(app.url(&format!("{base}/motions"))).json(&json!({"name": "many", "keyframes": many})).send().await.expect("post");
    let p = json_of(r, 413).await;
    assert!(p["detail"].as_str().expect("detail").contains("limit of 2097152 bytes"), "{p:#}");

    // Problems: unreachable target, form errors.
    let far = json!({"name": "far", "keyframes": [{"kind": "joints", "values": {}}, {"kind": "tool", "frame": "TOOL", "position": [40.0, 0, 0]}]});
    let f = json_of(app.client.post(app.url(&format!("{base}/motions"))).json(&far).send().await.expect("post"), 201).await;
    let p = json_of(app.get(&format!("{base}/motions/{}/trajectory", f["id"].as_str().expect("id"))).await, 422).await;
    assert_eq!(p["type"], "/problems/motion-invalid");
    assert_eq!(p["errors"][0]["field"], "keyframes[1]");
    assert!(p["detail"].as_str().expect("detail").contains("inverse kinematics failed for frame \"TOOL\""), "{p:#}");
    let bad = json!({"name": "", "keyframes": [{"kind": "joints", "values": {"J1": 1}, "duration": -1}]});
    let p = json_of(app.client.post(app.url(&format!("{base}/motions"))).json(&bad).send().await.expect("post"), 422).await;
    assert_eq!(p["errors"].as_array().expect("errors").len(), 3, "{p:#}");

    // A drive on the first joint and a re-export: Mechatronics.mo follows the motions (the one
    // this version cannot plan is skipped and reported), the report lists them.
    // The maxon RE 40 (with the stall torque its catalogue prints, 2280 mNm at 24 V, added as a
    // user's instance) and the 100:1 strain-wave gear carry the datasheet values every check needs.
    let classes = json_of(app.get("/api/library/classes").await, 200).await;
    let class_of = |path: &str| {
        classes.as_array().expect("classes").iter().find(|c| c["modelica_class"] == path).expect("class")["id"]
            .as_str()
            .expect("id")
            .to_string()
    };
    let re40 =
        json_of(app.get(&format!("/api/library/instances/{}", instance_named(&app, "maxon RE 40 148877 (24 V)").await)).await, 200).await;
    let mut values = re40["values"].as_object().expect("values").clone();
    values.insert("T_stall".into(), json!({"value": 2280, "unit": "mNm"}));
    let with_stall = json!({"class_id": re40["class_id"], "name": "RE 40 with stall torque", "source": "test: the seed's RE 40 with the catalogue's stall torque 2280 mNm", "values": values});
    let motor = json_of(app.client.post(app.url("/api/library/instances")).json(&with_stall).send().await.expect("post"), 201).await["id"]
        .as_str()
        .expect("id")
        .to_string();
    let amp = json!({"class_id": class_of("cad2mo.Sizing.ServoAmplifier"), "name": "test amplifier 10-50 V, 5 A / 15 A", "source": "test values",
        "values": {"U_min": 10, "U_max": 50, "I_cont": 5, "I_peak": 15}});
    let amp = json_of(app.client.post(app.url("/api/library/instances")).json(&amp).send().await.expect("post"), 201).await["id"]
        .as_str()
        .expect("id")
        .to_string();
    // A gear with every value the checks read (the seed's "Ideal gear 100:1" lacks its torque
    // ratings since migration 0017).
    let gear = json!({"class_id": class_of("Modelica.Mechanics.Rotational.Components.IdealGear"), "name": "test gear 100:1", "source": "test values",
        "values": {"ratio": 100, "T_rated": 31, "T_peak": 70, "w_in_max": 764.5, "J_in": 7.9e-6}});
    let gear = json_of(app.client.post(app.url("/api/library/instances")).json(&gear).send().await.expect("post"), 201).await["id"]
        .as_str()
        .expect("id")
        .to_string();
    let controller = seeded_instance(&app, "cad2mo.Drives.Controllers.CascadePPI").await;
    let drive = json!({"motor_instance": motor, "gear_instance": gear, "controller_instance": controller});
    json_of(app.client.put(app.url(&format!("{base}/drives/{}", names[0]))).json(&drive).send().await.expect("put"), 200).await;
    // Sizing at 1 kHz without settings: the checks that need an amplifier are not evaluated and
    // the amplifier is named missing.
    let plain = json_of(app.get(&format!("{base}/motions/{mid}/sizing")).await, 200).await;
    assert!(plain["drives"][0]["missing"].as_array().expect("missing").contains(&json!("amplifier")), "{:#}", plain["drives"][0]);
    assert_eq!(plain["settings"]["reserve"], 0.2);
    // With an amplifier at 24 V, a 1 s dwell, a 20 % reserve and a brake resistor: every check
    // evaluated against its motor, gear and amplifier; ranked real alternatives; what the other
    // joints ask of a drive.
    let query = format!("amplifier={amp}&supply_voltage=24&reserve=0.2&dwell=1&brake_power=50");
    let sz = json_of(app.get(&format!("{base}/motions/{mid}/sizing?{query}")).await, 200).await;
    assert_eq!(sz["rate"], 1000.0);
    assert_eq!((sz["settings"]["dwell"].as_f64(), sz["settings"]["amplifier"]["supply_voltage"].as_f64()), (Some(1.0), Some(24.0)));
    assert_eq!(sz["settings"]["brake"], json!({"kind": "resistor", "power": 50.0}));
    let d = &sz["drives"][0];
    assert_eq!(d["joint"], names[0].as_str(), "{sz:#}");
    let checks: Vec<&str> = d["checks"].as_array().expect("checks").iter().map(|c| c["check"].as_str().expect("check")).collect();
    assert_eq!(d["missing"], json!([]), "{d:#}");
    for c in ["peak_torque", "rms_torque", "voltage", "peak_current", "rms_current", "inertia_ratio", "braking"] {
        assert!(checks.contains(&c), "{c} in {checks:?}");
    }
    let by = |name: &str| d["checks"].as_array().expect("checks").iter().find(|c| c["check"] == name).expect("check").clone();
    assert_eq!(by("voltage")["limit"], 24.0);
    assert_eq!(by("peak_current")["limit"], 15.0);
    assert!((by("peak_torque")["limit"].as_f64().expect("limit") - 2.28).abs() < 1e-12);
    assert!(by("peak_torque")["source"].as_str().expect("source").contains("T_stall"));
    for c in d["checks"].as_array().expect("checks") {
        if let (Some(v), Some(l)) = (c["value"].as_f64(), c["limit"].as_f64()) {
            assert!((c["margin"].as_f64().expect("margin") - (l - v) / l).abs() < 1e-12, "{c}");
            assert!(c["source"].is_string() && c["rule"].is_string(), "{c}");
        }
    }
    for a in d["alternatives"].as_array().expect("alternatives") {
        assert!(a["why"].is_string() && a["standing"].is_string(), "{a}");
    }
    // Bad settings: 422 naming each field.
    for (q, field) in [
        ("reserve=1.5", "reserve"),
        ("dwell=-1", "dwell"),
        (&*format!("amplifier={gear}"), "amplifier"),
        ("amplifier=nope", "amplifier"),
        (&*format!("amplifier={amp}&supply_voltage=60"), "supply_voltage"),
        ("supply_voltage=24", "supply_voltage"),
        ("brake_power=10&bus_capacitance=0.001&bus_voltage_max=60", "brake_power"),
        ("bus_capacitance=0.001", "bus_voltage_max"),
        ("screw_life=0", "screw_life"),
    ] {
        let p = json_of(app.get(&format!("{base}/motions/{mid}/sizing?{q}")).await, 422).await;
        assert_eq!(p["errors"][0]["field"], field, "{q}: {p:#}");
    }
    // The gear's output torque is the joint torque of the trajectory at the same rate.
    let t1k = json_of(app.get(&format!("{base}/motions/{mid}/trajectory?rate=1000")).await, 200).await;
    let peak = t1k["tau"][0].as_array().expect("tau").iter().map(|v| v.as_f64().expect("f").abs()).fold(0.0, f64::max);
    let gear_peak = by("gear_peak_torque");
    assert!((gear_peak["value"].as_f64().expect("value") - peak).abs() < 1e-9 * peak, "{gear_peak} vs {peak}");
    let points = d["operating_points"]["speed"].as_array().expect("points").len();
    assert!(points > 10 && points <= 2000, "{points}");
    assert_eq!(sz["undriven"].as_array().expect("undriven").len(), 5);
    assert!(sz["ranking"].as_str().expect("ranking").contains("real catalogue combinations only"));
    let r = app.client.post(app.url(&format!("{base}/reexport"))).send().await.expect("reexport");
    let queued = json_of(r, 202).await;
    assert_eq!(app.wait_for_job(queued["job_id"].as_str().expect("job")).await["status"], "succeeded");
    let zip = app.package(&id, 1).await.bytes().await.expect("zip");
    let mut z = zip::ZipArchive::new(std::io::Cursor::new(zip.to_vec())).expect("zip");
    let read = |z: &mut zip::ZipArchive<std::io::Cursor<Vec<u8>>>, suffix: &str| -> String {
        let name = z.file_names().find(|n| n.ends_with(suffix)).unwrap_or_else(|| panic!("no {suffix}")).to_string();
        let mut s = String::new();
        std::io::Read::read_to_string(&mut z.by_name(&name).expect("entry"), &mut s).expect("utf-8");
        s
    };
    // The package with its Motions passes the Modelica checks.
    let dir = tempfile::tempdir().expect("tempdir");
    z.extract(dir.path()).expect("extract");
    if let Some(out) = cad2mo_tests::common::msl_check(dir.path()) {
        let text = out.unwrap_or_else(|e| panic!("msl-check: {e}"));
        assert!(text.contains(" 0 problems"), "msl-check: {text}");
    }
    if let Some(errors) = cad2mo_tests::common::modelica_syntax_errors(dir.path()) {
        assert!(errors.is_empty(), "{errors:?}");
    }
    let mech = read(&mut z, "/Mechatronics.mo");
    assert!(mech.contains("Motions.pick motion_pick \"Motion pick\""), "{mech}");
    assert!(mech.contains(&format!("drive_{0}.q_motion = motion_pick.y[1];", names[0])), "{mech}");
    assert!(mech.contains(&format!("drive_{0}.qd_motion = motion_pick.y[7];", names[0])), "{mech}");
    let table = read(&mut z, "/Motions/pick.mo");
    let rows = table.matches(";\n      ").count() + 1;
    assert_eq!(rows, (duration * 100.0 - 1e-9).ceil() as usize + 1, "100 Hz table rows");
    assert!(read(&mut z, "/package.order").lines().any(|l| l == "Motions"));
    let sizing: Value = serde_json::from_str(&read(&mut z, "/Resources/Sizing/pick.json")).expect("sizing json");
    assert_eq!(sizing["drives"][0]["joint"], names[0].as_str());
    assert_eq!(sizing["drives"][0]["checks"], plain["drives"][0]["checks"], "the package's sizing is the API's with the default settings");
    let report: Value = app.report(&id, 1).await.json().await.expect("report");
    assert_eq!(report["motions"]["written"], json!(["pick"]));
    assert_eq!(report["motions"]["skipped"][0]["motion"], "far");
    assert!(report["motions"]["skipped"][0]["problem"].as_str().expect("problem").contains("inverse kinematics failed"));

    // A new CAD version with five joints: the sixth's limits are orphaned; a motion naming it is
    // refused, naming the keyframe and the joint.
    json_of(app.client.put(url(&names[5])).json(&json!({"speed": 2})).send().await.expect("put"), 200).await;
    let six =
        json!({"name": "wrist", "keyframes": [{"kind": "joints", "values": {}}, {"kind": "joints", "values": {names[5].clone(): 0.2}}]});
    let w = json_of(app.client.post(app.url(&format!("{base}/motions"))).json(&six).send().await.expect("post"), 201).await;
    let (_, _, job2) = app.upload_version_ok(&id, arm_zip(5), &[]).await;
    assert_eq!(app.wait_for_job(&job2).await["status"], "succeeded");
    let j = json_of(app.get(&format!("{base}/joints")).await, 200).await;
    assert_eq!(j["version"], 2);
    assert_eq!(j["joints"].as_array().expect("joints").len(), 5);
    assert!(j["orphans"].as_array().expect("orphans").iter().any(|o| o["joint"] == names[5].as_str()), "{j:#}");
    let p = json_of(app.get(&format!("{base}/motions/{}/trajectory", w["id"].as_str().expect("id"))).await, 422).await;
    assert_eq!(p["errors"][0]["field"], format!("keyframes[1].values.{}", names[5]));

    // Delete.
    assert_eq!(app.client.delete(app.url(&format!("{base}/motions/{mid}"))).send().await.expect("del").status(), 204);
    json_of(app.get(&format!("{base}/motions/{mid}")).await, 404).await;
    assert_eq!(app.client.delete(url(&names[5])).send().await.expect("del").status(), 204);
    let list = json_of(app.get(&format!("{base}/motions")).await, 200).await;
    assert_eq!(list.as_array().expect("list").len(), 2);
}

/// Panda's fingers through the API: `panda_finger_joint2` mimics `panda_finger_joint1`, so
/// `/joints` lists it as dependent with its coupling, a motion of the leader moves both, the
/// follower's torque is the leader's to carry, and a keyframe that contradicts the coupling
/// (finger1 = 0.04, finger2 = 0: the example) is a 422 naming it.
#[tokio::test]
async fn panda_fingers_follow_their_mimic_coupling() {
    let Some(fx) = cad2mo_tests::common::fixtures_dir("panda_fingers_follow_their_mimic_coupling") else { return };
    let urdf = std::fs::read(fx.join("urdf/Gepetto+example-robot-data/39aa9437/robots/panda_description/urdf/panda.urdf")).expect("panda");
    let zip = cad2mo_engine::pipeline::back::bundle::write_zip(&[("panda.urdf".to_string(), urdf)]).expect("zip");
    let app = TestApp::spawn().await;
    let (id, _, job) = app.upload_model_ok(zip, &[]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");
    let base = format!("/api/models/{id}");
    let j = json_of(app.get(&format!("{base}/joints")).await, 200).await;
    let joints = j["joints"].as_array().expect("joints");
    let find =
        |n: &str| joints.iter().find(|x| x["name"].as_str().is_some_and(|s| s.ends_with(n))).unwrap_or_else(|| panic!("no {n}: {j:#}"));
    let (f1, f2) = (find("finger_joint1"), find("finger_joint2"));
    let (n1, n2) = (f1["name"].as_str().expect("name").to_string(), f2["name"].as_str().expect("name").to_string());
    assert_eq!(f1["independent"], true);
    assert!(f1.get("mimic").is_none());
    assert_eq!(f2["independent"], false, "{f2:#}");
    assert_eq!(f2["mimic"], json!({"leader": n1, "multiplier": 1.0, "offset": 0.0}));
    assert_eq!(f2["damping"], 0.3, "the URDF's <dynamics damping=\"0.3\">");
    // Panda's zero pose is outside joints 4 and 6's ranges: the first keyframe starts inside.
    let (n4, n6) = (
        find("panda_joint4")["name"].as_str().expect("name").to_string(),
        find("panda_joint6")["name"].as_str().expect("name").to_string(),
    );
    let start = json!({"kind": "joints", "values": {n4.clone(): -1.5, n6.clone(): 1.5}});
    // The leader alone: both fingers open together; the follower's torque is on the leader.
    let open = json!({"name": "open", "keyframes": [start.clone(), {"kind": "joints", "values": {n1.clone(): 0.04}, "interpolation": "quintic", "duration": 1.0}]});
    let m = json_of(app.client.post(app.url(&format!("{base}/motions"))).json(&open).send().await.expect("post"), 201).await;
    let t = json_of(app.get(&format!("{base}/motions/{}/trajectory?rate=100", m["id"].as_str().expect("id"))).await, 200).await;
    let names: Vec<&str> =
        t["joints"].as_array().expect("joints").iter().map(|x| x.as_str().or(x["name"].as_str()).expect("joint name")).collect();
    let (i1, i2) = (names.iter().position(|n| *n == n1).expect("i1"), names.iter().position(|n| *n == n2).expect("i2"));
    let col = |k: &str, i: usize| -> Vec<f64> { t[k][i].as_array().expect("axis").iter().map(|v| v.as_f64().expect("f")).collect() };
    assert_eq!(col("q", i1), col("q", i2));
    assert!((col("q", i2).last().copied().expect("last") - 0.04).abs() < 1e-12);
    assert!(col("tau", i2).iter().all(|x| *x == 0.0), "the follower carries no torque of its own");
    assert!(col("tau", i1).iter().any(|x| x.abs() > 0.0));
    // The contradiction is refused, naming the coupling.
    let bad = json!({"name": "bad", "keyframes": [start, {"kind": "joints", "values": {n1.clone(): 0.04, n2.clone(): 0.0}}]});
    let b = json_of(app.client.post(app.url(&format!("{base}/motions"))).json(&bad).send().await.expect("post"), 201).await;
    let p = json_of(app.get(&format!("{base}/motions/{}/trajectory", b["id"].as_str().expect("id"))).await, 422).await;
    assert_eq!(p["errors"][0]["field"], format!("keyframes[1].values.{n2}"), "{p:#}");
    assert!(p["detail"].as_str().expect("detail").contains("mimic coupling"), "{p:#}");
}
