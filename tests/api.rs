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
    assert_eq!(body["version"], cad2mo::pipeline::VERSION);
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
    assert!(dir.path().join("cad2mo.db").exists());
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
    // A wrong token is refused; a created one is accepted.
    let r = app.client.get(app.url("/api/models")).bearer_auth("c2m_wrong").send().await.expect("get");
    assert_eq!(r.status(), 401);
    let url = format!("sqlite://{}?mode=rwc", app.data_dir().join("cad2mo.db").display());
    let store = cad2mo::store::Store::open(&url).await.expect("store");
    let token = cad2mo::store::tokens::create(&store, "test").await.expect("token");
    let r = app.client.get(app.url("/api/models")).bearer_auth(&token).send().await.expect("get");
    assert_eq!(r.status(), 200);
    // Only the hash is stored.
    let stored: Vec<(String,)> = sqlx_rows(&store).await;
    assert!(stored.iter().all(|(h,)| h != &token && h.len() == 64));
}

async fn sqlx_rows(store: &cad2mo::store::Store) -> Vec<(String,)> {
    cad2mo::store::tokens::hashes(store).await.expect("hashes").into_iter().map(|h| (h,)).collect()
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
