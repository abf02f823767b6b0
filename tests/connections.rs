//! Connection hygiene (issue 26, point 7): idle half-sent requests beyond the connection cap do
//! not lock HTTP out (health answers within 1 s; other requests over the cap get a quick 503
//! naming the limit), a half-sent head and a stalled body are dropped after their timeouts, and
//! an idle kept-alive connection is closed; an HTTP/2 connection that keeps sending frames but
//! begins no request is closed after the header timeout.

use std::time::{Duration, Instant};

use cad2mo_tests::app::TestApp;
use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio::net::TcpStream;

/// A connection that sent part of a request head and then nothing.
async fn half_sent(addr: &str) -> TcpStream {
    let mut s = TcpStream::connect(addr).await.expect("connect");
    s.write_all(b"GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: ").await.expect("write");
    s
}

/// How long until the peer closes `s`, at most `within`, and what it sent before.
async fn closed_after(s: &mut TcpStream, within: Duration) -> Option<(Duration, String)> {
    let t = Instant::now();
    let mut buf = [0u8; 4096];
    let mut got = Vec::new();
    loop {
        match tokio::time::timeout(within.saturating_sub(t.elapsed()), s.read(&mut buf)).await {
            Err(_) => return None,
            Ok(Ok(0)) | Ok(Err(_)) => return Some((t.elapsed(), String::from_utf8_lossy(&got).into_owned())),
            Ok(Ok(n)) => got.extend_from_slice(&buf[..n.min(4096)]),
        }
    }
}

/// A fresh client per probe: no pooled connection, so each probe is a new one over the cap.
async fn probe(url: &str) -> (u16, Duration, String) {
    let client = reqwest::Client::builder().pool_max_idle_per_host(0).build().expect("client");
    let t = Instant::now();
    let r = tokio::time::timeout(Duration::from_secs(1), client.get(url).header("X-Requested-With", "cad2mo").send())
        .await
        .expect("an answer within 1 s")
        .expect("a response");
    let status = r.status().as_u16();
    let body = r.text().await.unwrap_or_default();
    (status, t.elapsed(), body)
}

#[tokio::test]
async fn health_answers_while_idle_half_sent_connections_fill_the_cap() {
    const CAP: usize = 8;
    let app = TestApp::spawn_with(|s| {
        s.max_connections = CAP;
        s.header_timeout = Duration::from_secs(3);
    })
    .await;
    let addr = app.address.trim_start_matches("http://").to_string();
    // Five times the cap plus the reserve: the cap and the health reserve are full.
    let mut idle = Vec::new();
    for _ in 0..(5 * CAP + cad2mo_server::api::serve::RESERVE) {
        idle.push(half_sent(&addr).await);
    }
    tokio::time::sleep(Duration::from_millis(100)).await;
    for _ in 0..5 {
        let (status, took, _) = probe(&app.url("/api/health")).await;
        assert_eq!(status, 200, "health over the cap");
        assert!(took < Duration::from_secs(1), "health took {took:?}");
        // Anything but health over the cap: a quick 503 naming the limit.
        let (status, took, body) = probe(&app.url("/api/models")).await;
        assert_eq!(status, 503, "{body}");
        assert!(body.contains("limit of 8 connections") && body.contains("--max-connections"), "{body}");
        assert!(took < Duration::from_secs(1));
        // More idle connections keep coming.
        idle.push(half_sent(&addr).await);
    }
    // The first half-sent request (inside the cap) is closed after the 3 s header timeout.
    let (first, _) = closed_after(&mut idle[0], Duration::from_secs(5)).await.expect("closed by the header timeout");
    assert!(first < Duration::from_secs(4), "closed after {first:?}");
    // ... and then the cap has room again: a normal request is served.
    let (status, _, _) = probe(&app.url("/api/models")).await;
    assert_eq!(status, 200);
}

