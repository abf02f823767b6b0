//! Background conversion jobs: a bounded worker pool over the `jobs` table.
//!
//! The table is the queue. Uploads insert a `queued` job (with its version, in one transaction)
//! and [`Jobs::notify`] the dispatcher. The dispatcher task holds a semaphore of
//! `settings.workers` permits: with a permit in hand it claims the oldest queued job
//! (`store::models::claim_next_job`: job and version -> `running`, `started_at`) and runs it on
//! tokio's blocking pool, so at most `workers` conversions run at once and none on the async
//! runtime. A run reads the bundle blob, builds the package ([`crate::service::export::build_package`]),
//! stores package and report with [`Blobs::put`] (atomic) and only then points the version at
//! them (`succeeded`, `finished_at`); any error is stored as a problem document on the job and
//! the version (`failed`).
//!
//! Restart: [`Jobs::start`] (called by `App::build`) first re-queues the jobs a stopped server
//! left `running` (`store::models::requeue_unfinished`), then runs them.
//!
//! Poison jobs (crash accounting, issue 26): a start finds the jobs a stopped instance left
//! `running` (`store::models::requeue_unfinished`). The only job running there is charged the
//! stop (`jobs.aborts`); jobs that were running together are charged nothing but marked
//! `isolate`, and the dispatcher then runs one job at a time (waiting for the others to end)
//! until no such job is queued, so a crash during such a run is charged to the one job running.
//! A job charged [`MAX_ABORTS`] times is quarantined: failed with `/problems/conversion-aborted`
//! without running again (listed by `GET /api/jobs`), instead of taking the service down at
//! every start; a bystander is re-run, not blamed. Every claim also counts an attempt
//! (`jobs.attempts`) and more than [`MAX_ATTEMPTS`] fail a job whatever the cause (a backstop for
//! leases taken over on PostgreSQL, which do not pass through a start). Conversion
//! is deterministic and idempotent and blobs are content-addressed, so redoing a half-done job is
//! harmless; a crash between the blob writes and the database update leaves at worst an
//! unreferenced blob.
//!
//! Several instances (PostgreSQL): each claim holds a lease (`jobs.lease_owner`,
//! `jobs.lease_until`) that [`keep_while`] renews every third of the lease while the job runs. A
//! job whose instance died is claimable again once its lease has passed (an attempt more), and
//! the result of an instance that lost its lease is discarded (`finish_*` are conditional on the
//! lease). A start re-queues only jobs no live instance holds (see
//! `store::models::requeue_unfinished`).
//!
//! Memory (issue 26): each job's peak memory is estimated from its version's size, stored at
//! upload (`versions.triangles`, `versions.bundle_bytes`; [`cad2mo_engine::pipeline::peak_memory_estimate`]),
//! and a [`MemoryBudget`] (`--job-memory`) holds the estimates of the running jobs: the dispatcher
//! claims the next job only once its estimate fits beside theirs, so the workers together stay
//! within the budget; a job estimated over the whole budget (or of unknown size: versions stored
//! before migration 0016) takes all of it and runs alone. The budget is fair (first come, first
//! served): a large job waiting for room is not overtaken by small ones behind it.
//!
//! Progress: a running job's latest step (conversion stage, `done` of `total`, an overall
//! fraction) is kept in memory on a [`ProgressBoard`] shared with the API, which shows it on
//! `GET /api/jobs/{id}`, and written to `jobs.progress_json` at most every [`PROGRESS_EVERY`]
//! when it changed, so that the other instances show it too.
//!
//! Shutdown: the dispatcher stops when the last [`Jobs`] handle is dropped (the app's state);
//! queued jobs wait in the table for the next start. [`Jobs::halt`] stops it at once, like a
//! kill: running jobs are abandoned (still `running` in the table, re-queued by the next start)
//! and none of them records anything afterwards. On Ctrl-C or SIGTERM the server stops
//! gracefully ([`Jobs::stop`]): it halts, then puts the jobs it was running back in the queue
//! without charging them an abort (a stop asked for is no crash). Tests halt the server they
//! stop (like a kill), so that its jobs cannot finish behind the back of the next one.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use serde::Serialize;

use tokio::sync::{mpsc, watch, OwnedSemaphorePermit, Semaphore};
use tokio::task::{JoinHandle, JoinSet};
use tracing::Instrument;

use crate::service::export::{self, BuildStage, BuildStep, ExportOptions};
use crate::store::blobs::Blobs;
use crate::store::models::{self, ClaimedJob, Claimer, JobOutputs};
use crate::store::{Engine, Store, StoreError};
use cad2mo_engine::collision::{CacheStats, MemoryShapeCache};
use cad2mo_engine::pipeline::observe::Stage;

/// Stops of the service while a job was the only one running before it is quarantined (see the
/// module doc): failed with `/problems/conversion-aborted` without running again.
pub const MAX_ABORTS: i64 = 2;

