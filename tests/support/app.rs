//! `TestApp`: the real service on port 0 with a fresh database and data folder per test, and one
//! method per endpoint. The database is SQLite in the data folder, or, when
//! `CAD2MO_TEST_DATABASE_URL` names a PostgreSQL server (`scripts/test` starts one for a second
//! run of the API tests), a new database `t_<uuid>` on it, dropped with the app (its URL is kept
//! in the data folder, so a restart on the same folder finds it).

use std::path::Path;

use cad2mo_server::app::App;
use cad2mo_server::config::Settings;

pub struct TestApp {
    pub address: String,
    /// Sends `X-Requested-With: cad2mo` like the browser UI (without a token, the service
    /// refuses state-changing requests without it); use `reqwest::Client::new()` to play a
    /// cross-site page.
    pub client: reqwest::Client,
    dir: Option<tempfile::TempDir>,
    handle: Option<tokio::task::JoinHandle<()>>,
    /// Asks the app to stop as Ctrl-C or SIGTERM would ([`TestApp::stop_gracefully`]).
    graceful: Option<tokio::sync::oneshot::Sender<()>>,
    jobs: cad2mo_server::jobs::Jobs,
    database_url: String,
    /// Another app's database (not dropped with this one).
    shared: bool,
}

impl Drop for TestApp {
    fn drop(&mut self) {
        if let Some(h) = self.handle.take() {
            h.abort();
        }
        // Dropped with its data folder (not handed back by `stop`): its PostgreSQL database goes too.
        if let (Some(_), Some(base)) = (&self.dir, postgres_base()) {
            if !self.shared {
                cad2mo_server::store::testdb::drop_database_blocking(base, self.database_url.clone());
            }
        }
    }
}

/// The PostgreSQL server API tests run on (`CAD2MO_TEST_DATABASE_URL`), if any.
pub fn postgres_base() -> Option<String> {
    std::env::var("CAD2MO_TEST_DATABASE_URL").ok().filter(|u| !u.is_empty())
}

/// The database URL of the data folder `dir`: SQLite inside it, or its PostgreSQL database
/// (created on first use, its URL kept in `dir/postgres-url`).
pub async fn database_url_for(dir: &Path) -> String {
    let Some(base) = postgres_base() else {
        return format!("sqlite://{}?mode=rwc", dir.join("cad2mo.db").display());
    };
    let file = dir.join("postgres-url");
    if let Ok(url) = std::fs::read_to_string(&file) {
        return url;
    }
    let url = cad2mo_server::store::testdb::create_database(&base).await.expect("a test database on CAD2MO_TEST_DATABASE_URL");
    std::fs::write(&file, &url).expect("postgres-url");
    url
}

impl TestApp {
    /// Spawns the app with default test settings.
    pub async fn spawn() -> TestApp {
        Self::spawn_with(|_| {}).await
    }

    /// Spawns the app after `tweak` adjusts the settings.
    pub async fn spawn_with(tweak: impl FnOnce(&mut Settings)) -> TestApp {
        let dir = tempfile::tempdir().expect("tempdir");
        Self::spawn_in(dir, tweak).await
    }

    /// Spawns the app on an existing data folder (restart tests).
    pub async fn spawn_in(dir: tempfile::TempDir, tweak: impl FnOnce(&mut Settings)) -> TestApp {
        let mut settings = Settings::for_tests(dir.path());
        settings.database_url = database_url_for(dir.path()).await;
        if postgres_base().is_some() {
            // A stopped (killed) app's jobs are taken over after their lease: keep it short.
            settings.lease = std::time::Duration::from_secs(2);
        }
        let own_database = settings.database_url.clone();
        tweak(&mut settings);
        // A tweak may point the app at another app's database (several instances): not ours to drop.
        let shared = settings.database_url != own_database;
        let database_url = settings.database_url.clone();
        let app = App::build(settings).await.expect("app builds");
        let address = format!("http://{}", app.local_addr());
        let jobs = app.state().jobs.clone();
        let (graceful, asked) = tokio::sync::oneshot::channel::<()>();
        let handle = tokio::spawn(async move {
            let _ = app
                .run_until(async {
                    if asked.await.is_err() {
                        std::future::pending::<()>().await;
                    }
                })
                .await;
        });
        TestApp { address, client: ui_client(), dir: Some(dir), handle: Some(handle), graceful: Some(graceful), jobs, database_url, shared }
    }

