//! SQL for models, their versions and the conversion jobs.
//!
//! A model is one CAD assembly; each upload of it is a version (numbered from 1, never reused:
//! `models.last_version`); each version is converted by a job. A version's `status` follows its
//! latest job's: `queued` -> `running` -> `succeeded` | `failed`. Files (bundle, package, report)
//! live in the blob store; rows refer to them by SHA-256 and are only written after the blob is.
//!
//! The jobs table is the queue: [`claim_next_job`] atomically moves the oldest `queued` job to
//! `running`, and [`requeue_unfinished`] (called on start-up) puts back every job a stopped server
//! left `queued` or `running`.

use sqlx::AnyConnection;
use sqlx::FromRow;

use super::{sql, Engine, Pool, StoreError};

/// The database's clock as RFC 3339 UTC with milliseconds (the format of [`super::now`]; expanded by [`sql`]).
const NOW: &str = "%NOW%";

/// The stored upload of a new version.
#[derive(Debug, Clone)]
pub struct NewVersion<'a> {
    pub bundle_name: &'a str,
    pub bundle_sha256: &'a str,
    pub bundle_size: i64,
    /// The conversion options, serialised.
    pub options_json: &'a str,
    /// What the conversion will hold (the upload's check finds it; `None` when unknown): the
    /// meshes' triangles after instancing and the bundle's inflated bytes (migration 0016).
    pub triangles: Option<i64>,
    pub bundle_bytes: Option<i64>,
}

/// What an upload created.
#[derive(Debug, Clone, PartialEq)]
pub struct Created {
    pub model_id: String,
    pub version: i64,
    pub job_id: String,
}

/// A model with its latest version (if any).
#[derive(Debug, Clone, FromRow)]
pub struct ModelRow {
    pub id: String,
    pub name: String,
    pub created_at: String,
    pub latest_version: Option<i64>,
    pub latest_status: Option<String>,
}

/// One version.
#[derive(Debug, Clone, FromRow)]
pub struct VersionRow {
    pub model_id: String,
    pub version: i64,
    pub created_at: String,
    pub bundle_name: String,
    pub bundle_sha256: String,
    pub bundle_size: i64,
    pub options_json: String,
    pub status: String,
    pub package_sha256: Option<String>,
    pub report_sha256: Option<String>,
    pub error_json: Option<String>,
    pub summary_json: Option<String>,
    /// The version's latest job.
    pub job_id: Option<String>,
}

/// One job.
#[derive(Debug, Clone, FromRow)]
pub struct JobRow {
    pub id: String,
    pub kind: String,
    pub model_id: String,
    pub version: i64,
    pub status: String,
    pub error_json: Option<String>,
    pub created_at: String,
    pub started_at: Option<String>,
    pub finished_at: Option<String>,
    /// The latest progress a worker recorded while the job runs (`crate::jobs::JobProgress` as JSON).
    pub progress_json: Option<String>,
    /// Claims of the job so far (see [`ClaimedJob::attempts`]).
    pub attempts: i64,
}

/// A job a worker took, with what it needs to run.
#[derive(Debug, Clone)]
pub struct ClaimedJob {
    pub id: String,
    pub kind: String,
    pub model_id: String,
    pub version: i64,
    /// How many times the job was claimed, this claim included (a job claimed again after a
    /// restart found it `running` has attempts > 1).
    pub attempts: i64,
    /// Stops of the service while this job was the only one running (see [`requeue_unfinished`]).
    pub aborts: i64,
    /// `None` when the version no longer exists (deleted meanwhile).
    pub source: Option<JobSource>,
    /// This claim's lease token (`<instance>:<claim>`): renewing the lease, recording progress
    /// and finishing the job all require that the job still holds it.
    pub lease_owner: String,
}

/// How a worker claims: who it is and how long its claim holds without a renewal.
#[derive(Debug, Clone)]
pub struct Claimer {
    /// The instance's id (random, new at every start).
    pub instance: String,
    /// Seconds a claim or a renewal holds ([`claim_next_job`], [`renew_lease`]).
    pub lease_secs: f64,
}

/// The stored input of a version.
#[derive(Debug, Clone, FromRow)]
pub struct JobSource {
    pub bundle_name: String,
    pub bundle_sha256: String,
    pub options_json: String,
    /// The version's triangles and inflated bundle bytes (NULL for versions stored before
    /// migration 0016): the job's memory estimate.
    pub triangles: Option<i64>,
    pub bundle_bytes: Option<i64>,
}

fn new_id() -> String {
    uuid::Uuid::new_v4().to_string()
}

