//! Models and their versions: an upload checked and stored, a new model or version queued for
//! conversion, the stored versions and their outputs (package, report, bundle), the diff of two
//! versions. No HTTP: `api::models` parses the multipart upload and answers; no SQL: the rows
//! are `store::models`'.
//!
//! An upload is analysed at once, off the runtime, at most `max_checks` at a time (a check holds
//! the bundle analysed in memory, many times its size): beyond that, after `check_wait`, it is
//! [`ModelError::Busy`]. An unreadable bundle or bad XML is [`ModelError::Export`]; nothing is
//! stored then. Otherwise the bundle blob is stored, then the model/version/job rows in one
//! transaction, and the workers are woken.

use std::sync::Arc;
use std::time::Duration;

use serde_json::Value;
use tokio::sync::Semaphore;

use super::blocking;
use super::export::{self, ExportError, ExportOptions, Summary};
use crate::jobs::Jobs;
use crate::store::blobs::Blobs;
use crate::store::models::{self as db, Created, ModelRow, NewVersion, VersionRow};
use crate::store::{Store, StoreError};

/// Seconds to wait before retrying when every upload check is busy.
pub const RETRY_AFTER_SECS: u64 = 3;

/// Why a model use case failed.
#[derive(Debug, thiserror::Error)]
pub enum ModelError {
    /// The model or version does not exist (the text names it).
    #[error("{0} not found")]
    NotFound(String),
    /// Every upload check is taken; nothing was stored.
    #[error("too many uploads are being checked right now; retry in {retry_after} s")]
    Busy { retry_after: u64 },
    /// The version has no such output (yet): the text says why.
    #[error("{0}")]
    Conflict(String),
    /// The bundle does not read or analyse; nothing was stored.
    #[error(transparent)]
    Export(#[from] ExportError),
    #[error(transparent)]
    Store(#[from] StoreError),
    /// The file store failed or holds something corrupt (not the user's fault).
    #[error("internal error")]
    Internal(#[from] anyhow::Error),
}

/// The service's upload checks: at most the semaphore's permits at once, waiting `wait` for one.
#[derive(Clone, Copy)]
pub struct Checks<'a> {
    pub permits: &'a Arc<Semaphore>,
    pub wait: Duration,
}

/// What the use cases of this module work with.
#[derive(Clone, Copy)]
pub struct Ctx<'a> {
    pub store: &'a Store,
    pub blobs: &'a Blobs,
    pub jobs: &'a Jobs,
    pub checks: Checks<'a>,
}

/// An upload: the bundle zip, its file name, the conversion options and (for a new model) a
/// name other than the assembly's.
pub struct Upload {
    pub bundle: Vec<u8>,
    pub bundle_name: String,
    pub name: Option<String>,
    pub options: ExportOptions,
}

/// Checks the bundle and stores its blob. Returns the upload, its blob hash and what the check
/// found (the model name the bundle gives, its size for the job's memory estimate). The permit moves into the blocking task, so a client that hangs up does
/// not free it before its check has really finished.
async fn check_and_store(ctx: Ctx<'_>, upload: Upload) -> Result<(Upload, String, export::Checked), ModelError> {
    let permit = match tokio::time::timeout(ctx.checks.wait, ctx.checks.permits.clone().acquire_owned()).await {
        Ok(Ok(permit)) => permit,
        Ok(Err(_)) | Err(_) => {
            tracing::warn!("upload refused: every check is busy");
            return Err(ModelError::Busy { retry_after: RETRY_AFTER_SECS });
        }
    };
    let blobs = ctx.blobs.clone();
    let steps = ctx.jobs.step_cache();
    blocking(move || {
        let _permit = permit;
        let checked = export::check_bundle(&upload.bundle, &upload.bundle_name, &upload.options, Some(steps))?;
        let sha = blobs.put(&upload.bundle).map_err(|e| anyhow::Error::new(e).context("storing the bundle"))?;
        Ok((upload, sha, checked))
    })
    .await
}

fn new_version<'u>(upload: &'u Upload, sha: &'u str, options: &'u str, checked: &export::Checked) -> NewVersion<'u> {
    NewVersion {
        bundle_name: &upload.bundle_name,
        bundle_sha256: sha,
        bundle_size: i64::try_from(upload.bundle.len()).unwrap_or(i64::MAX),
        options_json: options,
        triangles: Some(i64::try_from(checked.triangles).unwrap_or(i64::MAX)),
        bundle_bytes: Some(i64::try_from(checked.bundle_bytes).unwrap_or(i64::MAX)),
    }
}

fn options_json(o: &ExportOptions) -> Result<String, ModelError> {
    serde_json::to_string(o).map_err(|e| ModelError::Internal(e.into()))
}

/// A new model from its first upload (named `upload.name`, else as the bundle's assembly).
pub async fn create_model(ctx: Ctx<'_>, upload: Upload) -> Result<Created, ModelError> {
    let (upload, sha, checked) = check_and_store(ctx, upload).await?;
    let name = upload.name.clone().unwrap_or_else(|| checked.model_name.clone());
    let options = options_json(&upload.options)?;
    let created = db::create_model(&ctx.store.pool, &name, &new_version(&upload, &sha, &options, &checked)).await?;
    ctx.jobs.notify();
    Ok(created)
}

/// A new version of model `id` (refused before the analysis when the model is unknown).
pub async fn create_version(ctx: Ctx<'_>, id: &str, upload: Upload) -> Result<Created, ModelError> {
    model(ctx.store, id).await?;
    let (upload, sha, checked) = check_and_store(ctx, upload).await?;
    let options = options_json(&upload.options)?;
    let created = db::create_version(&ctx.store.pool, id, &new_version(&upload, &sha, &options, &checked))
        .await?
        .ok_or_else(|| ModelError::NotFound(format!("model {id}")))?;
    ctx.jobs.notify();
    Ok(created)
}

