//! The live view end to end without a Modelica tool: the package's `LiveView` block and C sender,
//! the sender compiled with the system C compiler and driven by `tests/live/harness.c` with a
//! known motion, the service relaying it to a WebSocket client; defective, foreign, stale and
//! unsigned frames dropped and counted; tokens where the service requires them.

use std::io::Read;
use std::net::UdpSocket;
use std::time::Duration;

use cad2mo_tests::app::{json_of, TestApp};
use cad2mo_tests::live::{build_harness, run_harness, spin_motion, Stream};
use futures_util::{SinkExt, StreamExt};
use serde_json::Value;
use tokio_tungstenite::tungstenite::client::IntoClientRequest;
use tokio_tungstenite::tungstenite::Message;

#[path = "../engine/benches/support/gen.rs"]
#[allow(dead_code)]
mod gen;

fn arm_zip(n: usize) -> Vec<u8> {
    cad2mo_engine::pipeline::back::bundle::write_zip(&[("arm.xml".to_string(), gen::serial_arm_xml(n).into_bytes())]).expect("zip")
}

fn package_files(zip: &[u8]) -> Vec<(String, String)> {
    let mut z = zip::ZipArchive::new(std::io::Cursor::new(zip.to_vec())).expect("zip");
    let mut out = Vec::new();
    for i in 0..z.len() {
        let mut f = z.by_index(i).expect("entry");
        let mut s = String::new();
        if f.read_to_string(&mut s).is_ok() {
            out.push((f.name().to_string(), s));
        }
    }
    out
}

type Ws = tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;

async fn connect(app: &TestApp, path: &str, protocols: &str) -> Result<Ws, tokio_tungstenite::tungstenite::Error> {
    let url = app.url(path).replacen("http://", "ws://", 1);
    let mut req = url.into_client_request().expect("request");
    req.headers_mut().insert("sec-websocket-protocol", protocols.parse().expect("header"));
    tokio_tungstenite::connect_async(req).await.map(|(ws, _)| ws)
}

/// What the WebSocket delivered: frames (run, seq, time, poses) and text messages.
#[derive(Default)]
struct Seen {
    frames: Vec<(u32, u32, f64, Vec<f32>)>,
    texts: Vec<Value>,
}

async fn read_until_end(ws: &mut Ws, seen: &mut Seen) {
    loop {
        let m = tokio::time::timeout(Duration::from_secs(10), ws.next()).await.expect("a message within 10 s").expect("open").expect("ok");
        match m {
            Message::Binary(b) => {
                let u32_at = |k: usize| u32::from_le_bytes(b[k..k + 4].try_into().expect("4"));
                let time = f64::from_le_bytes(b[8..16].try_into().expect("8"));
                let n = u32_at(16) as usize;
                assert_eq!(b.len(), 24 + 28 * n);
                let poses = b[24..].chunks_exact(4).map(|c| f32::from_le_bytes(c.try_into().expect("4"))).collect();
                seen.frames.push((u32_at(0), u32_at(4), time, poses));
            }
            Message::Text(t) => {
                let v: Value = serde_json::from_str(&t).expect("json");
                let end = v["type"] == "end";
                seen.texts.push(v);
                if end {
                    return;
                }
            }
            _ => {}
        }
    }
}

/// Every relayed pose is the motion's at that frame's time: position and rotation about z.
fn check_poses(seen: &Seen, n: usize) {
    assert!(!seen.frames.is_empty());
    for (_, _, t, p) in &seen.frames {
        assert_eq!(p.len(), 7 * n);
        for i in 0..n {
            let b = &p[7 * i..7 * i + 7];
            let a = 0.5 * t + 0.1 * i as f64;
            let want = [i as f64, t.sin(), 0.1 * i as f64, 0.0, 0.0, (a / 2.0).sin(), (a / 2.0).cos()];
            // The quaternion's sign is free: compare q and -q.
            let sign = if (f64::from(b[6]) * want[6] + f64::from(b[5]) * want[5]) < 0.0 { -1.0 } else { 1.0 };
            for k in 0..7 {
                let w = if k >= 3 { sign * want[k] } else { want[k] };
                assert!((f64::from(b[k]) - w).abs() < 2e-6, "body {i} at t = {t}: component {k} is {} not {w}", b[k]);
            }
        }
    }
}

