//! Settings: one typed struct, loaded in one place (flags, with environment fallbacks).
//! Nothing else reads the environment.

use std::net::SocketAddr;
use std::path::PathBuf;

use clap::Args;

/// `cad2mo serve` flags. Every flag has an environment fallback (`CAD2MO_*`).
#[derive(Args, Debug, Clone)]
pub struct ServeArgs {
    /// Address to listen on.
    #[arg(long, env = "CAD2MO_BIND", default_value = "127.0.0.1:8080")]
    pub bind: SocketAddr,
    /// Database URL: `sqlite://FILE` (default: `<data-dir>/cad2mo.db`, created on start) or
    /// `postgres://USER:PASSWORD@HOST:PORT/DB` (several instances may share one PostgreSQL database).
    #[arg(long, env = "CAD2MO_DATABASE_URL")]
    pub database_url: Option<String>,
    /// Database connections per instance (mind PostgreSQL's max_connections across instances).
    #[arg(long, env = "CAD2MO_DB_POOL_SIZE", default_value_t = crate::store::POOL_SIZE)]
    pub db_pool_size: u32,
    /// Seconds a job's claim holds without renewal (renewed every third of it while the job runs):
    /// the jobs of an instance that died are taken over by another instance this long after.
    #[arg(long, env = "CAD2MO_LEASE_SECS", default_value_t = 30.0)]
    pub lease_secs: f64,
    /// Folder for the database and the content-addressed files (bundles, packages, reports).
    #[arg(long, env = "CAD2MO_DATA_DIR", default_value = "data")]
    pub data_dir: PathBuf,
    /// Largest accepted upload, in bytes.
    #[arg(long, env = "CAD2MO_MAX_UPLOAD", default_value_t = 256 * 1024 * 1024)]
    pub max_upload: u64,
    /// Conversion worker threads (default: the number of cores).
    #[arg(long, env = "CAD2MO_WORKERS")]
    pub workers: Option<usize>,
    /// Megabytes (10^6 bytes) the conversions running at once may need together, by their
    /// estimates (from each version's triangles and bundle size): a job waits until its estimate
    /// fits beside the running ones; one estimated over it runs alone.
    #[arg(long, env = "CAD2MO_JOB_MEMORY", default_value_t = crate::jobs::DEFAULT_JOB_MEMORY / 1_000_000)]
    pub job_memory: u64,
    /// Megabytes of collision shapes kept in memory by mesh content, shared by all conversions
    /// (re-exports and new versions reuse the shapes of unchanged meshes); 0: none kept.
    #[arg(long, env = "CAD2MO_SHAPE_CACHE_MB", default_value_t = 256)]
    pub shape_cache_mb: usize,
    /// Require bearer tokens even on loopback (they are always required beyond it).
    #[arg(long, env = "CAD2MO_REQUIRE_AUTH")]
    pub require_auth: bool,
    /// Uploads checked at once (each holds its bundle analysed in memory; default: --workers).
    /// Beyond it an upload waits up to --check-wait, then gets 503 with Retry-After.
    #[arg(long, env = "CAD2MO_MAX_CHECKS")]
    pub max_checks: Option<usize>,
    /// Seconds an upload may wait for a free check before 503.
    #[arg(long, env = "CAD2MO_CHECK_WAIT", default_value_t = 10.0)]
    pub check_wait: f64,
    /// HTTP connections served at once (lowered at start to fit under the open-file limit, which
    /// is first raised to its hard limit). Beyond it, 16 more connections answer only
    /// /api/health (others get 503 `busy`), the oldest of those dropped for the newest.
    #[arg(long, env = "CAD2MO_MAX_CONNECTIONS", default_value_t = 1000)]
    pub max_connections: usize,
    /// Seconds a client has to send a request's head (line and headers); the clock also runs
    /// while a kept-alive connection waits for its next request.
    #[arg(long, env = "CAD2MO_HEADER_TIMEOUT", default_value_t = 15.0)]
    pub header_timeout: f64,
    /// Longest pause, in seconds, while a request body is read (a stalled upload is dropped).
    #[arg(long, env = "CAD2MO_BODY_TIMEOUT", default_value_t = 30.0)]
    pub body_timeout: f64,
    /// Seconds an idle connection (no request in flight, no byte either way) is kept open.
    #[arg(long, env = "CAD2MO_KEEP_ALIVE_TIMEOUT", default_value_t = 5.0)]
    pub keep_alive_timeout: f64,
    /// Extra host names the service answers to (`name` for any port, `name:port`), e.g. behind
    /// a reverse proxy; repeat or separate by commas. Others get 421.
    #[arg(long = "allowed-host", env = "CAD2MO_ALLOWED_HOSTS", value_delimiter = ',')]
    pub allowed_hosts: Vec<String>,
    /// UDP address the live view listens on for running simulations (`off` to turn it off).
    #[arg(long, env = "CAD2MO_LIVE_BIND", default_value = "127.0.0.1:7878", value_parser = parse_live_bind)]
    pub live_bind: LiveBind,
    /// Host name that packages' live views send to (default: the live bind address, or the first
    /// --allowed-host when that is a wildcard).
    #[arg(long, env = "CAD2MO_LIVE_HOST")]
    pub live_host: Option<String>,
    /// Where bundles, packages and reports are kept: absent = `<data-dir>/blobs`;
    /// `s3://bucket/prefix` = an S3-compatible object store (credentials and region from the
    /// standard AWS_ACCESS_KEY_ID, AWS_SECRET_ACCESS_KEY, AWS_REGION variables).
    #[arg(long, env = "CAD2MO_BLOB_URL")]
    pub blob_url: Option<String>,
    /// Endpoint of an S3-compatible store other than AWS (MinIO, ...), e.g. http://minio:9000.
    #[arg(long, env = "CAD2MO_S3_ENDPOINT")]
    pub s3_endpoint: Option<String>,
}

