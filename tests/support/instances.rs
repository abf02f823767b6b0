//! Real `cad2mo serve` processes on one database and one blob store, for the multi-instance tests
//! (tests/multi_instance.rs) — the binary cargo builds, not the library in this process.
//!
//! The database: `CAD2MO_TEST_DATABASE_URL` when set (a PostgreSQL server for several instances),
//! else one SQLite file in WAL mode, which several processes share safely on one machine. The
//! blob store: the S3-compatible test server when `CAD2MO_TEST_S3_ENDPOINT` is set, else one
//! local folder (both instances get the same data folder then, as blobs live under it).

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use crate::common::workspace_root;
use crate::s3::S3Place;

/// The service binary, built first by cargo (a no-op when it is current), in the target folder
/// this test binary was built in.
pub fn binary() -> PathBuf {
    let exe = std::env::current_exe().expect("test binary path");
    // <target>/<profile>/deps/<test binary>
    let profile_dir = exe.parent().and_then(Path::parent).expect("target/<profile>").to_path_buf();
    let target_dir = profile_dir.parent().expect("target folder").to_path_buf();
    let release = profile_dir.file_name().is_some_and(|n| n == "release");
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let mut build = Command::new(cargo);
    build.args(["build", "--quiet", "-p", "cad2mo", "--bin", "cad2mo", "--target-dir"]).arg(&target_dir);
    // Without the variables cargo sets for this test binary: build scripts watch some of them
    // (ring: CARGO_MANIFEST_DIR), and a change would rebuild the service here and again after.
    for (k, _) in std::env::vars_os() {
        let k = k.to_string_lossy().to_string();
        let set_by_cargo = [
            "CARGO_MANIFEST_",
            "CARGO_PKG_",
            "CARGO_CRATE_",
            "CARGO_BIN_",
            "CARGO_PRIMARY_",
            "CARGO_TARGET_TMPDIR",
            "CARGO_RUSTC_CURRENT_DIR",
        ];
        if set_by_cargo.iter().any(|p| k.starts_with(p)) {
            build.env_remove(&k);
        }
    }
    if release {
        build.arg("--release");
    }
    let built = build.current_dir(workspace_root()).status();
    let bin = profile_dir.join(format!("cad2mo{}", std::env::consts::EXE_SUFFIX));
    assert!(bin.is_file(), "no service binary at {} (cargo build: {built:?})", bin.display());
    bin
}

/// Whether `cad2mo serve` accepts `flag` (features of other branches are probed, not assumed).
pub fn serve_accepts(bin: &Path, flag: &str) -> bool {
    let help = Command::new(bin).args(["serve", "--help"]).output().expect("cad2mo serve --help");
    String::from_utf8_lossy(&help.stdout).contains(flag)
}

/// A free loopback port (bound then released).
fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0").expect("bind").local_addr().expect("addr").port()
}

/// One running `cad2mo serve`.
pub struct Instance {
    pub name: String,
    pub address: String,
    pub log: PathBuf,
    child: Option<Child>,
}

impl Instance {
    /// Kills the process with SIGKILL (no shutdown, nothing recorded) and waits for it.
    pub fn kill9(&mut self) {
        if let Some(mut c) = self.child.take() {
            let _ = c.kill();
            let _ = c.wait();
        }
    }

    pub fn url(&self, path: &str) -> String {
        format!("{}{}", self.address, path)
    }

