//! Several service instances on one PostgreSQL database (issue 16): what one instance runs,
//! another shows. Needs `CAD2MO_TEST_DATABASE_URL` (`scripts/test` starts a PostgreSQL server);
//! without it the tests print a notice and pass (SQLite has one server per database).

use cad2mo_tests::app::{heavy_pendulum, postgres_base, TestApp};
use serde_json::Value;

/// A job running on instance A: polling instance B shows its progress, stage by stage (from the
/// progress row A writes), then its result.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_running_jobs_progress_is_visible_from_another_instance() {
    if postgres_base().is_none() {
        eprintln!("NOTICE: CAD2MO_TEST_DATABASE_URL is not set: several instances need PostgreSQL; skipped");
        return;
    }
    let a = TestApp::spawn_with(|s| s.workers = 1).await;
    let created: Value = a.upload_model(heavy_pendulum(300_000), "heavy.zip", &[]).await.json().await.expect("json");
    let job = created["job_id"].as_str().expect("job").to_string();
    let url = a.database_url().to_string();
    // B starts once A has the job (A claims it at once), so B, with nothing to claim, only reads.
    let b = TestApp::spawn_with(move |s| {
        s.workers = 1;
        s.database_url = url;
    })
    .await;
    let mut stages = Vec::new();
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(120);
    let done = loop {
        let seen: Value = b.job(&job).await.json().await.expect("json");
        match seen["status"].as_str() {
            Some("running") => {
                if let Some(stage) = seen["progress"]["stage"].as_str() {
                    assert!(seen["progress"]["fraction"].as_f64().is_some_and(|f| (0.0..=1.0).contains(&f)), "{seen:#}");
                    if stages.last().map(String::as_str) != Some(stage) {
                        stages.push(stage.to_string());
                    }
                }
            }
            Some("succeeded" | "failed") => break seen,
            _ => {}
        }
        assert!(std::time::Instant::now() < deadline, "the job did not finish: {seen:#}");
        tokio::time::sleep(std::time::Duration::from_millis(50)).await;
    };
    assert_eq!(done["status"], "succeeded", "{done:#}");
    assert!(done.get("progress").is_none());
    assert!(!stages.is_empty(), "instance B never showed the progress of A's running job");
    eprintln!("stages seen from the other instance: {stages:?}");
    // A ran it (B had nothing to claim): the same answer from both.
    let from_a: Value = a.job(&job).await.json().await.expect("json");
    assert_eq!(from_a["finished_at"], done["finished_at"]);
    // The job outlived its lease (2 s in tests) several times over, and A's renewals kept it:
    // B, polling for work all along, never took it over.
    let store = cad2mo_server::store::Store::open(a.database_url()).await.expect("store");
    let row = cad2mo_server::store::models::get_job(&store.pool, &job).await.expect("job").expect("job");
    assert_eq!(row.attempts, 1, "the running job was taken over: its lease was not renewed");
}
