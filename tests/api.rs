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
