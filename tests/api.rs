//! API tests: the real service on port 0 with a fresh SQLite database per test, driven through
//! `TestApp` (tests/support/app.rs).

use cad2mo_tests::app::TestApp;

#[tokio::test]
async fn health_answers_with_the_version() {
    let app = TestApp::spawn().await;
    let r = app.health().await;
    assert_eq!(r.status(), 200);
    let body: serde_json::Value = r.json().await.expect("json");
    assert_eq!(body["status"], "ok");
    assert_eq!(body["version"], cad2mo_engine::pipeline::VERSION);
}

#[tokio::test]
async fn unknown_route_is_404() {
    let app = TestApp::spawn().await;
    assert_eq!(app.get("/api/nope").await.status(), 404);
}

#[tokio::test]
async fn restart_keeps_the_database() {
    let app = TestApp::spawn().await;
    let dir = app.stop().await;
    assert!(dir.path().join("cad2mo.db").exists() || cad2mo_tests::app::postgres_base().is_some());
    let app = TestApp::spawn_in(dir, |_| {}).await;
    assert_eq!(app.health().await.status(), 200);
}

#[tokio::test]
async fn tokens_guard_models_and_writes_when_auth_is_required() {
    let app = TestApp::spawn_with(|s| s.force_auth = true).await;
    // No token: models are closed, the health check and library reads are open.
    let r = app.get("/api/models").await;
    assert_eq!(r.status(), 401);
    assert_eq!(r.headers()["content-type"], "application/problem+json");
    assert_eq!(r.headers()["www-authenticate"], "Bearer");
    assert_eq!(app.health().await.status(), 200);
    assert_eq!(app.get("/api/library/classes").await.status(), 200);
    let r = app.client.post(app.url("/api/library/instances")).json(&serde_json::json!({})).send().await.expect("post");
    assert_eq!(r.status(), 401);
    // Without a token, 401 comes first: not the 403 for a missing X-Requested-With.
    let r = reqwest::Client::new().delete(app.url("/api/models/x")).send().await.expect("delete");
    assert_eq!(problem_of(r, 401).await["type"], "/problems/unauthorized");
    // A wrong token is refused; a created one is accepted.
    let r = app.client.get(app.url("/api/models")).bearer_auth("c2m_wrong").send().await.expect("get");
    assert_eq!(r.status(), 401);
    let url = app.database_url().to_string();
    let store = cad2mo_server::store::Store::open(&url).await.expect("store");
    let token = cad2mo_server::store::tokens::create(&store, "test", None).await.expect("token");
    let r = app.client.get(app.url("/api/models")).bearer_auth(&token).send().await.expect("get");
    assert_eq!(r.status(), 200);
    // Only the hash is stored.
    let stored: Vec<(String,)> = sqlx_rows(&store).await;
    assert!(stored.iter().all(|(h,)| h != &token && h.len() == 64));
}

async fn sqlx_rows(store: &cad2mo_server::store::Store) -> Vec<(String,)> {
    cad2mo_server::store::tokens::hashes(store).await.expect("hashes").into_iter().map(|h| (h,)).collect()
}

/// Library reads are cached; a write must never leave a stale read behind.
#[tokio::test]
async fn library_cache_never_serves_stale_reads() {
    let app = TestApp::spawn().await;
    let list: serde_json::Value = app.get("/api/library/instances?domain=gear").await.json().await.expect("list");
    let inst = list.as_array().expect("instances").iter().find(|i| i["values"]["ratio"].is_number()).expect("a gear").clone();
    let id = inst["id"].as_str().expect("id");
    let mut update = serde_json::json!({"name": inst["name"], "source": inst["source"], "values": inst["values"]});
    update["values"]["ratio"] = serde_json::json!(42.5);
    let r = app.client.put(app.url(&format!("/api/library/instances/{id}"))).json(&update).send().await.expect("put");
    assert_eq!(r.status(), 200, "{}", r.text().await.unwrap_or_default());
    for path in [format!("/api/library/instances/{id}"), "/api/library/instances?domain=gear".to_string()] {
        let body: serde_json::Value = app.get(&path).await.json().await.expect("json");
        let text = body.to_string();
        assert!(text.contains("42.5"), "{path} is stale: {text}");
    }
}

async fn problem_of(r: reqwest::Response, status: u16) -> serde_json::Value {
    cad2mo_tests::app_models::problem(r, status).await
}