/// Inserts the version row and its convert job (inside the caller's transaction).
async fn insert_version_and_job(tx: &mut AnyConnection, model_id: &str, version: i64, v: &NewVersion<'_>) -> Result<String, StoreError> {
    sqlx::query(&sql(
        Engine::of(tx),
        format!(
            "INSERT INTO versions (model_id, version, created_at, bundle_name, bundle_sha256, bundle_size, options_json, status,
                                   triangles, bundle_bytes)
         VALUES (?, ?, {NOW}, ?, ?, ?, ?, 'queued', ?, ?)"
        ),
    ))
    .bind(model_id)
    .bind(version)
    .bind(v.bundle_name)
    .bind(v.bundle_sha256)
    .bind(v.bundle_size)
    .bind(v.options_json)
    .bind(v.triangles)
    .bind(v.bundle_bytes)
    .execute(&mut *tx)
    .await?;
    insert_job(tx, "convert", model_id, version).await
}

/// Inserts a queued job of `kind` for a version (inside the caller's transaction).
async fn insert_job(tx: &mut AnyConnection, kind: &str, model_id: &str, version: i64) -> Result<String, StoreError> {
    let job_id = new_id();
    sqlx::query(&sql(
        Engine::of(tx),
        format!("INSERT INTO jobs (id, kind, model_id, version, status, created_at) VALUES (?, ?, ?, ?, 'queued', {NOW})"),
    ))
    .bind(&job_id)
    .bind(kind)
    .bind(model_id)
    .bind(version)
    .execute(&mut *tx)
    .await?;
    Ok(job_id)
}

/// Creates a model with its first version and that version's job, in one transaction.
pub async fn create_model(pool: &Pool, name: &str, v: &NewVersion<'_>) -> Result<Created, StoreError> {
    let model_id = new_id();
    let mut tx = pool.begin().await?;
    sqlx::query(&pool.sql(format!("INSERT INTO models (id, name, created_at, last_version) VALUES (?, ?, {NOW}, 1)")))
        .bind(&model_id)
        .bind(name)
        .execute(&mut *tx)
        .await?;
    let job_id = insert_version_and_job(&mut tx, &model_id, 1, v).await?;
    tx.commit().await?;
    Ok(Created { model_id, version: 1, job_id })
}

/// Adds a version (numbered after every version the model ever had) and its job, in one
/// transaction. `None` when the model does not exist.
pub async fn create_version(pool: &Pool, model_id: &str, v: &NewVersion<'_>) -> Result<Option<Created>, StoreError> {
    let mut tx = pool.begin().await?;
    // A write first, so the transaction takes the write lock at once (no read-then-upgrade).
    let next: Option<(i64,)> =
        sqlx::query_as(&pool.sql("UPDATE models SET last_version = last_version + 1 WHERE id = ? RETURNING last_version"))
            .bind(model_id)
            .fetch_optional(&mut *tx)
            .await?;
    let Some((version,)) = next else {
        tx.rollback().await?;
        return Ok(None);
    };
    let job_id = insert_version_and_job(&mut tx, model_id, version, v).await?;
    tx.commit().await?;
    Ok(Some(Created { model_id: model_id.to_string(), version, job_id }))
}

const MODEL_SELECT: &str = "SELECT m.id, m.name, m.created_at, v.version AS latest_version, v.status AS latest_status
     FROM models m
     LEFT JOIN versions v
       ON v.model_id = m.id AND v.version = (SELECT MAX(version) FROM versions WHERE model_id = m.id)";

/// Every model, oldest first.
pub async fn list_models(pool: &Pool) -> Result<Vec<ModelRow>, StoreError> {
    Ok(sqlx::query_as(&pool.sql(format!("{MODEL_SELECT} ORDER BY m.created_at, m.rowid"))).fetch_all(pool).await?)
}

pub async fn get_model(pool: &Pool, id: &str) -> Result<Option<ModelRow>, StoreError> {
    Ok(sqlx::query_as(&pool.sql(format!("{MODEL_SELECT} WHERE m.id = ?"))).bind(id).fetch_optional(pool).await?)
}

/// Deletes a model with its versions, jobs and drives (cascade). False when absent.
/// Blobs stay: they are content-addressed and may be shared with other versions.
pub async fn delete_model(pool: &Pool, id: &str) -> Result<bool, StoreError> {
    let r = sqlx::query(&pool.sql("DELETE FROM models WHERE id = ?")).bind(id).execute(pool).await?;
    Ok(r.rows_affected() > 0)
}

const VERSION_SELECT: &str = "SELECT v.model_id, v.version, v.created_at, v.bundle_name, v.bundle_sha256, v.bundle_size,
            v.options_json, v.status, v.package_sha256, v.report_sha256, v.error_json, v.summary_json,
            (SELECT j.id FROM jobs j WHERE j.model_id = v.model_id AND j.version = v.version
              ORDER BY j.created_at DESC, j.rowid DESC LIMIT 1) AS job_id
     FROM versions v";

