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

use sqlx::{FromRow, SqlitePool};

use super::StoreError;

/// SQLite's clock as RFC 3339 UTC with milliseconds (the same format as [`super::now`]).
const NOW: &str = "strftime('%Y-%m-%dT%H:%M:%fZ', 'now')";

/// The stored upload of a new version.
#[derive(Debug, Clone)]
pub struct NewVersion<'a> {
    pub bundle_name: &'a str,
    pub bundle_sha256: &'a str,
    pub bundle_size: i64,
    /// The conversion options, serialised.
    pub options_json: &'a str,
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
    /// `None` when the version no longer exists (deleted meanwhile).
    pub source: Option<JobSource>,
}

/// The stored input of a version.
#[derive(Debug, Clone, FromRow)]
pub struct JobSource {
    pub bundle_name: String,
    pub bundle_sha256: String,
    pub options_json: String,
}

fn new_id() -> String {
    uuid::Uuid::new_v4().to_string()
}

/// Inserts the version row and its convert job (inside the caller's transaction).
async fn insert_version_and_job(
    tx: &mut sqlx::SqliteConnection,
    model_id: &str,
    version: i64,
    v: &NewVersion<'_>,
) -> Result<String, StoreError> {
    sqlx::query(&format!(
        "INSERT INTO versions (model_id, version, created_at, bundle_name, bundle_sha256, bundle_size, options_json, status)
         VALUES (?, ?, {NOW}, ?, ?, ?, ?, 'queued')"
    ))
    .bind(model_id)
    .bind(version)
    .bind(v.bundle_name)
    .bind(v.bundle_sha256)
    .bind(v.bundle_size)
    .bind(v.options_json)
    .execute(&mut *tx)
    .await?;
    insert_job(tx, "convert", model_id, version).await
}