/// Model `id`.
pub async fn model(store: &Store, id: &str) -> Result<ModelRow, ModelError> {
    db::get_model(&store.pool, id).await?.ok_or_else(|| ModelError::NotFound(format!("model {id}")))
}

/// Every version of model `id`, oldest first.
pub async fn versions(store: &Store, id: &str) -> Result<Vec<VersionRow>, ModelError> {
    Ok(db::list_versions(&store.pool, id).await?)
}

/// Version `v` of model `id`.
pub async fn version(store: &Store, id: &str, v: i64) -> Result<VersionRow, ModelError> {
    db::get_version(&store.pool, id, v).await?.ok_or_else(|| ModelError::NotFound(format!("version {v} of model {id}")))
}

/// Deletes model `id` with its versions, jobs and drives.
pub async fn delete_model(store: &Store, id: &str) -> Result<(), ModelError> {
    if !db::delete_model(&store.pool, id).await? {
        return Err(ModelError::NotFound(format!("model {id}")));
    }
    tracing::info!(model_id = %id, "model deleted");
    Ok(())
}

/// Deletes version `v` of model `id`.
pub async fn delete_version(store: &Store, id: &str, v: i64) -> Result<(), ModelError> {
    if !db::delete_version(&store.pool, id, v).await? {
        return Err(ModelError::NotFound(format!("version {v} of model {id}")));
    }
    tracing::info!(model_id = %id, version = v, "version deleted");
    Ok(())
}

/// A blob the database refers to (missing is the file store's fault, not the user's).
pub async fn read_blob(blobs: &Blobs, hash: String) -> Result<Vec<u8>, ModelError> {
    let blobs = blobs.clone();
    blocking(move || {
        blobs
            .get(&hash)
            .map_err(|e| ModelError::Internal(e.into()))?
            .ok_or_else(|| ModelError::Internal(anyhow::anyhow!("blob {hash} is missing from the file store")))
    })
    .await
}

/// The version's outputs once converted: (package hash, report hash).
pub fn outputs(v: &VersionRow) -> Option<(String, String)> {
    match (v.status.as_str(), &v.package_sha256, &v.report_sha256) {
        ("succeeded", Some(p), Some(r)) => Some((p.clone(), r.clone())),
        _ => None,
    }
}

/// An output of a version, or the version itself when it has none (yet): converting, or failed
/// with its stored problem.
pub enum Output<T> {
    Ready(T),
    NotConverted(Box<VersionRow>),
}

/// A version's stored package.
pub struct Package {
    pub bytes: Vec<u8>,
    /// The package name (the file stem of downloads).
    pub stem: String,
    /// Its blob hash.
    pub sha256: String,
}

/// Version `v`'s package.
pub async fn package(store: &Store, blobs: &Blobs, id: &str, v: i64) -> Result<Output<Package>, ModelError> {
    let row = version(store, id, v).await?;
    let Some((package, _)) = outputs(&row) else { return Ok(Output::NotConverted(Box::new(row))) };
    let bytes = read_blob(blobs, package.clone()).await?;
    let summary: Option<Summary> = row.summary_json.as_deref().and_then(|s| serde_json::from_str(s).ok());
    let stem = summary.map_or_else(|| "package".to_string(), |s| s.package_name);
    Ok(Output::Ready(Package { bytes, stem, sha256: package }))
}

/// Version `v`'s report.json: (bytes, blob hash).
pub async fn report(store: &Store, blobs: &Blobs, id: &str, v: i64) -> Result<Output<(Vec<u8>, String)>, ModelError> {
    let row = version(store, id, v).await?;
    let Some((_, report)) = outputs(&row) else { return Ok(Output::NotConverted(Box::new(row))) };
    let bytes = read_blob(blobs, report.clone()).await?;
    Ok(Output::Ready((bytes, report)))
}

/// Version `v`'s uploaded bundle, byte for byte, with its row (file name, hash).
pub async fn bundle(store: &Store, blobs: &Blobs, id: &str, v: i64) -> Result<(Vec<u8>, VersionRow), ModelError> {
    let row = version(store, id, v).await?;
    let bytes = read_blob(blobs, row.bundle_sha256.clone()).await?;
    Ok((bytes, row))
}

/// The parsed report of a converted version; [`ModelError::Conflict`] when it has none.
async fn converted_report(store: &Store, blobs: &Blobs, id: &str, v: i64) -> Result<Value, ModelError> {
    let row = version(store, id, v).await?;
    let Some((_, report)) = outputs(&row) else {
        return Err(ModelError::Conflict(format!("version {v} of model {id} has no report to compare (status {})", row.status)));
    };
    let bytes = read_blob(blobs, report).await?;
    serde_json::from_slice(&bytes).map_err(|e| ModelError::Internal(anyhow::anyhow!("stored report is corrupt: {e}")))
}

/// What changed from version `from` to version `to` of model `id` (both converted).
pub async fn diff(store: &Store, blobs: &Blobs, id: &str, from: i64, to: i64) -> Result<cad2mo_engine::diff::Diff, ModelError> {
    model(store, id).await?;
    let old = converted_report(store, blobs, id, from).await?;
    let new = converted_report(store, blobs, id, to).await?;
    blocking(move || Ok(cad2mo_engine::diff::diff(&old, &new))).await
}