/// A model's versions, in order.
pub async fn list_versions(pool: &Pool, model_id: &str) -> Result<Vec<VersionRow>, StoreError> {
    Ok(sqlx::query_as(&pool.sql(format!("{VERSION_SELECT} WHERE v.model_id = ? ORDER BY v.version")))
        .bind(model_id)
        .fetch_all(pool)
        .await?)
}

pub async fn get_version(pool: &Pool, model_id: &str, version: i64) -> Result<Option<VersionRow>, StoreError> {
    Ok(sqlx::query_as(&pool.sql(format!("{VERSION_SELECT} WHERE v.model_id = ? AND v.version = ?")))
        .bind(model_id)
        .bind(version)
        .fetch_optional(pool)
        .await?)
}

/// Deletes a version and its jobs. False when absent. The model stays (possibly with no
/// versions); its version numbers are not reused.
pub async fn delete_version(pool: &Pool, model_id: &str, version: i64) -> Result<bool, StoreError> {
    let mut tx = pool.begin().await?;
    let r = sqlx::query(&pool.sql("DELETE FROM versions WHERE model_id = ? AND version = ?"))
        .bind(model_id)
        .bind(version)
        .execute(&mut *tx)
        .await?;
    sqlx::query(&pool.sql("DELETE FROM jobs WHERE model_id = ? AND version = ?")).bind(model_id).bind(version).execute(&mut *tx).await?;
    tx.commit().await?;
    Ok(r.rows_affected() > 0)
}

pub async fn get_job(pool: &Pool, id: &str) -> Result<Option<JobRow>, StoreError> {
    Ok(sqlx::query_as(&pool.sql(
        "SELECT id, kind, model_id, version, status, error_json, created_at, started_at, finished_at, progress_json, attempts
         FROM jobs WHERE id = ?",
    ))
    .bind(id)
    .fetch_optional(pool)
    .await?)
}

/// How many queued jobs are ahead of queued job `id` (claimed in creation order), and how many
/// are running; `None` when `id` is not queued.
pub async fn queue_position(pool: &Pool, id: &str) -> Result<Option<(i64, i64)>, StoreError> {
    Ok(sqlx::query_as(&pool.sql(
        "SELECT (SELECT COUNT(*) FROM jobs a WHERE a.status = 'queued'
                   AND (a.created_at < j.created_at OR (a.created_at = j.created_at AND a.rowid < j.rowid))),
                (SELECT COUNT(*) FROM jobs r WHERE r.status = 'running')
         FROM jobs j WHERE j.id = ? AND j.status = 'queued'",
    ))
    .bind(id)
    .fetch_optional(pool)
    .await?)
}

/// Start-up recovery: jobs left `running` by a stopped server go back to `queued` (conversion is
/// idempotent, so a half-done run is simply redone), and so do their versions. Returns how many.
///
/// SQLite has one server per database: every `running` job is a stopped server's. On PostgreSQL
/// other instances may be running jobs right now: only jobs without a lease (marked interrupted)
/// or whose lease has passed are re-queued; the others belong to live instances.
pub async fn requeue_unfinished(pool: &Pool) -> Result<u64, StoreError> {
    let stale = match pool.engine() {
        Engine::Sqlite => "status = 'running'",
        Engine::Postgres => "status = 'running' AND (lease_until IS NULL OR lease_until < %NOW%)",
    };
    let mut tx = pool.begin().await?;
    // Crash accounting (issue 26): the jobs each stopped instance was running. A job that was the
    // only one running there is charged the stop (`aborts`); jobs that ran together are marked to
    // be re-run alone (`isolate`), nobody charged, so that a crash of such a run names its job.
    // On SQLite every running job is the one stopped server's; on PostgreSQL they are grouped by
    // the instance part of their lease token (jobs without one form one group).
    let running: Vec<(String, Option<String>)> =
        sqlx::query_as(&pool.sql(format!("SELECT id, lease_owner FROM jobs WHERE {stale}"))).fetch_all(&mut *tx).await?;
    let mut by_instance: std::collections::BTreeMap<String, Vec<String>> = Default::default();
    for (id, owner) in running {
        let instance = match pool.engine() {
            Engine::Sqlite => String::new(),
            Engine::Postgres => owner.as_deref().and_then(|o| o.split_once(':')).map(|(i, _)| i.to_string()).unwrap_or_default(),
        };
        by_instance.entry(instance).or_default().push(id);
    }
    for ids in by_instance.values() {
        let set = if ids.len() == 1 { "aborts = aborts + 1, isolate = 1" } else { "isolate = 1" };
        for id in ids {
            sqlx::query(&pool.sql(format!("UPDATE jobs SET {set} WHERE id = ?"))).bind(id).execute(&mut *tx).await?;
        }
    }
    let requeued: Vec<(String, i64)> = sqlx::query_as(&pool.sql(format!(
        "UPDATE jobs SET status = 'queued', started_at = NULL, lease_owner = NULL, lease_until = NULL, progress_json = NULL
         WHERE {stale} RETURNING model_id, version"
    )))
    .fetch_all(&mut *tx)
    .await?;
    requeue_versions(&mut tx, pool, &requeued).await?;
    tx.commit().await?;
    Ok(requeued.len() as u64)
}