/// Inserts a queued job of `kind` for a version (inside the caller's transaction).
async fn insert_job(tx: &mut sqlx::SqliteConnection, kind: &str, model_id: &str, version: i64) -> Result<String, StoreError> {
    let job_id = new_id();
    sqlx::query(&format!(
        "INSERT INTO jobs (id, kind, model_id, version, status, created_at) VALUES (?, ?, ?, ?, 'queued', {NOW})"
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
pub async fn create_model(pool: &SqlitePool, name: &str, v: &NewVersion<'_>) -> Result<Created, StoreError> {
    let model_id = new_id();
    let mut tx = pool.begin().await?;
    sqlx::query(&format!("INSERT INTO models (id, name, created_at, last_version) VALUES (?, ?, {NOW}, 1)"))
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
pub async fn create_version(
    pool: &SqlitePool,
    model_id: &str,
    v: &NewVersion<'_>,
) -> Result<Option<Created>, StoreError> {
    let mut tx = pool.begin().await?;
    // A write first, so the transaction takes the write lock at once (no read-then-upgrade).
    let next: Option<(i64,)> =
        sqlx::query_as("UPDATE models SET last_version = last_version + 1 WHERE id = ? RETURNING last_version")
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
pub async fn list_models(pool: &SqlitePool) -> Result<Vec<ModelRow>, StoreError> {
    Ok(sqlx::query_as(&format!("{MODEL_SELECT} ORDER BY m.created_at, m.rowid")).fetch_all(pool).await?)
}

pub async fn get_model(pool: &SqlitePool, id: &str) -> Result<Option<ModelRow>, StoreError> {
    Ok(sqlx::query_as(&format!("{MODEL_SELECT} WHERE m.id = ?")).bind(id).fetch_optional(pool).await?)
}

/// Deletes a model with its versions, jobs and drives (cascade). False when absent.
/// Blobs stay: they are content-addressed and may be shared with other versions.
pub async fn delete_model(pool: &SqlitePool, id: &str) -> Result<bool, StoreError> {
    let r = sqlx::query("DELETE FROM models WHERE id = ?").bind(id).execute(pool).await?;
    Ok(r.rows_affected() > 0)
}

const VERSION_SELECT: &str =
    "SELECT v.model_id, v.version, v.created_at, v.bundle_name, v.bundle_sha256, v.bundle_size,
            v.options_json, v.status, v.package_sha256, v.report_sha256, v.error_json, v.summary_json,
            (SELECT j.id FROM jobs j WHERE j.model_id = v.model_id AND j.version = v.version
              ORDER BY j.created_at DESC, j.rowid DESC LIMIT 1) AS job_id
     FROM versions v";

/// A model's versions, in order.
pub async fn list_versions(pool: &SqlitePool, model_id: &str) -> Result<Vec<VersionRow>, StoreError> {
    Ok(sqlx::query_as(&format!("{VERSION_SELECT} WHERE v.model_id = ? ORDER BY v.version"))
        .bind(model_id)
        .fetch_all(pool)
        .await?)
}

pub async fn get_version(pool: &SqlitePool, model_id: &str, version: i64) -> Result<Option<VersionRow>, StoreError> {
    Ok(sqlx::query_as(&format!("{VERSION_SELECT} WHERE v.model_id = ? AND v.version = ?"))
        .bind(model_id)
        .bind(version)
        .fetch_optional(pool)
        .await?)
}

/// Deletes a version and its jobs. False when absent. The model stays (possibly with no
/// versions); its version numbers are not reused.
pub async fn delete_version(pool: &SqlitePool, model_id: &str, version: i64) -> Result<bool, StoreError> {
    let mut tx = pool.begin().await?;
    let r = sqlx::query("DELETE FROM versions WHERE model_id = ? AND version = ?")
        .bind(model_id)
        .bind(version)
        .execute(&mut *tx)
        .await?;
    sqlx::query("DELETE FROM jobs WHERE model_id = ? AND version = ?")
        .bind(model_id)
        .bind(version)
        .execute(&mut *tx)
        .await?;
    tx.commit().await?;
    Ok(r.rows_affected() > 0)
}

pub async fn get_job(pool: &SqlitePool, id: &str) -> Result<Option<JobRow>, StoreError> {
    Ok(sqlx::query_as(
        "SELECT id, kind, model_id, version, status, error_json, created_at, started_at, finished_at FROM jobs WHERE id = ?",
    )
    .bind(id)
    .fetch_optional(pool)
    .await?)
}

/// How many queued jobs are ahead of queued job `id` (claimed in creation order), and how many
/// are running; `None` when `id` is not queued.
pub async fn queue_position(pool: &SqlitePool, id: &str) -> Result<Option<(i64, i64)>, StoreError> {
    Ok(sqlx::query_as(
        "SELECT (SELECT COUNT(*) FROM jobs a WHERE a.status = 'queued'
                   AND (a.created_at < j.created_at OR (a.created_at = j.created_at AND a.rowid < j.rowid))),
                (SELECT COUNT(*) FROM jobs r WHERE r.status = 'running')
         FROM jobs j WHERE j.id = ? AND j.status = 'queued'",
    )
    .bind(id)
    .fetch_optional(pool)
    .await?)
}

/// Start-up recovery: every job left `queued` or `running` by a stopped server goes back to
/// `queued` (conversion is idempotent, so a half-done run is simply redone), and so do their
/// versions. Returns how many jobs were `running`.
pub async fn requeue_unfinished(pool: &SqlitePool) -> Result<u64, StoreError> {
    let mut tx = pool.begin().await?;
    let r = sqlx::query("UPDATE jobs SET status = 'queued', started_at = NULL WHERE status = 'running'")
        .execute(&mut *tx)
        .await?;
    sqlx::query("UPDATE versions SET status = 'queued' WHERE status = 'running'").execute(&mut *tx).await?;
    tx.commit().await?;
    Ok(r.rows_affected())
}

/// Takes the oldest queued job whose model has no earlier job still queued or running (a
/// model's jobs run in version order: a version's Modelica names come from the one before it),
/// marks it and its version `running`, counts the attempt (`jobs.attempts`) and returns it.
/// `None` when nothing is claimable.
pub async fn claim_next_job(pool: &SqlitePool) -> Result<Option<ClaimedJob>, StoreError> {
    // Read first, outside any transaction: an idle poll must not take SQLite's write lock, or a
    // concurrent read-then-write transaction elsewhere would fail with "database is locked".
    let candidate: Option<(String,)> = sqlx::query_as(
        "SELECT j.id FROM jobs j WHERE j.status = 'queued'
           AND NOT EXISTS (SELECT 1 FROM jobs e WHERE e.model_id = j.model_id
                             AND e.status IN ('queued', 'running')
                             AND (e.version < j.version OR (e.version = j.version AND e.rowid < j.rowid)))
         ORDER BY j.created_at, j.rowid LIMIT 1",
    )
    .fetch_optional(pool)
    .await?;
    let Some((candidate,)) = candidate else { return Ok(None) };
    let mut tx = pool.begin().await?;
    let job: Option<(String, String, String, i64, i64)> = sqlx::query_as(&format!(
        "UPDATE jobs SET status = 'running', started_at = {NOW}, finished_at = NULL, error_json = NULL,
                attempts = attempts + 1
         WHERE id = ? AND status = 'queued'
         RETURNING id, kind, model_id, version, attempts"
    ))
    .bind(&candidate)
    .fetch_optional(&mut *tx)
    .await?;
    let Some((id, kind, model_id, version, attempts)) = job else {
        tx.rollback().await?;
        return Ok(None);
    };
    let source: Option<JobSource> = sqlx::query_as(
        "UPDATE versions SET status = 'running', error_json = NULL
         WHERE model_id = ? AND version = ?
         RETURNING bundle_name, bundle_sha256, options_json",
    )
    .bind(&model_id)
    .bind(version)
    .fetch_optional(&mut *tx)
    .await?;
    tx.commit().await?;
    Ok(Some(ClaimedJob { id, kind, model_id, version, attempts, source }))
}

/// The outputs of a successful job (blobs already stored).
#[derive(Debug, Clone)]
pub struct JobOutputs<'a> {
    pub package_sha256: &'a str,
    pub report_sha256: &'a str,
    pub summary_json: &'a str,
}

/// Marks a job and its version succeeded, pointing the version at its outputs.
pub async fn finish_succeeded(pool: &SqlitePool, job: &ClaimedJob, out: &JobOutputs<'_>) -> Result<(), StoreError> {
    let mut tx = pool.begin().await?;
    sqlx::query(&format!("UPDATE jobs SET status = 'succeeded', error_json = NULL, finished_at = {NOW} WHERE id = ?"))
        .bind(&job.id)
        .execute(&mut *tx)
        .await?;
    sqlx::query(
        "UPDATE versions SET status = 'succeeded', package_sha256 = ?, report_sha256 = ?, summary_json = ?, error_json = NULL
         WHERE model_id = ? AND version = ?",
    )
    .bind(out.package_sha256)
    .bind(out.report_sha256)
    .bind(out.summary_json)
    .bind(&job.model_id)
    .bind(job.version)
    .execute(&mut *tx)
    .await?;
    tx.commit().await?;
    Ok(())
}

/// Marks a job and its version failed with a problem document.
pub async fn finish_failed(pool: &SqlitePool, job: &ClaimedJob, error_json: &str) -> Result<(), StoreError> {
    let mut tx = pool.begin().await?;
    sqlx::query(&format!("UPDATE jobs SET status = 'failed', error_json = ?, finished_at = {NOW} WHERE id = ?"))
        .bind(error_json)
        .bind(&job.id)
        .execute(&mut *tx)
        .await?;
    sqlx::query(
        "UPDATE versions SET status = 'failed', package_sha256 = NULL, report_sha256 = NULL, summary_json = NULL, error_json = ?
         WHERE model_id = ? AND version = ?",
    )
    .bind(error_json)
    .bind(&job.model_id)
    .bind(job.version)
    .execute(&mut *tx)
    .await?;
    tx.commit().await?;
    Ok(())
}

/// Puts a job (and its version) back in the state a crash mid-conversion leaves: `running`, no
/// outputs. For recovery tests and operators; a server start re-queues it. False when absent.
pub async fn mark_interrupted(pool: &SqlitePool, job_id: &str) -> Result<bool, StoreError> {
    let mut tx = pool.begin().await?;
    let job: Option<(String, i64)> = sqlx::query_as(&format!(
        "UPDATE jobs SET status = 'running', started_at = {NOW}, finished_at = NULL, error_json = NULL
         WHERE id = ? RETURNING model_id, version"
    ))
    .bind(job_id)
    .fetch_optional(&mut *tx)
    .await?;
    let Some((model_id, version)) = job else {
        tx.rollback().await?;
        return Ok(false);
    };
    sqlx::query(
        "UPDATE versions SET status = 'running', package_sha256 = NULL, report_sha256 = NULL, summary_json = NULL, error_json = NULL
         WHERE model_id = ? AND version = ?",
    )
    .bind(&model_id)
    .bind(version)
    .execute(&mut *tx)
    .await?;
    tx.commit().await?;
    Ok(true)
}

/// Queues a re-export of a model's latest version (same bundle, current library and drives):
/// a `reexport` job, with the version back to `queued`. `None` when the model has no version.
pub async fn queue_reexport(pool: &SqlitePool, model_id: &str) -> Result<Option<(i64, String)>, StoreError> {
    let mut tx = pool.begin().await?;
    // Write first (no read-then-write lock upgrade inside the transaction).
    let job_id = new_id();
    let inserted: Option<(i64,)> = sqlx::query_as(&format!(
        "INSERT INTO jobs (id, kind, model_id, version, status, created_at)
         SELECT ?, 'reexport', ?, MAX(version), 'queued', {NOW} FROM versions WHERE model_id = ? HAVING COUNT(*) > 0
         RETURNING version"
    ))
    .bind(&job_id)
    .bind(model_id)
    .bind(model_id)
    .fetch_optional(&mut *tx)
    .await?;
    let Some((version,)) = inserted else {
        tx.rollback().await?;
        return Ok(None);
    };
    sqlx::query("UPDATE versions SET status = 'queued' WHERE model_id = ? AND version = ? AND status <> 'running'")
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

    fn upload() -> NewVersion<'static> {
        NewVersion { bundle_name: "b.zip", bundle_sha256: "ab", bundle_size: 2, options_json: "{}" }
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

    #[tokio::test]
    async fn claim_finish_and_requeue() {
        let (_d, s) = store().await;
        let a = create_model(&s.pool, "a", &upload()).await.unwrap();
        let b = create_model(&s.pool, "b", &upload()).await.unwrap();
        let j = claim_next_job(&s.pool).await.unwrap().unwrap();
        assert_eq!((j.id.as_str(), j.attempts), (a.job_id.as_str(), 1));
        assert_eq!(j.source.as_ref().unwrap().bundle_name, "b.zip");
        let out = JobOutputs { package_sha256: "p", report_sha256: "r", summary_json: "{}" };
        finish_succeeded(&s.pool, &j, &out).await.unwrap();
        let j2 = claim_next_job(&s.pool).await.unwrap().unwrap();
        assert_eq!(j2.id, b.job_id);
        assert!(claim_next_job(&s.pool).await.unwrap().is_none());
        // A crash now: b's job stays running until the next start re-queues it.
        assert_eq!(requeue_unfinished(&s.pool).await.unwrap(), 1);
        assert_eq!(get_job(&s.pool, &b.job_id).await.unwrap().unwrap().status, "queued");
        assert_eq!(get_version(&s.pool, &b.model_id, 1).await.unwrap().unwrap().status, "queued");
        let j3 = claim_next_job(&s.pool).await.unwrap().unwrap();
        assert_eq!((j3.id.as_str(), j3.attempts), (b.job_id.as_str(), 2), "every claim counts");
        finish_failed(&s.pool, &j3, "{\"status\":422}").await.unwrap();
        let v = get_version(&s.pool, &b.model_id, 1).await.unwrap().unwrap();
        assert_eq!((v.status.as_str(), v.error_json.as_deref()), ("failed", Some("{\"status\":422}")));
        assert!(mark_interrupted(&s.pool, &a.job_id).await.unwrap());
        assert_eq!(get_version(&s.pool, &a.model_id, 1).await.unwrap().unwrap().package_sha256, None);
        assert!(delete_model(&s.pool, &a.model_id).await.unwrap());
        assert!(get_job(&s.pool, &a.job_id).await.unwrap().is_none());
        assert_eq!(list_models(&s.pool).await.unwrap().len(), 1);
    }
}