async fn open_store(app: &TestApp) -> cad2mo_server::store::Store {
    let url = app.database_url().to_string();
    cad2mo_server::store::Store::open(&url).await.expect("store")
}

fn pendulum_zip() -> Vec<u8> {
    cad2mo_tests::app::zip_dir(&cad2mo_tests::common::workspace_root().join("tests/in/pendulum"))
}

fn bundle_form() -> reqwest::multipart::Form {
    cad2mo_tests::app_models::upload_form(pendulum_zip(), "p.zip", &[])
}

/// On loopback without a token, a web page in the user's browser must not drive the service:
/// each request below is what such a page can send (no CORS preflight needed), and is refused.
#[tokio::test]
async fn loopback_refuses_what_a_cross_site_page_can_send() {
    let app = TestApp::spawn().await;
    let page = reqwest::Client::new(); // a browser page: no client header
    let evil = "http://evil.example";
    let library_before = app.export_library().await.text().await.expect("xml");
    // The XML import of a replaced motor, as text/plain (a "simple" cross-site request).
    // (The library as it is: the same request with the client header is accepted, below.)
    let attack_xml = library_before.clone();
    let import = || page.post(app.url("/api/library/import")).header("content-type", "text/plain");
    let p = problem_of(import().header("origin", evil).body(attack_xml.clone()).send().await.expect("post"), 403).await;
    assert_eq!(p["type"], "/problems/cross-origin", "{p}");
    // Without an Origin (older browsers, some privacy settings): the client header is missing.
    let p = problem_of(import().body(attack_xml.clone()).send().await.expect("post"), 403).await;
    assert_eq!(p["type"], "/problems/client-header-required", "{p}");
    assert!(p["detail"].as_str().expect("detail").contains("X-Requested-With"), "says what to send: {p}");
    // A multipart upload, a re-export of everything, a delete.
    let r = page.post(app.url("/api/models")).multipart(bundle_form()).send().await.expect("post");
    assert_eq!(problem_of(r, 403).await["type"], "/problems/client-header-required");
    let r = page.post(app.url("/api/models")).header("origin", evil).multipart(bundle_form()).send().await.expect("post");
    assert_eq!(problem_of(r, 403).await["type"], "/problems/cross-origin");
    let r = page.post(app.url("/api/reexport")).send().await.expect("post");
    assert_eq!(problem_of(r, 403).await["type"], "/problems/client-header-required");
    // Even with the header (a page cannot send it cross-site, but a foreign Origin is enough).
    let r = app.client.post(app.url("/api/reexport")).header("origin", evil).send().await.expect("post");
    assert_eq!(problem_of(r, 403).await["type"], "/problems/cross-origin");
    let r = app.client.post(app.url("/api/reexport")).header("origin", "null").send().await.expect("post");
    assert_eq!(problem_of(r, 403).await["type"], "/problems/cross-origin");
    // DNS rebinding: evil.example resolved to 127.0.0.1 sends `Host: evil.example:PORT`.
    let port = app.address.rsplit(':').next().expect("port").to_string();
    let r = page.get(app.url("/api/models")).header("host", format!("evil.example:{port}")).send().await.expect("get");
    assert_eq!(problem_of(r, 421).await["type"], "/problems/misdirected-request");
    let r = page.get(app.url("/")).header("host", "evil.example").send().await.expect("get");
    problem_of(r, 421).await;
    // Nothing changed.
    assert_eq!(app.export_library().await.text().await.expect("xml"), library_before);
    assert_eq!(app.models().await.json::<serde_json::Value>().await.expect("json"), serde_json::json!([]));

    // The UI's own requests pass: same origin (by IP or localhost), with the header.
    let origin = app.address.clone();
    let r = app.client.post(app.url("/api/models")).header("origin", &origin).multipart(bundle_form()).send().await.expect("post");
    let (_, _, job) = cad2mo_tests::app_models::accepted(r).await;
    let r = app
        .client
        .post(app.url("/api/library/import"))
        .header("origin", format!("http://localhost:{port}"))
        .header("content-type", "application/xml")
        .body(library_before.clone())
        .send()
        .await
        .expect("post");
    assert_eq!(r.status(), 200, "{}", r.text().await.unwrap_or_default());
    for host in [format!("localhost:{port}"), format!("[::1]:{port}"), format!("127.0.0.1:{port}")] {
        assert_eq!(page.get(app.url("/api/models")).header("host", host.as_str()).send().await.expect("get").status(), 200, "{host}");
    }
    // Scripts without a token: a JSON body is enough (a page cannot send it cross-site).
    let r = page.post(app.url("/api/library/instances")).json(&serde_json::json!({})).send().await.expect("post");
    assert_eq!(r.status(), 422, "past the guard");
    app.wait_for_job(&job).await;

    // A valid token passes whatever the origin and content type; an invalid one does not.
    let token = cad2mo_server::store::tokens::create(&open_store(&app).await, "t", None).await.expect("token");
    let r = page.post(app.url("/api/reexport")).header("origin", evil).bearer_auth(&token).send().await.expect("post");
    assert_eq!(r.status(), 202);
    let r = page.post(app.url("/api/reexport")).header("origin", evil).bearer_auth("c2m_nope").send().await.expect("post");
    problem_of(r, 403).await;
}