/// Marks the versions of jobs put back in the queue queued again (those still running).
async fn requeue_versions(tx: &mut AnyConnection, pool: &Pool, jobs: &[(String, i64)]) -> Result<(), StoreError> {
    for (model_id, version) in jobs {
        sqlx::query(&pool.sql("UPDATE versions SET status = 'queued' WHERE model_id = ? AND version = ? AND status = 'running'"))
            .bind(model_id)
            .bind(version)
            .execute(&mut *tx)
            .await?;
    }
    Ok(())
}

/// Puts the jobs `instance` was running back in the queue (job and version) without charging
/// an abort: what a graceful stop (Ctrl-C, SIGTERM) does once its workers are halted, so that a
/// stop asked for is never counted as a crash of the job that happened to run. Returns how many.
pub async fn release_claims(pool: &Pool, instance: &str) -> Result<u64, StoreError> {
    let mut tx = pool.begin().await?;
    let requeued: Vec<(String, i64)> = sqlx::query_as(&pool.sql(
        "UPDATE jobs SET status = 'queued', started_at = NULL, lease_owner = NULL, lease_until = NULL, progress_json = NULL
         WHERE status = 'running' AND lease_owner LIKE ? RETURNING model_id, version",
    ))
    .bind(format!("{instance}:%"))
    .fetch_all(&mut *tx)
    .await?;
    requeue_versions(&mut tx, pool, &requeued).await?;
    tx.commit().await?;
    Ok(requeued.len() as u64)
}

/// Whether a queued job waits to be run alone (see [`requeue_unfinished`]): the worker pool then
/// runs one job at a time until none does.
pub async fn isolation_pending(pool: &Pool) -> Result<bool, StoreError> {
    let row: Option<(i64,)> =
        sqlx::query_as(&pool.sql("SELECT 1 FROM jobs WHERE isolate = 1 AND status = 'queued' LIMIT 1")).fetch_optional(pool).await?;
    Ok(row.is_some())
}

/// Jobs quarantined for stopping the service (failed with at least `min_aborts` aborts while
/// running alone), newest first, at most `limit`.
pub async fn quarantined_jobs(pool: &Pool, min_aborts: i64, limit: i64) -> Result<Vec<JobRow>, StoreError> {
    Ok(sqlx::query_as(&pool.sql(
        "SELECT id, kind, model_id, version, status, error_json, created_at, started_at, finished_at, progress_json, attempts
         FROM jobs WHERE status = 'failed' AND aborts >= ? ORDER BY created_at DESC, rowid DESC LIMIT ?",
    ))
    .bind(min_aborts)
    .bind(limit)
    .fetch_all(pool)
    .await?)
}

/// The latest jobs, newest first, at most `limit`.
pub async fn recent_jobs(pool: &Pool, limit: i64) -> Result<Vec<JobRow>, StoreError> {
    Ok(sqlx::query_as(&pool.sql(
        "SELECT id, kind, model_id, version, status, error_json, created_at, started_at, finished_at, progress_json, attempts
         FROM jobs ORDER BY created_at DESC, rowid DESC LIMIT ?",
    ))
    .bind(limit)
    .fetch_all(pool)
    .await?)
}

/// A job is claimable when it is queued, or running under a lease that has passed (its instance
/// died), and no earlier job of its model is still queued or running: a model's jobs run in
/// version order (a version's Modelica names come from the one before it).
const CLAIMABLE: &str = "(j.status = 'queued' OR (j.status = 'running' AND j.lease_until < %NOW%))
           AND NOT EXISTS (SELECT 1 FROM jobs e WHERE e.model_id = j.model_id
                             AND e.status IN ('queued', 'running')
                             AND (e.version < j.version OR (e.version = j.version AND e.rowid < j.rowid)))";

