//! The application: [`App::build`] opens the store, starts the workers and binds the listener;
//! [`App::run_until_stopped`] serves. Tests build on port 0 and read [`App::local_addr`].
//!
//! Start-up recovery: `App::build` starts the conversion workers with [`Jobs::start`], which first
//! re-queues every job a previous run left `queued` or `running` (a crash, a kill, a power cut):
//! conversion is idempotent, so such jobs are simply redone and never stay stuck.

use std::net::SocketAddr;
use std::sync::Arc;

use anyhow::Context;
use tokio::net::TcpListener;

use crate::config::Settings;
use crate::jobs::Jobs;
use crate::store::blobs::Blobs;
use crate::store::Store;

/// Shared by every handler (cheap to clone).
#[derive(Clone)]
pub struct AppState {
    pub settings: Arc<Settings>,
    pub store: Store,
    pub blobs: Blobs,
    /// The conversion worker pool (notify it after queueing a job).
    pub jobs: Jobs,
    /// Permits for upload checks (`settings.max_checks`): bounds the bundles analysed at once.
    pub checks: Arc<tokio::sync::Semaphore>,
    /// Permits for closed-loop simulations (`settings.workers`): bounds the runs at once.
    pub simulations: Arc<tokio::sync::Semaphore>,
    /// Analysed versions for motions (a few, most recently used).
    pub kinematics: crate::service::motions::Cache,
    /// The address actually bound (port 0 resolved): the `Host` the service answers to.
    pub addr: SocketAddr,
    /// The live view: frames from running simulations, relayed to browsers.
    pub relay: crate::relay::Relay,
    /// Collision shapes of a few versions (read back from their packages).
    pub collisions: crate::service::motions::Cache<crate::service::collisions::VersionShapes>,
}

pub struct App {
    listener: TcpListener,
    state: AppState,
}

/// Starts the conversion workers with the service's settings; a failed job is stored with the
/// problem document the API shows for it.
pub async fn start_jobs(
    store: Store,
    blobs: Blobs,
    settings: &Settings,
    live: Option<(String, u16)>,
) -> Result<Jobs, crate::store::StoreError> {
    let workers = crate::jobs::Workers { count: settings.workers, memory: settings.job_memory };
    Jobs::start(store, blobs, workers, live, settings.lease, settings.shape_cache_bytes, crate::api::error::job_problem).await
}

impl App {
    pub async fn build(settings: Settings) -> anyhow::Result<App> {
        std::fs::create_dir_all(&settings.data_dir).with_context(|| format!("creating data folder {}", settings.data_dir.display()))?;
        let store = Store::open_with(&settings.database_url, settings.db_pool_size).await.context("opening the database")?;
        crate::store::library::seed_if_empty(&store).await.context("seeding the motor library")?;
        crate::store::library::seed_new_classes(&store).await.context("adding new seed classes and parameters to the motor library")?;
        crate::store::library::seed_new_instances(&store).await.context("adding new seed instances to the motor library")?;
        let blobs = Blobs::open(&settings.blobs, &settings.data_dir).await.context("opening the file store")?;
        tracing::info!(blobs = %blobs.location(), "file store open");
        let fd_limit = crate::api::serve::raise_fd_limit();
        let listener = TcpListener::bind(settings.bind).await.with_context(|| format!("binding {}", settings.bind))?;
        let relay = crate::relay::Relay::start(settings.live_bind, settings.requires_auth(), store.clone(), blobs.clone()).await;
        let live = relay.addr().map(|a| (settings.live_host(), a.port()));
        let jobs = start_jobs(store.clone(), blobs.clone(), &settings, live).await.context("starting the conversion workers")?;
        let addr = listener.local_addr().unwrap_or(settings.bind);
        let mut settings = settings;
        let cap = crate::api::serve::connection_cap(settings.max_connections, fd_limit);
        if cap < settings.max_connections {
            tracing::warn!(wanted = settings.max_connections, cap, fd_limit, "--max-connections lowered to fit under the open-file limit");
        }
        settings.max_connections = cap;
        tracing::info!(max_connections = cap, fd_limit, "connection limit");
        let checks = Arc::new(tokio::sync::Semaphore::new(settings.max_checks.max(1)));
        let simulations = Arc::new(tokio::sync::Semaphore::new(settings.workers.max(1)));
        let state = AppState {
            settings: Arc::new(settings),
            store,
            blobs,
            jobs,
            checks,
            simulations,
            addr,
            kinematics: Default::default(),
            relay,
            collisions: Default::default(),
        };
        Ok(App { listener, state })
    }

    pub fn local_addr(&self) -> SocketAddr {
        self.state.addr
    }

    pub fn state(&self) -> &AppState {
        &self.state
    }

    /// Serves until Ctrl-C or SIGTERM (or the task is dropped); see [`App::run_until`].
    pub async fn run_until_stopped(self) -> anyhow::Result<()> {
        self.run_until(stop_signal()).await
    }

    /// Serves until `shutdown` resolves, then stops the workers gracefully: the jobs running
    /// here go back to the queue, not charged as aborts ([`crate::jobs::Jobs::stop`]), and the
    /// next start redoes them. Dropping the task instead is a kill: nothing is released.
    pub async fn run_until(self, shutdown: impl std::future::Future<Output = ()>) -> anyhow::Result<()> {
        let router = crate::api::router(self.state.clone()).layer(tower_http::trace::TraceLayer::new_for_http());
        let s = &self.state.settings;
        let limits = crate::api::serve::Limits {
            max_connections: s.max_connections,
            header_timeout: s.header_timeout,
            body_timeout: s.body_timeout,
            keep_alive: s.keep_alive_timeout,
        };
        let served = crate::api::serve::serve(self.listener, router, limits, shutdown).await.context("serving");
        self.state.jobs.stop().await;
        served
    }
}

/// Resolves at Ctrl-C (SIGINT) or, on Unix, SIGTERM (what service managers and containers send).
async fn stop_signal() {
    #[cfg(unix)]
    {
        let term = tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate());
        match term {
            Ok(mut term) => {
                tokio::select! {
                    _ = tokio::signal::ctrl_c() => tracing::info!("Ctrl-C: stopping"),
                    _ = term.recv() => tracing::info!("SIGTERM: stopping"),
                }
            }
            Err(e) => {
                tracing::warn!(error = %e, "cannot listen for SIGTERM; Ctrl-C only");
                let _ = tokio::signal::ctrl_c().await;
            }
        }
    }
    #[cfg(not(unix))]
    {
        let _ = tokio::signal::ctrl_c().await;
    }
}