/// `--live-bind`: an address, or off.
#[derive(Clone, Copy, Debug)]
pub struct LiveBind(pub Option<SocketAddr>);

fn parse_live_bind(s: &str) -> Result<LiveBind, String> {
    if s.eq_ignore_ascii_case("off") {
        return Ok(LiveBind(None));
    }
    s.parse::<SocketAddr>().map(|a| LiveBind(Some(a))).map_err(|e| format!("{s}: {e} (an address such as 127.0.0.1:7878, or off)"))
}

/// A timeout setting: `secs` within 0.05 s .. 1 hour (`default` when not a number).
fn seconds(secs: f64, default: f64) -> std::time::Duration {
    let secs = if secs.is_nan() { default } else { secs.clamp(0.05, 3600.0) };
    std::time::Duration::try_from_secs_f64(secs).unwrap_or(std::time::Duration::from_secs(30))
}

/// The service's settings.
#[derive(Debug, Clone)]
pub struct Settings {
    pub bind: SocketAddr,
    pub database_url: String,
    /// Database connections per instance.
    pub db_pool_size: u32,
    /// How long a job's claim holds without renewal (see `crate::jobs`).
    pub lease: std::time::Duration,
    pub data_dir: PathBuf,
    pub max_upload: u64,
    pub workers: usize,
    /// Bytes the running conversions' memory estimates may add up to (see `crate::jobs::MemoryBudget`).
    pub job_memory: u64,
    /// Bytes of the process's collision shape cache (see `cad2mo_engine::collision::MemoryShapeCache`).
    pub shape_cache_bytes: usize,
    /// Require tokens even on loopback.
    pub force_auth: bool,
    /// Upload checks (bundle analyses) at once.
    pub max_checks: usize,
    /// How long an upload waits for a check before 503.
    pub check_wait: std::time::Duration,
    /// HTTP connections served at once (before the open-file limit lowers it, see `App::build`).
    pub max_connections: usize,
    /// Time to send a request head (also the longest wait for the next request on a connection).
    pub header_timeout: std::time::Duration,
    /// Longest pause while a request body is read.
    pub body_timeout: std::time::Duration,
    /// How long an idle connection is kept open.
    pub keep_alive_timeout: std::time::Duration,
    /// Extra `Host` names (`name` or `name:port`), beyond the bound address.
    pub allowed_hosts: Vec<String>,
    /// Where the live view receives frames (`None`: off).
    pub live_bind: Option<SocketAddr>,
    /// The host name packages' live views send to (see [`Settings::live_host`]).
    pub live_host: Option<String>,
    /// Where blobs are kept (the local folder by default, or an S3-compatible store).
    pub blobs: crate::store::blobs::BlobSettings,
}