/// Claims of one job before it is given up whatever the reason (a backstop: leases taken over
/// on PostgreSQL, stops beside other jobs): a job claimed for the `MAX_ATTEMPTS + 1`-th time
/// fails without running.
pub const MAX_ATTEMPTS: i64 = 10;

/// How often a running job's progress is written to the database at most (4 a second), so that
/// every instance can show it.
const PROGRESS_EVERY: Duration = Duration::from_millis(250);

/// The default `--job-memory`: 1.2 GB for the conversions running at once, so the service
/// (about 200 MB besides them) stays under 1.5 GB.
pub const DEFAULT_JOB_MEMORY: u64 = 1_200_000_000;

/// The worker pool's size: conversions at once, and the memory their estimates may add up to.
#[derive(Clone, Copy, Debug)]
pub struct Workers {
    pub count: usize,
    /// Bytes (`--job-memory`).
    pub memory: u64,
}

/// Memory for the running conversions, in whole megabytes (10^6 bytes), handed out first come,
/// first served (a tokio semaphore is fair): a job holds its estimate's share while it runs.
#[derive(Clone, Debug)]
pub struct MemoryBudget {
    permits: Arc<Semaphore>,
    total: u32,
}

impl MemoryBudget {
    /// A budget of `bytes` (at least 1 MB).
    pub fn new(bytes: u64) -> MemoryBudget {
        let total = u32::try_from(bytes.div_ceil(1_000_000)).unwrap_or(u32::MAX).clamp(1, Semaphore::MAX_PERMITS as u32);
        MemoryBudget { permits: Arc::new(Semaphore::new(total as usize)), total }
    }

    /// The megabytes a job with this estimate holds: its estimate rounded up, at least 1, at most
    /// the whole budget (a job over it runs alone); the whole budget when the size is unknown.
    pub fn share(&self, estimate: Option<u64>) -> u32 {
        estimate.map_or(self.total, |b| u32::try_from(b.div_ceil(1_000_000)).unwrap_or(u32::MAX).clamp(1, self.total))
    }

    /// Waits until `share` megabytes are free (after every earlier request), and holds them
    /// until the permit is dropped. (`None` only were the semaphore closed, which it never is.)
    pub async fn admit(&self, share: u32) -> Option<OwnedSemaphorePermit> {
        self.permits.clone().acquire_many_owned(share.clamp(1, self.total)).await.ok()
    }

    /// Megabytes not held by running jobs.
    pub fn free(&self) -> usize {
        self.permits.available_permits()
    }
}

/// A job's estimated peak memory from its version's size (`None`: unknown).
fn estimate(triangles: Option<i64>, bundle_bytes: Option<i64>) -> Option<u64> {
    let (t, b) = (u64::try_from(triangles?).ok()?, u64::try_from(bundle_bytes?).ok()?);
    Some(cad2mo_engine::pipeline::peak_memory_estimate(t, b))
}