fn counters(v: &Value) -> (u64, u64, Value) {
    let c = &v["counters"];
    (c["received"].as_u64().expect("received"), c["relayed"].as_u64().expect("relayed"), c["dropped"].clone())
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_simulated_motion_reaches_the_browser_and_bad_frames_are_counted() {
    let app = TestApp::spawn().await;
    let (id, v, job) = app.upload_model_ok(arm_zip(3), &[]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");

    let status = json_of(app.get("/api/live").await, 200).await;
    assert_eq!(status["enabled"], true);
    assert_eq!(status["auth_required"], false);
    let udp: std::net::SocketAddr = status["udp"].as_str().expect("udp").parse().expect("address");
    let info = json_of(app.get(&format!("/api/models/{id}/versions/{v}/live")).await, 200).await;
    let bodies: Vec<String> = info["bodies"].as_array().expect("bodies").iter().map(|b| b.as_str().expect("name").to_string()).collect();
    let layout = info["layout"].as_str().expect("layout").to_string();
    assert_eq!(layout, cad2mo_engine::live::layout_hex(&bodies));
    let n = bodies.len();
    assert_eq!(n, 4, "the 3-joint arm's ground link and three links: {bodies:?}");

    // The package: Mechatronics declares the live view for this model and version, fed from
    // every body in the report's order; the block and its C source are in the package.
    let files = package_files(&app.package(&id, v).await.bytes().await.expect("zip"));
    let text =
        |suffix: &str| files.iter().find(|(n, _)| n.ends_with(suffix)).map(|(_, t)| t.clone()).unwrap_or_else(|| panic!("no {suffix}"));
    let mech = text("/Mechatronics.mo");
    assert!(mech.contains("parameter Boolean liveView = false"), "{mech}");
    assert!(mech.contains(&format!("    modelId=\"{id}\",\n    version={v},\n    layout=\"{layout}\"")), "{mech}");
    assert!(mech.contains(&format!("    livePort = {}", udp.port())) || mech.contains(&format!("livePort = {} ", udp.port())), "{mech}");
    let r0: Vec<String> = bodies.iter().map(|b| format!("{b}.frame_a.r_0")).collect();
    assert!(mech.contains(&format!("r_0={{{}}}", r0.join(", "))), "{mech}");
    assert!(text("/Components/Visualization.mo").contains("model LiveView"));
    assert!(text("/Components/package.order").lines().any(|l| l == "Visualization"));
    let sender = text("/Resources/Include/cad2mo_live.c");
    assert_eq!(sender, cad2mo_engine::pipeline::back::modelica::mechatronics::live::C_SOURCE);
    let dir = tempfile::tempdir().expect("tempdir");
    zip::ZipArchive::new(std::io::Cursor::new(app.package(&id, v).await.bytes().await.expect("zip").to_vec()))
        .expect("zip")
        .extract(dir.path())
        .expect("extract");
    if let Some(out) = cad2mo_tests::common::msl_check(dir.path()) {
        let text = out.unwrap_or_else(|e| panic!("msl-check: {e}"));
        assert!(text.contains(" 0 problems"), "msl-check: {text}");
    }
    if let Some(errors) = cad2mo_tests::common::modelica_syntax_errors(dir.path()) {
        assert!(errors.is_empty(), "{errors:?}");
    }

    let Some(harness) = build_harness(&sender, dir.path()) else { return };

    // A browser watches; the harness sends 40 frames of the known motion.
    let mut ws = connect(&app, &format!("/api/models/{id}/versions/{v}/live/ws"), "cad2mo.live").await.expect("websocket");
    let hello = ws.next().await.expect("hello").expect("ok");
    let hello: Value = serde_json::from_str(hello.to_text().expect("text")).expect("json");
    assert_eq!(hello["type"], "hello");
    assert_eq!(hello["bodies"], info["bodies"]);
    let motion = spin_motion(n, 40, 0.02);
    let (h, p, m, l) = (harness.clone(), udp.port(), id.clone(), layout.clone());
    let rows = motion.clone();
    let out = tokio::task::spawn_blocking(move || {
        run_harness(&h, &Stream { port: p, model: m, version: v, layout: l, token: None, real_time: true }, &rows)
    })
    .await
    .expect("harness");
    assert_eq!(out.trim(), "sent 40 failed 0");
    let mut seen = Seen::default();
    read_until_end(&mut ws, &mut seen).await;
    check_poses(&seen, n);
    // Paced in real time over loopback, every frame arrives, in order.
    assert_eq!(seen.frames.len(), 40, "frames relayed");
    assert!(seen.frames.windows(2).all(|w| w[1].1 == w[0].1 + 1));
    let end = seen.texts.last().expect("end");
    assert_eq!(end["type"], "end");
    assert!((end["time"].as_f64().expect("time") - 0.78).abs() < 1e-12);
    let stats = seen.texts.iter().rev().find(|t| t["type"] == "stats").expect("stats");
    assert_eq!(stats["frames"], 40);
    assert_eq!(stats["lost"], 0);
    assert_eq!(stats["ended"], true);
    let rate = stats["rate_hz"].as_f64().expect("rate");
    assert!((30.0..=60.0).contains(&rate), "paced at 50 Hz: {rate}");
    let info = json_of(app.get(&format!("/api/models/{id}/versions/{v}/live")).await, 200).await;
    assert_eq!(info["streams"][0]["frames"], 40);
    assert_eq!(info["streams"][0]["ended"], true);

    // Bad frames, each counted under its reason; the good frame between them still goes through.
    let udp_out = UdpSocket::bind("127.0.0.1:0").expect("udp");
    let model: [u8; 16] = *uuid_bytes(&id);
    let lay: [u8; 8] = hex_bytes(&layout);
    let body = |t: f64| -> Vec<[f64; 12]> {
        spin_motion(n, 1, 0.0)[0][1..].chunks(12).map(|c| std::array::from_fn(|k| c[k] + if k == 0 { t } else { 0.0 })).collect()
    };
    let frame = |seq: u32, layout: [u8; 8], version: u32, token: Option<&str>| {
        cad2mo_engine::live::encode(
            &cad2mo_engine::live::Header { model, version, layout, run: 7, seq, time: 1.0, last: false },
            &body(0.0),
            token,
        )
    };
    let good = frame(5, lay, v as u32, None);
    let mut wrong_magic = good.clone();
    wrong_magic[0] = b'X';
    let mut newer = good.clone();
    newer[4] = 9;
    let mut nan = body(0.0);
    nan[0][0] = f64::NAN;
    let sends: Vec<(Vec<u8>, &str)> = vec![
        (b"hello".to_vec(), "malformed"),
        (wrong_magic, "malformed"),
        (newer, "version"),
        (good[..good.len() - 7].to_vec(), "truncated"),
        (frame(1, [0; 8], v as u32, None), "foreign"),
        (frame(1, lay, 99, None), "foreign"),
        (
            cad2mo_engine::live::encode(
                &cad2mo_engine::live::Header {
                    model: *uuid_bytes("00000000-0000-4000-8000-000000000000"),
                    version: 1,
                    layout: lay,
                    run: 7,
                    seq: 1,
                    time: 1.0,
                    last: false,
                },
                &body(0.0),
                None,
            ),
            "foreign",
        ),
        (frame(2, lay, v as u32, Some("c2m_not_a_token")), "unauthenticated"),
        (
            cad2mo_engine::live::encode(
                &cad2mo_engine::live::Header { model, version: v as u32, layout: lay, run: 7, seq: 3, time: 1.0, last: false },
                &nan,
                None,
            ),
            "invalid",
        ),
        (good.clone(), "relayed"),
        (good.clone(), "stale"),
        (frame(4, lay, v as u32, None), "stale"),
    ];
    let before = json_of(app.get("/api/live").await, 200).await;
    let (rx0, rel0, _) = counters(&before);
    for (d, _) in &sends {
        udp_out.send_to(d, udp).expect("send");
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
    let mut after = Value::Null;
    for _ in 0..100 {
        after = json_of(app.get("/api/live").await, 200).await;
        if counters(&after).0 >= rx0 + sends.len() as u64 {
            break;
        }
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
    let (rx1, rel1, dropped) = counters(&after);
    assert_eq!(rx1 - rx0, sends.len() as u64, "{after:#}");
    assert_eq!(rel1 - rel0, 1, "{after:#}");
    for reason in ["malformed", "version", "truncated", "foreign", "unauthenticated", "invalid", "stale"] {
        let want = sends.iter().filter(|(_, r)| *r == reason).count() as u64;
        let was = before["counters"]["dropped"][reason].as_u64().unwrap_or(0);
        assert_eq!(dropped[reason].as_u64().expect(reason) - was, want, "{reason}: {after:#}");
    }
    assert_eq!(app.health().await.status(), 200, "the service is fine");

    // A foreign page may not open the WebSocket; an unknown version has none.
    let url = app.url(&format!("/api/models/{id}/versions/{v}/live/ws")).replacen("http://", "ws://", 1);
    let mut req = url.into_client_request().expect("request");
    req.headers_mut().insert("origin", "http://evil.example".parse().expect("origin"));
    match tokio_tungstenite::connect_async(req).await {
        Err(tokio_tungstenite::tungstenite::Error::Http(r)) => assert_eq!(r.status(), 403),
        other => panic!("a cross-origin WebSocket was not refused: {:?}", other.map(|_| ())),
    }
    match connect(&app, &format!("/api/models/{id}/versions/9/live/ws"), "cad2mo.live").await {
        Err(tokio_tungstenite::tungstenite::Error::Http(r)) => assert_eq!(r.status(), 404),
        other => panic!("an unknown version streamed: {:?}", other.map(|_| ())),
    }
    let _ = ws.close(None).await;
}

fn uuid_bytes(id: &str) -> &'static [u8; 16] {
    let hex: String = id.chars().filter(|c| *c != '-').collect();
    Box::leak(Box::new(hex_bytes::<16>(&hex)))
}

fn hex_bytes<const N: usize>(hex: &str) -> [u8; N] {
    std::array::from_fn(|k| u8::from_str_radix(&hex[2 * k..2 * k + 2], 16).expect("hex"))
}

/// Beyond loopback (here: `--require-auth`), frames must be signed with a live token and the
/// WebSocket needs one too; the token never travels in the frame.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn where_tokens_are_required_frames_and_viewers_need_one() {
    let app = TestApp::spawn_with(|s| s.force_auth = true).await;
    let store = cad2mo_server::store::Store::open(app.database_url()).await.expect("store");
    let token = cad2mo_server::store::tokens::create(&store, "sim", None).await.expect("token");
    let auth = reqwest::header::HeaderValue::from_str(&format!("Bearer {token}")).expect("header");
    let form = cad2mo_tests::app_models::upload_form(arm_zip(2), "arm.zip", &[]);
    let r = app.client.post(app.url("/api/models")).header("authorization", auth.clone()).multipart(form).send().await.expect("upload");
    let created = json_of(r, 202).await;
    let (id, v) = (created["model_id"].as_str().expect("id").to_string(), created["version"].as_i64().expect("v"));
    let job = created["job_id"].as_str().expect("job").to_string();
    for _ in 0..600 {
        let j = json_of(
            app.client.get(app.url(&format!("/api/jobs/{job}"))).header("authorization", auth.clone()).send().await.expect("job"),
            200,
        )
        .await;
        if j["status"] == "succeeded" {
            break;
        }
        assert_ne!(j["status"], "failed", "{j:#}");
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
    let get = |path: String| app.client.get(app.url(&path)).header("authorization", auth.clone()).send();
    let status = json_of(get("/api/live".into()).await.expect("live"), 200).await;
    assert_eq!(status["auth_required"], true);
    let udp: std::net::SocketAddr = status["udp"].as_str().expect("udp").parse().expect("address");
    let info = json_of(get(format!("/api/models/{id}/versions/{v}/live")).await.expect("info"), 200).await;
    let layout = info["layout"].as_str().expect("layout").to_string();
    let n = info["bodies"].as_array().expect("bodies").len();
    let zip = get(format!("/api/models/{id}/versions/{v}/package.zip")).await.expect("package").bytes().await.expect("zip");
    let files = package_files(&zip);
    let sender = files.iter().find(|(n, _)| n.ends_with("/cad2mo_live.c")).expect("sender").1.clone();
    let dir = tempfile::tempdir().expect("tempdir");
    let Some(harness) = build_harness(&sender, dir.path()) else { return };

    // Without a token the WebSocket is refused; with one as a sub-protocol it opens.
    match connect(&app, &format!("/api/models/{id}/versions/{v}/live/ws"), "cad2mo.live").await {
        Err(tokio_tungstenite::tungstenite::Error::Http(r)) => assert_eq!(r.status(), 401),
        other => panic!("a WebSocket without a token opened: {:?}", other.map(|_| ())),
    }
    let mut ws =
        connect(&app, &format!("/api/models/{id}/versions/{v}/live/ws"), &format!("cad2mo.live, bearer.{token}")).await.expect("websocket");
    let hello = ws.next().await.expect("hello").expect("ok");
    assert!(hello.to_text().expect("text").contains("\"hello\""));

    let motion = spin_motion(n, 10, 0.02);
    let before = counters(&json_of(get("/api/live".into()).await.expect("live"), 200).await);
    // Unsigned, then signed with an unknown token: dropped. Then signed with the live token.
    for t in [None, Some("c2m_0000")] {
        let (h, m, l, rows) = (harness.clone(), id.clone(), layout.clone(), motion.clone());
        let t = t.map(str::to_string);
        let out = tokio::task::spawn_blocking(move || {
            run_harness(&h, &Stream { port: udp.port(), model: m, version: v, layout: l, token: t, real_time: false }, &rows)
        })
        .await
        .expect("harness");
        assert_eq!(out.trim(), "sent 10 failed 0");
    }
    let (h, m, l, rows, tk) = (harness.clone(), id.clone(), layout.clone(), motion.clone(), token.clone());
    tokio::task::spawn_blocking(move || {
        run_harness(&h, &Stream { port: udp.port(), model: m, version: v, layout: l, token: Some(tk), real_time: true }, &rows)
    })
    .await
    .expect("harness");
    let mut seen = Seen::default();
    read_until_end(&mut ws, &mut seen).await;
    check_poses(&seen, n);
    assert_eq!(seen.frames.len(), 10);
    let after = counters(&json_of(get("/api/live".into()).await.expect("live"), 200).await);
    assert_eq!(after.1 - before.1, 10, "only the signed run is relayed");
    assert_eq!(after.2["unauthenticated"].as_u64().expect("n") - before.2["unauthenticated"].as_u64().expect("n"), 20);
    // A live simulation signs its frames with the caller's token (its SHA-256 keys them).
    let body = serde_json::json!({"duration": 0.1, "drives": false, "live": true, "live_real_time": false});
    let r = app.client.post(app.url(&format!("/api/models/{id}/simulations"))).header("authorization", auth.clone()).json(&body).send();
    let sim = json_of(r.await.expect("simulate"), 201).await;
    let mut seen = Seen::default();
    read_until_end(&mut ws, &mut seen).await;
    assert_eq!(seen.frames.len() as u64, sim["live"]["frames"].as_u64().expect("frames"), "{sim:#}");
    assert!(seen.frames.iter().all(|f| u64::from(f.0) == sim["live"]["run"].as_u64().expect("run")));
    let last = counters(&json_of(get("/api/live".into()).await.expect("live"), 200).await);
    assert_eq!(last.2["unauthenticated"], after.2["unauthenticated"], "no simulation frame is unsigned");
    let _ = ws.send(Message::Close(None)).await;
}

/// The bodies' frames of a stored result at each of its instants, read through the results API:
/// per instant, 12 numbers per body (`frame_a.r_0`, then `R.T` row by row), bodies in `bodies`' order.
async fn stored_frames(app: &TestApp, rid: &str, bodies: &[String]) -> (Vec<f64>, Vec<Vec<[f64; 12]>>) {
    let mut names = Vec::new();
    for b in bodies {
        names.extend((1..=3).map(|i| format!("{b}.frame_a.r_0[{i}]")));
        names.extend((1..=3).flat_map(|i| (1..=3).map(move |j| format!("{b}.frame_a.R.T[{i},{j}]"))));
    }
    let mut columns: Vec<Vec<f64>> = Vec::new();
    let mut t = Vec::new();
    for chunk in names.chunks(48) {
        let q: Vec<String> =
            chunk.iter().map(|n| format!("name={}", n.replace('[', "%5B").replace(']', "%5D").replace(',', "%2C"))).collect();
        let got = json_of(app.get(&format!("/api/results/{rid}/series?{}&width=10000", q.join("&"))).await, 200).await;
        for v in got["variables"].as_array().expect("variables") {
            t = v["t"].as_array().expect("t").iter().map(|x| x.as_f64().expect("t")).collect();
            columns.push(v["y"].as_array().expect("y").iter().map(|x| x.as_f64().expect("y")).collect());
        }
    }
    assert_eq!(columns.len(), 12 * bodies.len());
    let frames = (0..t.len()).map(|k| (0..bodies.len()).map(|b| std::array::from_fn(|x| columns[12 * b + x][k])).collect()).collect();
    (t, frames)
}

/// A closed-loop simulation with `live` on sends its bodies' poses to the relay while it runs
/// (paced to the wall clock, a frame every 0.02 s of simulated time, the last one final): the
/// Live tab's WebSocket gets every frame, each at an instant of the stored result and equal to
/// the result's poses there as the protocol carries them (f32, re-orthonormalised) within 1e-9.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_live_simulation_is_relayed_with_the_poses_of_its_stored_result() {
    let app = TestApp::spawn().await;
    let (id, v, job) = app.upload_model_ok(arm_zip(2), &[("gravity", "0,0,-9.81")]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");
    let url = app.url(&format!("/api/models/{id}/simulations"));
    let p = json_of(
        app.client.post(&url).json(&serde_json::json!({"duration": 0.5, "live": true, "live_period": 0.001})).send().await.expect("post"),
        422,
    )
    .await;
    assert_eq!(p["errors"][0]["field"], "live_period", "{p:#}");

    let mut ws = connect(&app, &format!("/api/models/{id}/versions/{v}/live/ws"), "cad2mo.live").await.expect("websocket");
    let started = std::time::Instant::now();
    let joints = json_of(app.get(&format!("/api/models/{id}/joints")).await, 200).await;
    let first = joints["joints"][0]["name"].as_str().expect("joint").to_string();
    let body = serde_json::json!({"duration": 0.5, "drives": false, "start": {first: 0.4}, "live": true});
    let post = tokio::spawn({
        let client = app.client.clone();
        async move { client.post(&url).json(&body).send().await.expect("post") }
    });
    let mut seen = Seen::default();
    read_until_end(&mut ws, &mut seen).await;
    let sim = json_of(post.await.expect("task"), 201).await;
    let wall = started.elapsed().as_secs_f64();
    let _ = ws.send(Message::Close(None)).await;
    println!("live simulation: {} frames in {wall:.3} s, {:#}", seen.frames.len(), sim["live"]);
    assert!(wall >= 0.5, "paced to the wall clock: {wall} s");
    let live = &sim["live"];
    assert_eq!(
        (live["frames"].as_u64(), live["send_errors"].as_u64(), live["real_time"].as_bool()),
        (Some(26), Some(0), Some(true)),
        "{sim:#}"
    );
    assert!((live["period"].as_f64().expect("period") - 0.02).abs() < 1e-12, "{live:#}");
    assert_eq!(seen.frames.len(), 26, "every frame relayed: {:?}", seen.texts);
    let hello = seen.texts.iter().find(|x| x["type"] == "hello").expect("hello");
    let bodies: Vec<String> = hello["bodies"].as_array().expect("bodies").iter().map(|b| b.as_str().expect("name").to_string()).collect();
    let (t, stored) = stored_frames(&app, sim["result_id"].as_str().expect("result"), &bodies).await;
    let model: [u8; 16] = hex_bytes(&id.replace('-', ""));
    for (k, (run, seq, time, poses)) in seen.frames.iter().enumerate() {
        assert_eq!((u64::from(*run), *seq as usize), (live["run"].as_u64().expect("run"), k));
        let i = t.iter().position(|x| x == time).unwrap_or_else(|| panic!("frame {k} at {time} s is no instant of the result"));
        assert!((time - 0.02 * k as f64).abs() < 1e-12, "frame {k} at {time} s");
        // The stored poses as a frame carries them: the relay's own path from r_0 and R.T.
        let h =
            cad2mo_engine::live::Header { model, version: v as u32, layout: cad2mo_engine::live::layout_id(&bodies), ..Default::default() };
        let bytes = cad2mo_engine::live::encode(&h, &stored[i], None);
        let mut want = Vec::new();
        cad2mo_engine::live::poses_into(&cad2mo_engine::live::decode(&bytes).expect("frame"), &mut want).expect("poses");
        assert_eq!(poses.len(), want.len());
        for (c, (a, b)) in poses.iter().zip(&want).enumerate() {
            assert!((f64::from(*a) - f64::from(*b)).abs() <= 1e-9, "frame {k} (t = {time}), number {c}: {a} relayed, {b} stored");
        }
    }
    // The arm fell: the last frame is not the first.
    assert_ne!(seen.frames[0].3, seen.frames[25].3);
    assert!(seen.texts.iter().any(|x| x["type"] == "end"));
}

/// With the live view off, a live simulation is a 422 naming `live` and saying why; without
/// `live` the same run works.
#[tokio::test]
async fn a_live_simulation_needs_the_live_view_on() {
    let app = TestApp::spawn_with(|s| s.live_bind = None).await;
    let (id, _, job) = app.upload_model_ok(arm_zip(1), &[]).await;
    assert_eq!(app.wait_for_job(&job).await["status"], "succeeded");
    let url = app.url(&format!("/api/models/{id}/simulations"));
    let p =
        json_of(app.client.post(&url).json(&serde_json::json!({"duration": 0.05, "live": true})).send().await.expect("post"), 422).await;
    assert_eq!(p["errors"][0]["field"], "live", "{p:#}");
    assert!(p["errors"][0]["message"].as_str().expect("message").contains("live view is off"), "{p:#}");
    let sim = json_of(app.client.post(&url).json(&serde_json::json!({"duration": 0.05})).send().await.expect("post"), 201).await;
    assert!(sim.get("live").is_none(), "{sim:#}");
}