impl Settings {
    pub fn from_args(a: ServeArgs) -> Settings {
        let database_url = a.database_url.unwrap_or_else(|| format!("sqlite://{}?mode=rwc", a.data_dir.join("cad2mo.db").display()));
        let workers = a.workers.filter(|w| *w > 0).unwrap_or_else(|| std::thread::available_parallelism().map(|n| n.get()).unwrap_or(2));
        Settings {
            bind: a.bind,
            database_url,
            db_pool_size: a.db_pool_size.max(1),
            lease: std::time::Duration::try_from_secs_f64(a.lease_secs.clamp(1.0, 3600.0)).unwrap_or(std::time::Duration::from_secs(30)),
            data_dir: a.data_dir,
            max_upload: a.max_upload,
            workers,
            job_memory: a.job_memory.max(1).saturating_mul(1_000_000),
            shape_cache_bytes: a.shape_cache_mb.saturating_mul(1 << 20),
            force_auth: a.require_auth,
            max_checks: a.max_checks.filter(|n| *n > 0).unwrap_or(workers),
            check_wait: std::time::Duration::try_from_secs_f64(a.check_wait.clamp(0.0, 600.0)).unwrap_or_default(),
            max_connections: a.max_connections.max(1),
            header_timeout: seconds(a.header_timeout, 15.0),
            body_timeout: seconds(a.body_timeout, 30.0),
            keep_alive_timeout: seconds(a.keep_alive_timeout, 5.0),
            allowed_hosts: a.allowed_hosts.into_iter().map(|h| h.trim().to_string()).filter(|h| !h.is_empty()).collect(),
            live_bind: a.live_bind.0,
            live_host: a.live_host.map(|h| h.trim().to_string()).filter(|h| !h.is_empty()),
            blobs: crate::store::blobs::BlobSettings {
                url: a.blob_url.map(|u| u.trim().to_string()).filter(|u| !u.is_empty()),
                s3_endpoint: a.s3_endpoint.map(|u| u.trim().to_string()).filter(|u| !u.is_empty()),
                ..Default::default()
            },
        }
    }

    /// Settings for tests: port 0 on loopback, everything under `dir`.
    pub fn for_tests(dir: &std::path::Path) -> Settings {
        Settings {
            bind: SocketAddr::from(([127, 0, 0, 1], 0)),
            database_url: format!("sqlite://{}?mode=rwc", dir.join("cad2mo.db").display()),
            db_pool_size: crate::store::POOL_SIZE,
            lease: std::time::Duration::from_secs(30),
            data_dir: dir.to_path_buf(),
            max_upload: 64 * 1024 * 1024,
            workers: 2,
            job_memory: crate::jobs::DEFAULT_JOB_MEMORY,
            shape_cache_bytes: cad2mo_engine::collision::DEFAULT_CACHE_BYTES,
            force_auth: false,
            max_checks: 2,
            check_wait: std::time::Duration::from_secs(10),
            max_connections: 1000,
            header_timeout: std::time::Duration::from_secs(15),
            body_timeout: std::time::Duration::from_secs(30),
            keep_alive_timeout: std::time::Duration::from_secs(5),
            allowed_hosts: Vec::new(),
            live_bind: Some(SocketAddr::from(([127, 0, 0, 1], 0))),
            live_host: None,
            blobs: Default::default(),
        }
    }

    /// The host that packages' live views send to: `--live-host`, else the live bind address,
    /// else (bound to a wildcard) the first `--allowed-host`'s name, else 127.0.0.1.
    pub fn live_host(&self) -> String {
        if let Some(h) = &self.live_host {
            return h.clone();
        }
        match self.live_bind {
            Some(a) if !a.ip().is_unspecified() => a.ip().to_string(),
            _ => self
                .allowed_hosts
                .first()
                .map(|h| h.rsplit_once(':').filter(|(_, p)| p.parse::<u16>().is_ok()).map_or(h.as_str(), |(n, _)| n).to_string())
                .unwrap_or_else(|| "127.0.0.1".to_string()),
        }
    }

    /// Whether the service requires bearer tokens (it listens beyond loopback).
    pub fn requires_auth(&self) -> bool {
        self.force_auth || !self.bind.ip().is_loopback()
    }
}