/// Why a job failed. Stored with the job as the document `describe` (given to [`Jobs::start`] by
/// the app: the API's problem+json) makes of it.
#[derive(Debug, thiserror::Error)]
pub enum JobError {
    #[error("{0} not found")]
    NotFound(String),
    /// The job was running each time the service stopped (see the module doc).
    #[error(
        "the conversion stopped the service {times} times (it was running alone at each stop); \
         it is not tried again: check the bundle (size, meshes) or upload a new version"
    )]
    Aborted { times: i64 },
    /// The bundle does not read or convert (the user's input).
    #[error(transparent)]
    Export(#[from] export::ExportError),
    /// The model's drives no longer resolve against the library.
    #[error(transparent)]
    Drive(#[from] crate::service::drives::DriveError),
    #[error(transparent)]
    Store(#[from] StoreError),
    /// Not the input's fault (blobs, a panic in the conversion, corrupt stored options).
    #[error("internal error")]
    Internal(#[from] anyhow::Error),
}

/// What a failed job stores: the document the API shows for it.
pub type DescribeFailure = fn(JobError) -> serde_json::Value;

/// A handle on the worker pool (cheap to clone): wakes the dispatcher.
#[derive(Clone, Debug)]
pub struct Jobs {
    wake: mpsc::Sender<()>,
    board: ProgressBoard,
    halt: Arc<Halt>,
    shapes: Arc<MemoryShapeCache>,
    /// STEP tessellations by file content, shared by the upload checks and every job.
    steps: Arc<cad2mo_engine::pipeline::front::mesh::step::MemoryStepCache>,
    /// For [`Jobs::stop`]: the store and this instance's claims.
    store: Store,
    instance: String,
}

/// Stops the dispatcher: the signal, and the dispatcher's task to wait for.
#[derive(Debug)]
struct Halt {
    signal: watch::Sender<bool>,
    dispatcher: Mutex<Option<JoinHandle<()>>>,
}

#[derive(Clone)]
struct Ctx {
    store: Store,
    blobs: Blobs,
    board: ProgressBoard,
    /// Where packages' live views send to (host, UDP port), when the service receives them.
    live: Option<(String, u16)>,
    /// This instance's claims: its id and the lease time.
    claimer: Claimer,
    /// Collision shapes by mesh content, shared by every job of the process.
    shapes: Arc<MemoryShapeCache>,
    /// STEP parts' tessellations by file content, shared by every job of the process.
    steps: Arc<cad2mo_engine::pipeline::front::mesh::step::MemoryStepCache>,
    /// A failure's stored document.
    describe: DescribeFailure,
}

/// Where a running job is.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct JobProgress {
    /// `xml`, `meshes`, `vrml`, `analysis`, `modelica`, `collision`, `shapes`, `report`, `package` (zipping)
    /// or `storing`, in that order; a job may skip some.
    pub stage: &'static str,
    /// The stage for people, e.g. "Writing shapes".
    pub label: &'static str,
    /// Units of the stage done (bodies, files) of `total`.
    pub done: usize,
    pub total: usize,
    /// An estimate of the whole job done, 0..1, never decreasing: stages weighted by their usual
    /// share of the time (meshes and shapes dominate large models).
    pub fraction: f64,
}

/// The stages of a job in order: the conversion's ([`Stage::ALL`], row `Stage::X as usize`),
/// then zipping and storing; with their weights in the overall fraction (they add up to 100).
const STAGES: [(&str, &str, f64); 10] = [
    ("xml", "Reading the XML", 5.0),
    ("meshes", "Reading STL meshes", 20.0),
    ("vrml", "Reading and matching VRML", 20.0),
    ("analysis", "Analysing joints and loops", 4.0),
    ("modelica", "Writing Modelica", 4.0),
    ("collision", "Making collision shapes", 10.0),
    ("shapes", "Writing shapes", 20.0),
    ("report", "Writing the report", 2.0),
    ("package", "Zipping the package", 12.0),
    ("storing", "Storing the package", 3.0),
];
const PACKAGE: usize = Stage::ALL.len();
const STORING: usize = PACKAGE + 1;

impl JobProgress {
    /// The progress of a job at `step`.
    pub fn at(step: BuildStep) -> JobProgress {
        let index = match step.stage {
            BuildStage::Convert(s) => s as usize,
            BuildStage::Package => PACKAGE,
        };
        Self::of(index, step.done, step.total)
    }

    fn of(index: usize, done: usize, total: usize) -> JobProgress {
        let (stage, label, weight) = STAGES[index.min(STAGES.len() - 1)];
        let before: f64 = STAGES[..index].iter().map(|s| s.2).sum();
        let within = if total == 0 { 0.0 } else { (done.min(total) as f64) / total as f64 };
        JobProgress { stage, label, done, total, fraction: ((before + weight * within) / 100.0).clamp(0.0, 1.0) }
    }

    fn storing() -> JobProgress {
        Self::of(STORING, 0, 1)
    }

    /// The progress as stored in the database (`jobs.progress_json`), for other instances.
    fn to_json(&self) -> String {
        serde_json::json!({"stage": self.stage, "done": self.done, "total": self.total, "fraction": self.fraction}).to_string()
    }

    /// Progress stored by [`JobProgress::to_json`] (by this or another instance); `None` when it is
    /// not one (an unknown stage).
    pub fn from_json(json: &str) -> Option<JobProgress> {
        let v: serde_json::Value = serde_json::from_str(json).ok()?;
        let (stage, label, _) = *STAGES.iter().find(|s| Some(s.0) == v["stage"].as_str())?;
        let done = usize::try_from(v["done"].as_u64()?).ok()?;
        let total = usize::try_from(v["total"].as_u64()?).ok()?;
        Some(JobProgress { stage, label, done, total, fraction: v["fraction"].as_f64()?.clamp(0.0, 1.0) })
    }
}

/// The latest progress of every running job (cheap to clone; shared by workers and the API).
#[derive(Clone, Default, Debug)]
pub struct ProgressBoard(Arc<Mutex<HashMap<String, JobProgress>>>);

impl ProgressBoard {
    /// The map; a panic elsewhere while it was locked leaves plain data, still usable.
    fn map(&self) -> std::sync::MutexGuard<'_, HashMap<String, JobProgress>> {
        self.0.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
    }

    fn set(&self, job: &str, p: JobProgress) {
        self.map().insert(job.to_string(), p);
    }

    fn clear(&self, job: &str) {
        self.map().remove(job);
    }

    fn get(&self, job: &str) -> Option<JobProgress> {
        self.map().get(job).cloned()
    }
}

impl Jobs {
    /// Re-queues unfinished jobs, then starts the dispatcher with `workers.count` workers (at
    /// least one) whose jobs' memory estimates add up to at most `workers.memory` (see the module doc).
    /// Packages get a live view sending to `live` (host, UDP port) when it is given.
    /// Must be called inside a tokio runtime.
    /// A claim holds for `lease` and is renewed every third of it while the job runs.
    pub async fn start(
        store: Store,
        blobs: Blobs,
        workers: Workers,
        live: Option<(String, u16)>,
        lease: Duration,
        shape_cache_bytes: usize,
        describe: DescribeFailure,
    ) -> Result<Jobs, StoreError> {
        let requeued = models::requeue_unfinished(&store.pool).await?;
        if requeued > 0 {
            tracing::warn!(requeued, "jobs interrupted by a stop were re-queued");
        }
        let (wake, rx) = mpsc::channel(1);
        let board = ProgressBoard::default();
        let instance = uuid::Uuid::new_v4().simple().to_string();
        tracing::info!(instance = %instance, lease_secs = lease.as_secs_f64(), "job queue instance");
        let claimer = Claimer { instance: instance.clone(), lease_secs: lease.as_secs_f64().max(0.1) };
        let shapes = Arc::new(MemoryShapeCache::new(shape_cache_bytes));
        let steps = Arc::new(cad2mo_engine::pipeline::front::mesh::step::MemoryStepCache::default());
        let ctx = Ctx {
            store: store.clone(),
            blobs,
            board: board.clone(),
            live,
            claimer,
            shapes: shapes.clone(),
            steps: steps.clone(),
            describe,
        };
        let (signal, halted) = watch::channel(false);
        let budget = MemoryBudget::new(workers.memory);
        let dispatcher = tokio::spawn(dispatch(ctx, workers.count.max(1), budget, rx, halted).instrument(tracing::info_span!("jobs")));
        let halt = Arc::new(Halt { signal, dispatcher: Mutex::new(Some(dispatcher)) });
        let jobs = Jobs { wake, board, halt, shapes, steps, store, instance };
        jobs.notify(); // pick up what is already queued
        Ok(jobs)
    }

    /// The counters of the process's collision shape cache: shapes served to jobs from it
    /// (`hits`) and computed by them (`misses`).
    pub fn shape_cache_stats(&self) -> CacheStats {
        self.shapes.stats()
    }

    /// The process's STEP tessellations by file content: the upload check puts the parts it
    /// meshes there, so the job converting the upload meshes them no more.
    pub fn step_cache(&self) -> Arc<dyn cad2mo_engine::pipeline::front::mesh::step::StepCache> {
        self.steps.clone()
    }

    /// Tells the dispatcher that jobs may be queued (call after committing one).
    pub fn notify(&self) {
        // A full channel means a wake-up is already pending: nothing is lost.
        let _ = self.wake.try_send(());
    }

    /// The latest progress of a running job (`None` when it is not running here).
    pub fn progress(&self, job_id: &str) -> Option<JobProgress> {
        self.board.get(job_id)
    }

    /// A graceful stop (Ctrl-C, SIGTERM): [`Jobs::halt`], then the jobs this instance was running
    /// go back to the queue uncharged (`store::models::release_claims`), so the next start runs
    /// them again without counting the stop as their abort. A kill skips this, and is charged.
    pub async fn stop(&self) {
        self.halt().await;
        match models::release_claims(&self.store.pool, &self.instance).await {
            Ok(0) => {}
            Ok(released) => tracing::info!(released, "jobs running at the stop were put back in the queue (not counted as aborts)"),
            Err(e) => {
                tracing::warn!(error = %e, "could not put the running jobs back in the queue: the next start counts the stop against them")
            }
        }
    }

    /// Stops claiming and abandons the running jobs (see the module doc); returns once no job
    /// of this pool can touch the database any more. Later calls return at once.
    pub async fn halt(&self) {
        let _ = self.halt.signal.send(true);
        let dispatcher = self.halt.dispatcher.lock().unwrap_or_else(|p| p.into_inner()).take();
        if let Some(d) = dispatcher {
            let _ = d.await;
        }
    }
}

/// Claims queued jobs while permits are free; sleeps until notified when nothing is queued.
/// Running jobs live in a [`JoinSet`] so that a halt can abandon them.
async fn dispatch(ctx: Ctx, workers: usize, budget: MemoryBudget, mut wake: mpsc::Receiver<()>, mut halted: watch::Receiver<bool>) {
    let permits = Arc::new(Semaphore::new(workers));
    let mut running = JoinSet::new();
    tracing::info!(workers, memory_mb = budget.total, "job workers started");
    loop {
        while running.try_join_next().is_some() {}
        let permit = tokio::select! {
            p = permits.clone().acquire_owned() => match p { Ok(p) => p, Err(_) => break },
            () = halt_requested(&mut halted) => break,
        };
        if halted_now(&halted) {
            break;
        }
        // Crash accounting: while a job waits to be run alone, jobs run one at a time.
        let alone = models::isolation_pending(&ctx.store.pool).await.unwrap_or(false);
        if alone {
            while !running.is_empty() {
                tokio::select! {
                    _ = running.join_next() => {}
                    () = halt_requested(&mut halted) => break,
                }
            }
            if halted_now(&halted) {
                break;
            }
        }
        // Memory: the job the claim would take starts only once its estimate fits beside the
        // running jobs' (a read first: nothing is claimed while it waits, so the table shows it
        // queued and a stop meanwhile charges it nothing).
        let mut memory = None;
        if let Ok(Some((triangles, bytes))) = models::next_job_size(&ctx.store.pool).await {
            let share = budget.share(estimate(triangles, bytes));
            if (share as usize) > budget.free() {
                tracing::info!(share_mb = share, free_mb = budget.free(), "the next job waits for memory");
            }
            tokio::select! {
                m = budget.admit(share) => memory = m,
                () = halt_requested(&mut halted) => break,
            }
        }
        match models::claim_next_job(&ctx.store.pool, &ctx.claimer).await {
            Ok(Some(job)) => {
                let span =
                    tracing::info_span!("job", job_id = %job.id, kind = %job.kind, model_id = %job.model_id, version = job.version, alone);
                // Another job than the one read (queued or claimed elsewhere meanwhile): its own share.
                let share = budget.share(job.source.as_ref().and_then(|s| estimate(s.triangles, s.bundle_bytes)));
                if memory.as_ref().is_none_or(|m| m.num_permits() < share as usize) {
                    drop(memory.take());
                    tokio::select! {
                        m = budget.admit(share) => memory = m,
                        () = halt_requested(&mut halted) => break,
                    }
                }
                let ctx = ctx.clone();
                running.spawn(
                    async move {
                        run(&ctx, job).await;
                        drop(memory);
                        drop(permit);
                    }
                    .instrument(span),
                );
                if alone {
                    tokio::select! {
                        _ = running.join_next() => {}
                        () = halt_requested(&mut halted) => break,
                    }
                }
            }
            Ok(None) => {
                drop(memory);
                drop(permit);
                // Woken by a new job, or after a short while: a job held back behind an earlier
                // job of its model becomes claimable when that one finishes, and on PostgreSQL
                // other instances queue jobs (and may die, leaving leases to expire).
                let poll = match ctx.store.pool.engine() {
                    Engine::Sqlite => Duration::from_millis(100),
                    Engine::Postgres => Duration::from_millis(250),
                };
                tokio::select! {
                    w = wake.recv() => if w.is_none() {
                        tracing::info!("job workers stopped");
                        // The last handle is gone, but jobs already running finish.
                        while running.join_next().await.is_some() {}
                        return;
                    },
                    () = halt_requested(&mut halted) => break,
                    () = tokio::time::sleep(poll) => {}
                }
            }
            Err(e) => {
                drop(memory);
                drop(permit);
                tracing::error!(error = %e, "claiming a job failed; retrying");
                tokio::select! {
                    () = tokio::time::sleep(Duration::from_secs(1)) => {}
                    w = wake.recv() => if w.is_none() {
                        while running.join_next().await.is_some() {}
                        return;
                    },
                    () = halt_requested(&mut halted) => break,
                }
            }
        }
    }
    let abandoned = running.len();
    running.shutdown().await;
    tracing::info!(abandoned, "job workers halted");
}

/// Resolves once a halt is requested (never when the sender is gone without one).
async fn halt_requested(halted: &mut watch::Receiver<bool>) {
    loop {
        if halted_now(halted) {
            return;
        }
        if halted.changed().await.is_err() {
            std::future::pending::<()>().await;
        }
    }
}

fn halted_now(halted: &watch::Receiver<bool>) -> bool {
    *halted.borrow()
}

/// Runs one claimed job to `succeeded` or `failed`.
async fn run(ctx: &Ctx, job: ClaimedJob) {
    tracing::info!("job running");
    let started = std::time::Instant::now();
    ctx.board.set(&job.id, JobProgress::of(0, 0, 1));
    let result = if job.aborts >= MAX_ABORTS {
        tracing::error!(aborts = job.aborts, "the job stopped the service while running alone: quarantined (failed)");
        Err(JobError::Aborted { times: job.aborts })
    } else if job.attempts > MAX_ATTEMPTS {
        tracing::error!(attempts = job.attempts, "the job was claimed too often (stops, lost leases): marked failed");
        Err(JobError::Aborted { times: job.attempts - 1 })
    } else {
        keep_while(ctx, &job, convert(ctx, &job)).await
    };
    let ms = started.elapsed().as_millis() as u64;
    let result = result.map_err(|e| (ctx.describe)(e).to_string());
    for attempt in 1..=3 {
        let recorded = match &result {
            Ok(out) => {
                let outputs =
                    JobOutputs { package_sha256: &out.package_sha256, report_sha256: &out.report_sha256, summary_json: &out.summary_json };
                models::finish_succeeded(&ctx.store.pool, &job, &outputs).await
            }
            Err(e) => models::finish_failed(&ctx.store.pool, &job, e).await,
        };
        match recorded {
            Ok(false) => {
                ctx.board.clear(&job.id);
                tracing::warn!(ms, "the job's lease was lost (another instance took it over): its result is discarded");
                return;
            }
            Ok(true) => {
                ctx.board.clear(&job.id);
                match &result {
                    Ok(_) => tracing::info!(ms, "job succeeded"),
                    Err(e) => tracing::warn!(ms, error = %e, "job failed"),
                }
                return;
            }
            Err(e) => {
                tracing::error!(attempt, error = %e, "recording the job's result failed");
                tokio::time::sleep(Duration::from_millis(500 * attempt)).await;
            }
        }
    }
    // Still `running` in the table: the next start re-queues it.
    ctx.board.clear(&job.id);
}

/// Runs `work` while keeping the job's claim alive: every [`PROGRESS_EVERY`] the latest progress
/// (when it changed) is written for other instances, and every third of the lease the lease is
/// renewed. A lost lease is logged; the work still ends, but its result will not be recorded.
async fn keep_while<T>(ctx: &Ctx, job: &ClaimedJob, work: impl std::future::Future<Output = T>) -> T {
    tokio::pin!(work);
    let renew_every = Duration::from_secs_f64(ctx.claimer.lease_secs / 3.0);
    let mut tick = tokio::time::interval(PROGRESS_EVERY.min(renew_every));
    tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
    let mut renewed = tokio::time::Instant::now();
    let mut written: Option<JobProgress> = None;
    let mut lost = false;
    loop {
        tokio::select! {
            out = &mut work => return out,
            _ = tick.tick() => {}
        }
        if lost {
            continue;
        }
        let held = if renewed.elapsed() >= renew_every {
            renewed = tokio::time::Instant::now();
            models::renew_lease(&ctx.store.pool, job, ctx.claimer.lease_secs).await
        } else {
            match ctx.board.get(&job.id).filter(|p| written.as_ref() != Some(p)) {
                Some(p) => {
                    let r = models::set_progress(&ctx.store.pool, job, &p.to_json()).await;
                    written = Some(p);
                    r
                }
                None => Ok(true),
            }
        };
        match held {
            Ok(true) => {}
            Ok(false) => {
                lost = true;
                tracing::warn!("the job's lease was lost: another instance may have taken it over");
            }
            Err(e) => tracing::warn!(error = %e, "renewing the job's lease or recording its progress failed"),
        }
    }
}

/// The Modelica names of the model's latest converted version before this one (re-exports of a
/// version keep their own earlier names too), so CAD renames keep their Modelica names.
async fn previous_names(ctx: &Ctx, job: &ClaimedJob) -> Result<cad2mo_engine::pipeline::back::modelica::Hints, JobError> {
    let versions = models::list_versions(&ctx.store.pool, &job.model_id).await?;
    let earlier = versions
        .iter()
        .filter(|v| v.version < job.version || (v.version == job.version && job.kind == "reexport"))
        .filter(|v| v.report_sha256.is_some())
        .max_by_key(|v| v.version);
    let Some(hash) = earlier.and_then(|v| v.report_sha256.clone()) else { return Ok(Default::default()) };
    let blobs = ctx.blobs.clone();
    let bytes = tokio::task::spawn_blocking(move || blobs.get(&hash))
        .await
        .map_err(|e| JobError::Internal(e.into()))?
        .map_err(|e| JobError::Internal(e.into()))?;
    let report: serde_json::Value = bytes.and_then(|b| serde_json::from_slice(&b).ok()).unwrap_or_default();
    Ok(cad2mo_engine::pipeline::name_hints(&report))
}

struct Stored {
    package_sha256: String,
    report_sha256: String,
    summary_json: String,
}

/// The conversion itself, off the runtime: bundle blob -> package and report blobs.
async fn convert(ctx: &Ctx, job: &ClaimedJob) -> Result<Stored, JobError> {
    let Some(source) = job.source.clone() else {
        return Err(JobError::NotFound(format!("version {} of model {}", job.version, job.model_id)));
    };
    let drives = crate::service::drives::resolve_for_model(&ctx.store, &job.model_id).await?;
    let specs: Vec<_> = crate::store::motions::list(&ctx.store, &job.model_id).await?.into_iter().map(|m| m.spec).collect();
    // Limits, drives and the library matter only for motions (their tables and sizing files).
    let motions = if specs.is_empty() {
        export::MotionsInput::default()
    } else {
        export::MotionsInput {
            specs,
            limits: crate::store::motions::limits(&ctx.store, &job.model_id).await?,
            version: job.version,
            drives: crate::service::motions::drive_parts(&ctx.store, &job.model_id).await?,
            catalog: cad2mo_engine::sizing::Catalog::from_library(&crate::store::library::export(&ctx.store).await?),
        }
    };
    let hints = previous_names(ctx, job).await?;
    let live = match (&ctx.live, u32::try_from(job.version)) {
        (Some((host, port)), Ok(version)) => Some(cad2mo_engine::pipeline::back::modelica::mechatronics::live::LiveTarget {
            model_id: job.model_id.clone(),
            version,
            host: host.clone(),
            port: *port,
        }),
        _ => None,
    };
    let collision_edits =
        crate::store::collision::edits(&ctx.store, &job.model_id).await?.into_iter().map(|(a, b, x)| ((a, b), x)).collect();
    let shape_cache: Arc<dyn cad2mo_engine::collision::ShapeCache> = ctx.shapes.clone();
    let step_cache: Arc<dyn cad2mo_engine::pipeline::front::mesh::step::StepCache> = ctx.steps.clone();
    let scene = crate::store::scene::get(&ctx.store, &job.model_id).await?;
    let mesh_rows: Vec<(String, String)> =
        crate::store::scene::meshes(&ctx.store, &job.model_id).await?.into_iter().map(|r| (r.name, r.blob_sha256)).collect();
    let scene_meshes = {
        let blobs = ctx.blobs.clone();
        tokio::task::spawn_blocking(move || crate::service::scene::load_meshes(&mesh_rows, |h| blobs.get(h)))
            .await
            .map_err(|e| JobError::Internal(e.into()))?
            .map_err(JobError::Internal)?
    };
    let context = export::Context {
        name_hints: hints,
        live,
        collision_edits,
        shape_cache: Some(shape_cache),
        step_cache: Some(step_cache),
        scene,
        scene_meshes,
    };
    let blobs = ctx.blobs.clone();
    let board = ctx.board.clone();
    let job_id = job.id.clone();
    let span = tracing::Span::current();
    let task = tokio::task::spawn_blocking(move || {
        span.in_scope(|| {
            let options: ExportOptions = serde_json::from_str(&source.options_json)
                .map_err(|e| JobError::Internal(anyhow::anyhow!("stored options are corrupt: {e}")))?;
            let bundle = blobs
                .get(&source.bundle_sha256)
                .map_err(|e| JobError::Internal(e.into()))?
                .ok_or_else(|| JobError::Internal(anyhow::anyhow!("bundle blob {} is missing", source.bundle_sha256)))?;
            let mut last = 0.0;
            let built = export::build_package(&bundle, &source.bundle_name, &options, &drives, &motions, &context, &mut |step| {
                let p = JobProgress::at(step);
                // Never backwards, and not every one of 10,000 bodies: a new stage or 1 % more.
                if p.fraction >= last + 0.01 || (p.done == 0 && p.fraction >= last) {
                    last = p.fraction.max(last);
                    board.set(&job_id, p);
                }
            })?;
            tracing::info!(computed = built.shapes.computed, cached = built.shapes.cached, "collision shapes");
            board.set(&job_id, JobProgress::storing());
            let summary_json = serde_json::to_string(&built.summary).map_err(|e| JobError::Internal(e.into()))?;
            // Blobs first: the database points at them only once they are complete on disk.
            let package_sha256 = blobs.put(&built.package_zip).map_err(|e| JobError::Internal(e.into()))?;
            let report_sha256 = blobs.put(&built.report_json).map_err(|e| JobError::Internal(e.into()))?;
            Ok(Stored { package_sha256, report_sha256, summary_json })
        })
    });
    task.await.map_err(|e| JobError::Internal(anyhow::anyhow!("the conversion panicked: {e}")))?
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Shares: the estimate in whole MB, at least 1, at most the budget; unknown sizes take it
    /// all. Two jobs over half the budget never hold it at once; small ones do, beside a large one.
    #[tokio::test]
    async fn memory_budget_admits_what_fits() {
        let budget = MemoryBudget::new(1_000_000_000);
        assert_eq!((budget.share(Some(600_000_001)), budget.share(Some(0)), budget.share(Some(5_000_000_000))), (601, 1, 1000));
        assert_eq!(budget.share(None), 1000, "unknown size: the whole budget");
        let soon = Duration::from_millis(50);
        let large = budget.admit(600).await.expect("admitted");
        assert!(tokio::time::timeout(soon, budget.admit(600)).await.is_err(), "a second large job waits");
        let small = [budget.admit(200).await.expect("a"), budget.admit(200).await.expect("b")];
        assert_eq!(budget.free(), 0);
        drop(large);
        let second = tokio::time::timeout(soon, budget.admit(600)).await.expect("admitted once the first ended").expect("permit");
        drop((second, small));
        assert_eq!(budget.free(), 1000);
        // First come, first served: a small request behind a waiting large one waits too.
        let held = budget.admit(500).await.expect("held");
        let waiting = tokio::spawn({
            let b = budget.clone();
            async move { b.admit(600).await.map(|p| p.num_permits()) }
        });
        tokio::time::sleep(Duration::from_millis(20)).await;
        assert!(tokio::time::timeout(soon, budget.admit(100)).await.is_err(), "not overtaken");
        drop(held);
        assert_eq!(waiting.await.expect("joined"), Some(600));
    }

    /// The dispatcher's admission (two workers, a 1 GB budget): two jobs estimated at 690 MB run
    /// one after the other, and a 150 MB job runs beside the second.
    #[tokio::test(flavor = "multi_thread", worker_threads = 2)]
    async fn large_jobs_run_apart_and_small_ones_beside_them() {
        let dir = tempfile::tempdir().expect("tempdir");
        let store = Store::open(&format!("sqlite://{}?mode=rwc", dir.path().join("t.db").display())).await.expect("store");
        let blobs = Blobs::new(dir.path()).expect("blobs");
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/in/pendulum");
        let files: Vec<(String, Vec<u8>)> = ["PENDULUM.xml", "meshes/LINK_prt.stl"]
            .iter()
            .map(|f| (f.to_string(), std::fs::read(root.join(f)).expect("pendulum")))
            .collect();
        let zip = cad2mo_engine::pipeline::back::bundle::write_zip(&files).expect("zip");
        let sha = blobs.put(&zip).expect("put");
        // 150 MB + 60 B × 9 M triangles = 690 MB; 150 MB + 60 B × 1,000 = 150.06 MB.
        let mut ids = Vec::new();
        for (name, triangles) in [("large1", 9_000_000), ("large2", 9_000_000), ("small1", 1_000), ("small2", 1_000)] {
            let v = models::NewVersion {
                bundle_name: "p.zip",
                bundle_sha256: &sha,
                bundle_size: zip.len() as i64,
                options_json: "{}",
                triangles: Some(triangles),
                bundle_bytes: Some(0),
            };
            ids.push(models::create_model(&store.pool, name, &v).await.expect("queued").job_id);
        }
        let workers = Workers { count: 2, memory: 1_000_000_000 };
        let describe: DescribeFailure = |e| serde_json::json!({ "detail": e.to_string() });
        let jobs = Jobs::start(store.clone(), blobs, workers, None, Duration::from_secs(30), 0, describe).await.expect("start");
        let deadline = std::time::Instant::now() + Duration::from_secs(120);
        let rows = loop {
            let mut rows = Vec::new();
            for id in &ids {
                rows.push(models::get_job(&store.pool, id).await.expect("read").expect("job"));
            }
            if rows.iter().all(|r| r.status == "succeeded" || r.status == "failed") {
                break rows;
            }
            assert!(std::time::Instant::now() < deadline, "jobs still running: {rows:?}");
            tokio::time::sleep(Duration::from_millis(50)).await;
        };
        jobs.halt().await;
        assert!(rows.iter().all(|r| r.status == "succeeded"), "{rows:?}");
        let span = |i: usize| (rows[i].started_at.clone().expect("started"), rows[i].finished_at.clone().expect("finished"));
        let (l1, l2, s1) = (span(0), span(1), span(2));
        assert!(l2.0 >= l1.1, "the large jobs overlapped: {l1:?} {l2:?}");
        assert!(s1.0 < l2.1 && l2.0 < s1.1, "the small job did not run beside the second large one: {l2:?} {s1:?}");
    }

    #[test]
    fn stage_table_follows_the_pipeline_stages() {
        for s in Stage::ALL {
            assert_eq!(STAGES[s as usize].0, format!("{s:?}").to_lowercase(), "row of {s:?}");
        }
        assert_eq!((STAGES[PACKAGE].0, STAGES[STORING].0), ("package", "storing"));
        assert_eq!(STAGES.iter().map(|s| s.2).sum::<f64>(), 100.0);
        // Each step's fraction is at least the one before, through every stage and within it.
        let mut steps: Vec<BuildStep> =
            Stage::ALL.iter().flat_map(|&s| (0..=3).map(move |done| BuildStep { stage: BuildStage::Convert(s), done, total: 3 })).collect();
        steps.extend((0..=2).map(|done| BuildStep { stage: BuildStage::Package, done, total: 2 }));
        let mut fractions: Vec<f64> = steps.into_iter().map(|s| JobProgress::at(s).fraction).collect();
        fractions.push(JobProgress::storing().fraction);
        assert!(fractions.windows(2).all(|w| w[0] <= w[1]), "{fractions:?}");
        assert_eq!((fractions[0], JobProgress::storing().fraction), (0.0, 0.97));
    }
}