/// The size of the job [`claim_next_job`] would take now (its version's `triangles` and
/// `bundle_bytes`, each NULL when unknown), for the worker pool's memory admission; `None` when
/// nothing is claimable. A read only: the claim may still take another job (another instance
/// claimed this one meanwhile), and the caller then checks the one it got.
pub async fn next_job_size(pool: &Pool) -> Result<Option<(Option<i64>, Option<i64>)>, StoreError> {
    Ok(sqlx::query_as(&pool.sql(format!(
        "SELECT v.triangles, v.bundle_bytes FROM jobs j
         LEFT JOIN versions v ON v.model_id = j.model_id AND v.version = j.version
         WHERE {CLAIMABLE} ORDER BY j.isolate DESC, j.created_at, j.rowid LIMIT 1"
    )))
    .fetch_optional(pool)
    .await?)
}

/// Takes the oldest claimable job (see [`CLAIMABLE`]), marks it and its version `running` under a
/// lease of `claimer.lease_secs` held by a new token, counts the attempt (`jobs.attempts`) and
/// returns it. `None` when nothing is claimable.
///
/// Two claimers never get the same job: on PostgreSQL the candidate row is locked in the claim's
/// transaction (`FOR UPDATE SKIP LOCKED`: concurrent claimers pass over it to the next); on
/// SQLite, with its single writer, the update is conditional on the job still being claimable.
pub async fn claim_next_job(pool: &Pool, claimer: &Claimer) -> Result<Option<ClaimedJob>, StoreError> {
    let owner = format!("{}:{}", claimer.instance, new_id());
    let set = "status = 'running', started_at = %NOW%, finished_at = NULL, error_json = NULL, progress_json = NULL,
               attempts = attempts + 1, lease_owner = ?, lease_until = %UNTIL%";
    // Jobs to be run alone first (the dispatcher runs nothing beside them).
    let mut tx;
    let job: Option<(String, String, String, i64, i64, i64)> = match pool.engine() {
        Engine::Postgres => {
            tx = pool.begin().await?;
            sqlx::query_as(&pool.sql(format!(
                "WITH c AS (SELECT j.id FROM jobs j WHERE {CLAIMABLE}
                            ORDER BY j.isolate DESC, j.created_at, j.rowid LIMIT 1 FOR UPDATE OF j SKIP LOCKED)
                 UPDATE jobs SET {set} FROM c WHERE jobs.id = c.id
                 RETURNING jobs.id, jobs.kind, jobs.model_id, jobs.version, jobs.attempts, jobs.aborts"
            )))
            .bind(&owner)
            .bind(claimer.lease_secs)
            .fetch_optional(&mut *tx)
            .await?
        }
        Engine::Sqlite => {
            // Read first, outside any transaction: an idle poll must not take SQLite's write lock,
            // or a concurrent read-then-write transaction elsewhere would fail with "database is locked".
            let candidate: Option<(String,)> = sqlx::query_as(
                &pool.sql(format!("SELECT j.id FROM jobs j WHERE {CLAIMABLE} ORDER BY j.isolate DESC, j.created_at, j.rowid LIMIT 1")),
            )
            .fetch_optional(pool)
            .await?;
            let Some((candidate,)) = candidate else { return Ok(None) };
            tx = pool.begin().await?;
            sqlx::query_as(&pool.sql(format!(
                "UPDATE jobs SET {set} WHERE id = ? AND id IN (SELECT j.id FROM jobs j WHERE {CLAIMABLE})
                 RETURNING id, kind, model_id, version, attempts, aborts"
            )))
            .bind(&owner)
            .bind(claimer.lease_secs)
            .bind(&candidate)
            .fetch_optional(&mut *tx)
            .await?
        }
    };
    let Some((id, kind, model_id, version, attempts, aborts)) = job else {
        tx.rollback().await?;
        return Ok(None);
    };
    let source: Option<JobSource> = sqlx::query_as(&pool.sql(
        "UPDATE versions SET status = 'running', error_json = NULL
         WHERE model_id = ? AND version = ?
         RETURNING bundle_name, bundle_sha256, options_json, triangles, bundle_bytes",
    ))
    .bind(&model_id)
    .bind(version)
    .fetch_optional(&mut *tx)
    .await?;
    tx.commit().await?;
    Ok(Some(ClaimedJob { id, kind, model_id, version, attempts, aborts, source, lease_owner: owner }))
}

/// Extends a running job's lease by `lease_secs` from now. False when the job no longer holds
/// this lease (it passed and another instance took the job over, or the job was deleted).
pub async fn renew_lease(pool: &Pool, job: &ClaimedJob, lease_secs: f64) -> Result<bool, StoreError> {
    let r = sqlx::query(&pool.sql("UPDATE jobs SET lease_until = %UNTIL% WHERE id = ? AND lease_owner = ? AND status = 'running'"))
        .bind(lease_secs)
        .bind(&job.id)
        .bind(&job.lease_owner)
        .execute(pool)
        .await?;
    Ok(r.rows_affected() == 1)
}