#[tokio::test]
async fn a_stalled_upload_and_an_idle_connection_are_dropped() {
    let app = TestApp::spawn_with(|s| {
        s.body_timeout = Duration::from_millis(800);
        s.keep_alive_timeout = Duration::from_millis(500);
    })
    .await;
    let addr = app.address.trim_start_matches("http://").to_string();

    // An upload that announces 100 kB and sends 10 bytes.
    let mut s = TcpStream::connect(&addr).await.expect("connect");
    let head = format!(
        "POST /api/models HTTP/1.1\r\nHost: {addr}\r\nX-Requested-With: cad2mo\r\n\
         Content-Type: multipart/form-data; boundary=XyZ\r\nContent-Length: 100000\r\n\r\n--XyZ\r\nCon"
    );
    s.write_all(head.as_bytes()).await.expect("write");
    let (t, answer) = closed_after(&mut s, Duration::from_secs(5)).await.expect("a stalled upload is dropped");
    assert!(t >= Duration::from_millis(700) && t < Duration::from_secs(3), "dropped after {t:?}: {answer}");
    assert!(answer.starts_with("HTTP/1.1 408") && answer.contains("--body-timeout"), "{answer}");

    // A kept-alive connection that goes quiet after one answer.
    let mut s = TcpStream::connect(&addr).await.expect("connect");
    s.write_all(format!("GET /api/health HTTP/1.1\r\nHost: {addr}\r\n\r\n").as_bytes()).await.expect("write");
    let mut buf = [0u8; 1024];
    let n = s.read(&mut buf).await.expect("read");
    assert!(String::from_utf8_lossy(&buf[..n]).starts_with("HTTP/1.1 200"));
    let (t, _) = closed_after(&mut s, Duration::from_secs(5)).await.expect("an idle connection is closed");
    assert!(t < Duration::from_secs(2), "closed after {t:?}");
    assert_eq!(app.health().await.status(), 200);
}

/// HTTP/2 (prior knowledge): a connection that sends its preface and then only pings, never a
/// request's headers, is closed after the header timeout (hyper times HTTP/1 heads only; the
/// pings keep bytes moving, so the keep-alive watchdog alone would never close it).
#[tokio::test]
async fn an_http2_connection_that_begins_no_request_is_closed_after_the_header_timeout() {
    let app = TestApp::spawn_with(|s| {
        s.header_timeout = Duration::from_millis(1000);
        s.keep_alive_timeout = Duration::from_secs(30);
    })
    .await;
    let addr = app.address.trim_start_matches("http://").to_string();
    let s = TcpStream::connect(&addr).await.expect("connect");
    let (mut rd, mut wr) = s.into_split();
    // Preface and an empty SETTINGS frame, then a PING every 200 ms.
    wr.write_all(b"PRI * HTTP/2.0\r\n\r\nSM\r\n\r\n\x00\x00\x00\x04\x00\x00\x00\x00\x00").await.expect("preface");
    let pinger = tokio::spawn(async move {
        for k in 0u8..100 {
            tokio::time::sleep(Duration::from_millis(200)).await;
            let mut ping = vec![0, 0, 8, 6, 0, 0, 0, 0, 0];
            ping.extend_from_slice(&[k; 8]);
            if wr.write_all(&ping).await.is_err() {
                return;
            }
        }
    });
    let t = Instant::now();
    let mut buf = [0u8; 4096];
    let mut got = 0usize;
    let closed = loop {
        match tokio::time::timeout(Duration::from_secs(6).saturating_sub(t.elapsed()), rd.read(&mut buf)).await {
            Err(_) => break None,
            Ok(Ok(0)) | Ok(Err(_)) => break Some(t.elapsed()),
            Ok(Ok(n)) => got += n,
        }
    };
    pinger.abort();
    let closed = closed.expect("closed by the header timeout while pinging");
    assert!(got > 0, "the server spoke HTTP/2 (settings, ping acks)");
    assert!(closed >= Duration::from_millis(900) && closed < Duration::from_secs(4), "closed after {closed:?}");
    assert_eq!(app.health().await.status(), 200);
}