    /// The app's database URL (SQLite in its data folder, or its PostgreSQL database).
    pub fn database_url(&self) -> &str {
        &self.database_url
    }

    /// The data folder (database and blobs).
    /// The counters of the service's collision shape cache (shared by all its jobs).
    pub fn shape_cache_stats(&self) -> cad2mo_engine::collision::CacheStats {
        self.jobs.shape_cache_stats()
    }

    pub fn data_dir(&self) -> &Path {
        self.dir.as_ref().expect("data folder").path()
    }

    /// Stops the server abruptly (like a kill: its running jobs are abandoned, never recorded)
    /// and hands back its data folder.
    pub async fn stop(mut self) -> tempfile::TempDir {
        if let Some(h) = self.handle.take() {
            h.abort();
            let _ = h.await;
        }
        self.jobs.halt().await;
        self.dir.take().expect("data folder")
    }

    /// Stops the server as Ctrl-C or SIGTERM does (`App::run_until`'s graceful stop: the jobs it
    /// was running go back to the queue uncharged), waits for it (at most 30 s) and hands back
    /// its data folder.
    pub async fn stop_gracefully(mut self) -> tempfile::TempDir {
        if let Some(g) = self.graceful.take() {
            let _ = g.send(());
        }
        if let Some(h) = self.handle.take() {
            tokio::time::timeout(std::time::Duration::from_secs(30), h).await.expect("stopped within 30 s").expect("the server task");
        }
        self.dir.take().expect("data folder")
    }

    pub fn url(&self, path: &str) -> String {
        format!("{}{}", self.address, path)
    }

    pub async fn get(&self, path: &str) -> reqwest::Response {
        self.client.get(self.url(path)).send().await.expect("request")
    }

    pub async fn health(&self) -> reqwest::Response {
        self.get("/api/health").await
    }
}

/// A client that sends what the browser UI sends with every request (web/src/api.js).
pub fn ui_client() -> reqwest::Client {
    let mut headers = reqwest::header::HeaderMap::new();
    headers.insert("x-requested-with", reqwest::header::HeaderValue::from_static("cad2mo"));
    reqwest::Client::builder().default_headers(headers).build().expect("client")
}

/// Zips a directory (a bundle folder) into memory, paths relative to it.
pub fn zip_dir(dir: &Path) -> Vec<u8> {
    let mut files = Vec::new();
    for p in crate::common::files_with_ext(dir, &[""]) {
        let rel = p.strip_prefix(dir).expect("under dir").to_string_lossy().replace('\\', "/");
        files.push((rel, std::fs::read(&p).expect("read")));
    }
    cad2mo_engine::pipeline::back::bundle::write_zip(&files).expect("zip")
}

/// The pendulum case with a binary STL of `triangles` small facets inside its link's box (mm):
/// a bundle whose conversion takes long enough (seconds in a debug build) to be watched.
pub fn heavy_pendulum(triangles: u32) -> Vec<u8> {
    let dir = crate::common::workspace_root().join("tests/in/pendulum");
    let xml = std::fs::read(dir.join("PENDULUM.xml")).expect("xml");
    let mut stl = vec![0u8; 80];
    stl.extend_from_slice(&triangles.to_le_bytes());
    for i in 0..triangles {
        let x = -15.0 + 330.0 * (i as f32 / triangles as f32);
        let y = -15.0 + 30.0 * ((i % 97) as f32 / 97.0);
        stl.extend_from_slice(&[0f32, 0.0, 1.0].map(f32::to_le_bytes).concat());
        for v in [[x, y, 0.0], [x + 0.5, y, 0.0], [x, y + 0.5, 1.0]] {
            stl.extend_from_slice(&v.map(f32::to_le_bytes).concat());
        }
        stl.extend_from_slice(&[0, 0]);
    }
    cad2mo_engine::pipeline::back::bundle::write_zip(&[("PENDULUM.xml".into(), xml), ("meshes/LINK_prt.stl".into(), stl)]).expect("zip")
}

/// The JSON body of a response, asserting its status first (the body is in the message).
pub async fn json_of(r: reqwest::Response, status: u16) -> serde_json::Value {
    let s = r.status().as_u16();
    let v: serde_json::Value = r.json().await.expect("json body");
    assert_eq!(s, status, "{v:#}");
    v
}