/// Records a running job's progress (JSON), while it holds its lease. False when it does not.
pub async fn set_progress(pool: &Pool, job: &ClaimedJob, progress_json: &str) -> Result<bool, StoreError> {
    let r = sqlx::query(&pool.sql("UPDATE jobs SET progress_json = ? WHERE id = ? AND lease_owner = ? AND status = 'running'"))
        .bind(progress_json)
        .bind(&job.id)
        .bind(&job.lease_owner)
        .execute(pool)
        .await?;
    Ok(r.rows_affected() == 1)
}

/// Ends a job: `status`, `error_json` and `finished_at` on the job, if it still holds its lease
/// (an instance whose lease passed must not overwrite the result of the one that took over).
/// The lease and the progress are cleared. False when the lease was lost: nothing is written.
async fn finish_job(tx: &mut AnyConnection, job: &ClaimedJob, status: &str, error_json: Option<&str>) -> Result<bool, StoreError> {
    let r = sqlx::query(&sql(
        Engine::of(tx),
        "UPDATE jobs SET status = ?, error_json = ?, finished_at = %NOW%, lease_owner = NULL, lease_until = NULL, progress_json = NULL
         WHERE id = ? AND lease_owner = ? AND status = 'running'",
    ))
    .bind(status)
    .bind(error_json)
    .bind(&job.id)
    .bind(&job.lease_owner)
    .execute(&mut *tx)
    .await?;
    Ok(r.rows_affected() == 1)
}

/// The outputs of a successful job (blobs already stored).
#[derive(Debug, Clone)]
pub struct JobOutputs<'a> {
    pub package_sha256: &'a str,
    pub report_sha256: &'a str,
    pub summary_json: &'a str,
}

/// Marks a job and its version succeeded, pointing the version at its outputs. False (nothing
/// written) when the job no longer holds its lease.
pub async fn finish_succeeded(pool: &Pool, job: &ClaimedJob, out: &JobOutputs<'_>) -> Result<bool, StoreError> {
    let mut tx = pool.begin().await?;
    if !finish_job(&mut tx, job, "succeeded", None).await? {
        tx.rollback().await?;
        return Ok(false);
    }
    sqlx::query(&pool.sql(
        "UPDATE versions SET status = 'succeeded', package_sha256 = ?, report_sha256 = ?, summary_json = ?, error_json = NULL
         WHERE model_id = ? AND version = ?",
    ))
    .bind(out.package_sha256)
    .bind(out.report_sha256)
    .bind(out.summary_json)
    .bind(&job.model_id)
    .bind(job.version)
    .execute(&mut *tx)
    .await?;
    tx.commit().await?;
    Ok(true)
}

/// Marks a job and its version failed with a problem document. False (nothing written) when the
/// job no longer holds its lease.
pub async fn finish_failed(pool: &Pool, job: &ClaimedJob, error_json: &str) -> Result<bool, StoreError> {
    let mut tx = pool.begin().await?;
    if !finish_job(&mut tx, job, "failed", Some(error_json)).await? {
        tx.rollback().await?;
        return Ok(false);
    }
    sqlx::query(&pool.sql(
        "UPDATE versions SET status = 'failed', package_sha256 = NULL, report_sha256 = NULL, summary_json = NULL, error_json = ?
         WHERE model_id = ? AND version = ?",
    ))
    .bind(error_json)
    .bind(&job.model_id)
    .bind(job.version)
    .execute(&mut *tx)
    .await?;
    tx.commit().await?;
    Ok(true)
}

/// Puts a job (and its version) back in the state a crash mid-conversion leaves: `running`, no
/// outputs. For recovery tests and operators; a server start re-queues it. False when absent.
pub async fn mark_interrupted(pool: &Pool, job_id: &str) -> Result<bool, StoreError> {
    let mut tx = pool.begin().await?;
    let job: Option<(String, i64)> = sqlx::query_as(&pool.sql(format!(
        "UPDATE jobs SET status = 'running', started_at = {NOW}, finished_at = NULL, error_json = NULL,
                lease_owner = NULL, lease_until = NULL, progress_json = NULL
         WHERE id = ? RETURNING model_id, version"
    )))
    .bind(job_id)
    .fetch_optional(&mut *tx)
    .await?;
    let Some((model_id, version)) = job else {
        tx.rollback().await?;
        return Ok(false);
    };
    sqlx::query(&pool.sql(
        "UPDATE versions SET status = 'running', package_sha256 = NULL, report_sha256 = NULL, summary_json = NULL, error_json = NULL
         WHERE model_id = ? AND version = ?",
    ))
    .bind(&model_id)
    .bind(version)
    .execute(&mut *tx)
    .await?;
    tx.commit().await?;
    Ok(true)
}