    /// Sends SIGTERM (a graceful stop) and waits up to `within` for the process to end: its exit
    /// status, or `None` if it did not end (it is then killed).
    pub fn terminate(&mut self, within: Duration) -> Option<std::process::ExitStatus> {
        let mut c = self.child.take()?;
        let _ = Command::new("kill").args(["-TERM", &c.id().to_string()]).status();
        let deadline = Instant::now() + within;
        while Instant::now() < deadline {
            if let Ok(Some(status)) = c.try_wait() {
                return Some(status);
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        let _ = c.kill();
        let _ = c.wait();
        None
    }

    /// The process id, while it runs.
    pub fn pid(&self) -> Option<u32> {
        self.child.as_ref().map(Child::id)
    }

    /// Its log so far.
    pub fn log_text(&self) -> String {
        std::fs::read_to_string(&self.log).unwrap_or_default()
    }

    /// Job ids this instance logged as succeeded.
    pub fn succeeded_jobs(&self) -> Vec<String> {
        self.log_text()
            .lines()
            .filter(|l| l.contains("job succeeded"))
            .filter_map(|l| l.split("job_id=").nth(1).map(|r| r.split([' ', '}']).next().unwrap_or_default().to_string()))
            .collect()
    }
}

impl Drop for Instance {
    fn drop(&mut self) {
        self.kill9();
    }
}

/// Where the instances keep their data.
pub struct Cluster {
    /// The database URL every instance uses.
    pub database_url: String,
    /// The S3 place, when blobs are on the S3 test server.
    pub s3: Option<S3Place>,
    pub bin: PathBuf,
    dir: tempfile::TempDir,
    extra: Vec<String>,
    started: usize,
}

impl Cluster {
    /// A database and a blob store for `test`; instances are started with [`Cluster::start`],
    /// each with `extra` flags.
    pub async fn new(test: &str, extra: &[&str]) -> Cluster {
        let bin = binary();
        let dir = tempfile::tempdir().expect("tempdir");
        // CAD2MO_TEST_DATABASE_URL names a PostgreSQL server: a fresh database on it.
        let database_url = match std::env::var("CAD2MO_TEST_DATABASE_URL").ok().filter(|u| !u.is_empty()) {
            Some(base) => cad2mo_server::store::testdb::create_database(&base).await.expect("a test database on CAD2MO_TEST_DATABASE_URL"),
            None => format!("sqlite://{}?mode=rwc", dir.path().join("shared.db").display()),
        };
        let s3 = crate::s3::try_place(test).await;
        if s3.is_none() {
            println!("NOTICE: {test}: blobs in one shared local folder instead of an S3-compatible store");
        }
        Cluster { database_url, s3, bin, dir, extra: extra.iter().map(|s| s.to_string()).collect(), started: 0 }
    }

    /// The data folder of instance `i` (one shared folder when blobs are local).
    fn data_dir(&self, i: usize) -> PathBuf {
        match &self.s3 {
            Some(_) => self.dir.path().join(format!("instance{i}")),
            None => self.dir.path().join("shared"),
        }
    }

    /// Starts one more instance and waits until it answers.
    pub async fn start(&mut self) -> Instance {
        let i = self.started;
        self.started += 1;
        let data_dir = self.data_dir(i);
        std::fs::create_dir_all(&data_dir).expect("data folder");
        let log = self.dir.path().join(format!("instance{i}.log"));
        let client = reqwest::Client::new();
        for _ in 0..5 {
            let port = free_port();
            let mut cmd = Command::new(&self.bin);
            cmd.arg("serve")
                .args(["--bind", &format!("127.0.0.1:{port}")])
                .arg("--data-dir")
                .arg(&data_dir)
                .args(["--database-url", &self.database_url, "--live-bind", "off"])
                .args(&self.extra)
                .env("NO_COLOR", "1")
                .env("RUST_LOG", "info,sqlx=warn,tower_http=warn")
                .stdin(Stdio::null())
                .stdout(std::fs::File::create(&log).expect("log"))
                .stderr(std::fs::File::options().append(true).open(&log).expect("log"));
            for (k, v) in self.s3.iter().flat_map(S3Place::env) {
                cmd.env(k, v);
            }
            let mut child = cmd.spawn().expect("cad2mo serve starts");
            let address = format!("http://127.0.0.1:{port}");
            let deadline = Instant::now() + Duration::from_secs(60);
            loop {
                if let Ok(Some(status)) = child.try_wait() {
                    let text = std::fs::read_to_string(&log).unwrap_or_default();
                    if text.contains("binding") {
                        break; // the port was taken meanwhile: another one
                    }
                    panic!("instance {i} exited ({status}):\n{text}");
                }
                if client.get(format!("{address}/api/health")).send().await.is_ok_and(|r| r.status().is_success()) {
                    return Instance { name: format!("instance{i}"), address, log, child: Some(child) };
                }
                assert!(
                    Instant::now() < deadline,
                    "instance {i} did not answer in 60 s:\n{}",
                    std::fs::read_to_string(&log).unwrap_or_default()
                );
                tokio::time::sleep(Duration::from_millis(50)).await;
            }
        }
        panic!("instance {i}: no free port after 5 tries");
    }

    /// Where a blob lives when blobs are in the local folder.
    pub fn local_blob_path(&self, hash: &str) -> PathBuf {
        self.data_dir(0).join("blobs").join(&hash[..2]).join(hash)
    }

    /// Runs `cad2mo check-blobs` on the shared database and blob store: (exit code, stdout).
    pub fn check_blobs(&self) -> (Option<i32>, String) {
        let mut cmd = Command::new(&self.bin);
        cmd.arg("check-blobs").arg("--data-dir").arg(self.data_dir(0)).args(["--database-url", &self.database_url]).env("NO_COLOR", "1");
        for (k, v) in self.s3.iter().flat_map(S3Place::env) {
            cmd.env(k, v);
        }
        let out = cmd.output().expect("cad2mo check-blobs runs");
        let stdout = String::from_utf8_lossy(&out.stdout).to_string();
        assert!(out.status.code().is_some_and(|c| c <= 1), "check-blobs failed: {}\n{stdout}", String::from_utf8_lossy(&out.stderr));
        (out.status.code(), stdout)
    }

    /// The shared database and blob store, opened by this process (for the integrity checks).
    pub async fn open(&self) -> (cad2mo_server::store::Store, cad2mo_server::store::blobs::Blobs) {
        let store = cad2mo_server::store::Store::open(&self.database_url).await.expect("database");
        let settings = self.s3.as_ref().map(S3Place::settings).unwrap_or_default();
        let blobs = cad2mo_server::store::blobs::Blobs::open(&settings, &self.data_dir(0)).await.expect("blobs");
        (store, blobs)
    }
}