#[tokio::test]
async fn allowed_hosts_extend_the_names_the_service_answers_to() {
    let app = TestApp::spawn_with(|s| s.allowed_hosts = vec!["cad.example.org".into(), "box:9000".into()]).await;
    let get = |host: &'static str| app.client.get(app.url("/api/models")).header("host", host).send();
    assert_eq!(get("cad.example.org").await.expect("get").status(), 200);
    assert_eq!(get("CAD.example.org:443").await.expect("get").status(), 200);
    assert_eq!(get("box:9000").await.expect("get").status(), 200);
    problem_of(get("box:9001").await.expect("get"), 421).await;
    problem_of(get("other.example.org").await.expect("get"), 421).await;
    // Its origin is one of ours.
    let r = app
        .client
        .post(app.url("/api/reexport"))
        .header("host", "cad.example.org")
        .header("origin", "https://cad.example.org")
        .send()
        .await
        .expect("post");
    assert_eq!(r.status(), 202);
}

#[tokio::test]
async fn tokens_expire_and_the_scheme_is_case_insensitive() {
    let app = TestApp::spawn_with(|s| s.force_auth = true).await;
    let store = open_store(&app).await;
    let token = cad2mo_server::store::tokens::create(&store, "t", Some(3600)).await.expect("token");
    let expired = cad2mo_server::store::tokens::create(&store, "old", Some(0)).await.expect("token");
    for scheme in ["Bearer", "bearer", "BEARER"] {
        let r = app.client.get(app.url("/api/models")).header("authorization", format!("{scheme} {token}")).send().await.expect("get");
        assert_eq!(r.status(), 200, "{scheme}");
    }
    let r = app.client.get(app.url("/api/models")).bearer_auth(&expired).send().await.expect("get");
    assert_eq!(problem_of(r, 401).await["type"], "/problems/unauthorized");
    // Revoked: refused at once.
    assert!(matches!(
        cad2mo_server::store::tokens::revoke(&store, "t").await.expect("revoke"),
        cad2mo_server::store::tokens::Revoked::One(_)
    ));
    let r = app.client.get(app.url("/api/models")).bearer_auth(&token).send().await.expect("get");
    problem_of(r, 401).await;
}

/// Bad path parameters are problem documents on every router (not axum's text/plain).
#[tokio::test]
async fn bad_path_and_query_parameters_are_problems() {
    let app = TestApp::spawn().await;
    use reqwest::Method;
    let cases = [
        (Method::GET, "/api/library/classes/%FF"),
        (Method::PUT, "/api/library/classes/%FF"),
        (Method::DELETE, "/api/library/classes/%FF"),
        (Method::GET, "/api/library/instances/%C3%28"),
        (Method::DELETE, "/api/library/instances/%FF"),
        (Method::GET, "/api/library/instances?class_id=a&class_id=b"),
        (Method::GET, "/api/models/%FF/drives"),
        (Method::GET, "/api/models/x/drives/%FF"),
        (Method::PUT, "/api/models/%FF/drives/J"),
        (Method::DELETE, "/api/models/x/drives/%FF"),
        (Method::POST, "/api/models/%FF/reexport"),
        (Method::GET, "/api/models/%FF"),
        (Method::GET, "/api/models/x/versions/%FF"),
        (Method::GET, "/api/jobs/%FF"),
        (Method::GET, "/api/models/x/diff?from=1&to=2&to=3"),
    ];
    for (method, path) in cases {
        let r = app
            .client
            .request(method.clone(), app.url(path))
            .header("content-type", "application/json")
            .body("{}")
            .send()
            .await
            .expect("request");
        let p = problem_of(r, 400).await;
        assert_eq!(p["type"], "/problems/bad-request", "{method} {path}: {p}");
    }
}