/// Queues a re-export of a model's latest version (same bundle, current library and drives):
/// a `reexport` job, with the version back to `queued`. `None` when the model has no version.
pub async fn queue_reexport(pool: &Pool, model_id: &str) -> Result<Option<(i64, String)>, StoreError> {
    let mut tx = pool.begin().await?;
    // Write first (no read-then-write lock upgrade inside the transaction).
    let job_id = new_id();
    let inserted: Option<(i64,)> = sqlx::query_as(&pool.sql(format!(
        "INSERT INTO jobs (id, kind, model_id, version, status, created_at)
         SELECT ?, 'reexport', ?, MAX(version), 'queued', {NOW} FROM versions WHERE model_id = ? HAVING COUNT(*) > 0
         RETURNING version"
    )))
    .bind(&job_id)
    .bind(model_id)
    .bind(model_id)
    .fetch_optional(&mut *tx)
    .await?;
    let Some((version,)) = inserted else {
        tx.rollback().await?;
        return Ok(None);
    };
    sqlx::query(&pool.sql("UPDATE versions SET status = 'queued' WHERE model_id = ? AND version = ? AND status <> 'running'"))
        .bind(model_id)
        .bind(version)
        .execute(&mut *tx)
        .await?;
    tx.commit().await?;
    Ok(Some((version, job_id)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::store::Store;

    async fn store() -> (tempfile::TempDir, Store) {
        let dir = tempfile::tempdir().unwrap();
        let url = format!("sqlite://{}?mode=rwc", dir.path().join("t.db").display());
        (dir, Store::open(&url).await.unwrap())
    }

    fn claimer() -> Claimer {
        Claimer { instance: "test".into(), lease_secs: 30.0 }
    }

    fn upload() -> NewVersion<'static> {
        NewVersion { bundle_name: "b.zip", bundle_sha256: "ab", bundle_size: 2, options_json: "{}", triangles: None, bundle_bytes: None }
    }

    #[tokio::test]
    async fn versions_are_numbered_and_never_reused() {
        let (_d, s) = store().await;
        let c = create_model(&s.pool, "m", &upload()).await.unwrap();
        assert_eq!(c.version, 1);
        let c2 = create_version(&s.pool, &c.model_id, &upload()).await.unwrap().unwrap();
        assert_eq!(c2.version, 2);
        assert!(delete_version(&s.pool, &c.model_id, 2).await.unwrap());
        assert!(get_job(&s.pool, &c2.job_id).await.unwrap().is_none());
        let c3 = create_version(&s.pool, &c.model_id, &upload()).await.unwrap().unwrap();
        assert_eq!(c3.version, 3);
        assert!(create_version(&s.pool, "nope", &upload()).await.unwrap().is_none());
        let m = get_model(&s.pool, &c.model_id).await.unwrap().unwrap();
        assert_eq!((m.latest_version, m.latest_status.as_deref()), (Some(3), Some("queued")));
        let v = get_version(&s.pool, &c.model_id, 3).await.unwrap().unwrap();
        assert_eq!(v.job_id.as_deref(), Some(c3.job_id.as_str()));
    }

    /// Issue 26, crash accounting: a stop while several jobs run charges none of them; they are
    /// re-run alone first, and only a job that is running alone at a stop is charged.
    #[tokio::test]
    async fn a_stop_charges_only_a_job_running_alone() {
        let (_d, s) = store().await;
        let a = create_model(&s.pool, "a", &upload()).await.unwrap();
        let b = create_model(&s.pool, "b", &upload()).await.unwrap();
        let c = create_model(&s.pool, "c", &upload()).await.unwrap();
        let aborts = |id: String| {
            let pool = s.pool.clone();
            async move {
                let (n, iso): (i64, i64) =
                    sqlx::query_as(&pool.sql("SELECT aborts, isolate FROM jobs WHERE id = ?")).bind(id).fetch_one(&pool).await.unwrap();
                (n, iso)
            }
        };
        // Three jobs running when the process aborts: nobody is charged, all are to run alone.
        for _ in 0..3 {
            claim_next_job(&s.pool, &claimer()).await.unwrap().unwrap();
        }
        assert!(!isolation_pending(&s.pool).await.unwrap());
        assert_eq!(requeue_unfinished(&s.pool).await.unwrap(), 3);
        for j in [&a.job_id, &b.job_id, &c.job_id] {
            assert_eq!(aborts(j.clone()).await, (0, 1), "a bystander is not charged");
        }
        assert!(isolation_pending(&s.pool).await.unwrap());
        // Re-run alone: a (innocent) finishes; b aborts the process while alone: charged.
        let ja = claim_next_job(&s.pool, &claimer()).await.unwrap().unwrap();
        assert_eq!((ja.id.as_str(), ja.aborts), (a.job_id.as_str(), 0));
        let out = JobOutputs { package_sha256: "p", report_sha256: "r", summary_json: "{}" };
        assert!(finish_succeeded(&s.pool, &ja, &out).await.unwrap());
        let jb = claim_next_job(&s.pool, &claimer()).await.unwrap().unwrap();
        assert_eq!(jb.id, b.job_id);
        assert_eq!(requeue_unfinished(&s.pool).await.unwrap(), 1);
        assert_eq!(aborts(b.job_id.clone()).await, (1, 1));
        assert_eq!(aborts(c.job_id.clone()).await, (0, 1), "c was queued, not running");
        // A queued job to be run alone comes before older ones.
        let new = create_model(&s.pool, "d", &upload()).await.unwrap();
        let jb = claim_next_job(&s.pool, &claimer()).await.unwrap().unwrap();
        assert_eq!((jb.id.as_str(), jb.aborts), (b.job_id.as_str(), 1));
        assert_eq!(requeue_unfinished(&s.pool).await.unwrap(), 1);
        let jb = claim_next_job(&s.pool, &claimer()).await.unwrap().unwrap();
        assert_eq!((jb.id.as_str(), jb.aborts), (b.job_id.as_str(), 2), "twice alone: the worker quarantines it");
        assert!(finish_failed(&s.pool, &jb, "{\"type\":\"/problems/conversion-aborted\"}").await.unwrap());
        let q = quarantined_jobs(&s.pool, 2, 50).await.unwrap();
        assert_eq!(q.iter().map(|j| j.id.as_str()).collect::<Vec<_>>(), [b.job_id.as_str()]);
        let jc = claim_next_job(&s.pool, &claimer()).await.unwrap().unwrap();
        assert_eq!((jc.id.as_str(), jc.aborts), (c.job_id.as_str(), 0));
        assert!(finish_succeeded(&s.pool, &jc, &out).await.unwrap());
        assert!(!isolation_pending(&s.pool).await.unwrap());
        assert_eq!(claim_next_job(&s.pool, &claimer()).await.unwrap().unwrap().id, new.job_id);
    }

    #[tokio::test]
    async fn claim_finish_and_requeue() {
        let (_d, s) = store().await;
        let a = create_model(&s.pool, "a", &upload()).await.unwrap();
        let b = create_model(&s.pool, "b", &upload()).await.unwrap();
        let j = claim_next_job(&s.pool, &claimer()).await.unwrap().unwrap();
        assert_eq!((j.id.as_str(), j.attempts), (a.job_id.as_str(), 1));
        assert_eq!(j.source.as_ref().unwrap().bundle_name, "b.zip");
        let out = JobOutputs { package_sha256: "p", report_sha256: "r", summary_json: "{}" };
        assert!(finish_succeeded(&s.pool, &j, &out).await.unwrap());
        let j2 = claim_next_job(&s.pool, &claimer()).await.unwrap().unwrap();
        assert_eq!(j2.id, b.job_id);
        assert!(claim_next_job(&s.pool, &claimer()).await.unwrap().is_none());
        // A crash now: b's job stays running until the next start re-queues it.
        assert_eq!(requeue_unfinished(&s.pool).await.unwrap(), 1);
        assert_eq!(get_job(&s.pool, &b.job_id).await.unwrap().unwrap().status, "queued");
        assert_eq!(get_version(&s.pool, &b.model_id, 1).await.unwrap().unwrap().status, "queued");
        let j3 = claim_next_job(&s.pool, &claimer()).await.unwrap().unwrap();
        assert_eq!((j3.id.as_str(), j3.attempts), (b.job_id.as_str(), 2), "every claim counts");
        assert!(finish_failed(&s.pool, &j3, "{\"status\":422}").await.unwrap());
        let v = get_version(&s.pool, &b.model_id, 1).await.unwrap().unwrap();
        assert_eq!((v.status.as_str(), v.error_json.as_deref()), ("failed", Some("{\"status\":422}")));
        assert!(mark_interrupted(&s.pool, &a.job_id).await.unwrap());
        assert_eq!(get_version(&s.pool, &a.model_id, 1).await.unwrap().unwrap().package_sha256, None);
        assert!(delete_model(&s.pool, &a.model_id).await.unwrap());
        assert!(get_job(&s.pool, &a.job_id).await.unwrap().is_none());
        assert_eq!(list_models(&s.pool).await.unwrap().len(), 1);
    }
}
