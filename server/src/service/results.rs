//! Simulation results: a result file read, checked and summarised before anything is stored
//! (for a version of a model, against its mechanism, or standalone), the stored results, and
//! work on a stored file. No HTTP, no SQL: the rows are `store::results`'.

use cad2mo_engine::results::{self, mat::Trajectory};

use super::blocking;
use crate::store::blobs::Blobs;
use crate::store::results::ResultRow;
use crate::store::{self, Store, StoreError};

/// Why a result use case failed.
#[derive(Debug, thiserror::Error)]
pub enum ResultError {
    /// The uploaded file is no result we can read (not MAT v4, truncated, non-finite values,
    /// nothing of the version's model in it): `name` is the file, `message` says why.
    #[error("{message}")]
    Unreadable { name: String, message: String },
    /// The result, or something it was asked for (a variable), does not exist.
    #[error("{0} not found")]
    NotFound(String),
    #[error(transparent)]
    Store(#[from] StoreError),
    /// The file store failed or a stored file no longer reads (not the user's fault).
    #[error("internal error")]
    Internal(#[from] anyhow::Error),
}

/// A stored result with its summary.
pub struct Stored {
    pub row: ResultRow,
    pub summary: results::Summary,
}

impl TryFrom<ResultRow> for Stored {
    type Error = ResultError;

    fn try_from(row: ResultRow) -> Result<Stored, ResultError> {
        let summary = serde_json::from_str(&row.summary_json)
            .map_err(|e| ResultError::Internal(anyhow::anyhow!("summary of result {}: {e}", row.id)))?;
        Ok(Stored { row, summary })
    }
}

/// Reads the file `name` (refused when it is not a finite result), summarises it with
/// `summarise`, then stores the file and its row: nothing is stored for a refused file.
pub async fn upload(
    store: &Store,
    blobs: &Blobs,
    owner: Option<(&str, i64)>,
    name: String,
    bytes: Vec<u8>,
    summarise: impl FnOnce(&Trajectory, &str) -> Result<results::Summary, String> + Send + 'static,
) -> Result<Stored, ResultError> {
    let blobs = blobs.clone();
    let (name, bytes, summary, sha) = blocking(move || {
        let unreadable = |message: String| ResultError::Unreadable { name: name.clone(), message };
        let t = Trajectory::read(&bytes, &name).map_err(|e| unreadable(e.to_string()))?;
        t.check_finite(&name).map_err(|e| unreadable(e.to_string()))?;
        let summary = summarise(&t, &name).map_err(unreadable)?;
        let sha = blobs.put(&bytes).map_err(|e| ResultError::Internal(e.into()))?;
        Ok::<_, ResultError>((name, bytes, summary, sha))
    })
    .await?;
    let summary_json = serde_json::to_string(&summary).map_err(|e| ResultError::Internal(e.into()))?;
    // Stored only when it reads back (a summary that cannot be served is never stored).
    serde_json::from_str::<results::Summary>(&summary_json)
        .map_err(|e| ResultError::Internal(anyhow::anyhow!("summary of {name}: {e}")))?;
    let (model_id, version) = (owner.map(|o| o.0), owner.map(|o| o.1));
    let row = store::results::insert(store, model_id, version, &name, bytes.len() as i64, &sha, &summary_json).await?;
    Stored::try_from(row)
}

/// The rows that can be served: one stored before its summary was checked and that no longer
/// reads is left out of the list (logged with its id; it answers alone at its own URL and can
/// be deleted), never failing the list for everyone.
fn servable(rows: Vec<ResultRow>) -> Vec<Stored> {
    rows.into_iter()
        .filter_map(|r| {
            let id = r.id.clone();
            Stored::try_from(r).map_err(|e| tracing::warn!(result = %id, error = %e, "a stored result cannot be listed")).ok()
        })
        .collect()
}

/// The results of no model.
pub async fn list_standalone(store: &Store) -> Result<Vec<Stored>, ResultError> {
    Ok(servable(store::results::list_standalone(store).await?))
}

/// The results of version `version` of model `model_id`.
pub async fn list(store: &Store, model_id: &str, version: i64) -> Result<Vec<Stored>, ResultError> {
    let versions = store::models::list_versions(&store.pool, model_id).await?;
    if !versions.iter().any(|v| v.version == version) {
        return Err(ResultError::NotFound(format!("version {version} of model {model_id}")));
    }
    Ok(servable(store::results::list(store, model_id, version).await?))
}

/// Result `id`'s row.
pub async fn find(store: &Store, id: &str) -> Result<ResultRow, ResultError> {
    store::results::get(store, id).await?.ok_or_else(|| ResultError::NotFound(format!("result {id}")))
}

/// Deletes result `id`.
pub async fn delete(store: &Store, id: &str) -> Result<(), ResultError> {
    if store::results::delete(store, id).await? {
        Ok(())
    } else {
        Err(ResultError::NotFound(format!("result {id}")))
    }
}

/// Runs `f` on the stored file of result `row`, off the runtime.
pub async fn with_file<T: Send + 'static>(
    blobs: &Blobs,
    row: ResultRow,
    f: impl FnOnce(&Trajectory) -> Result<T, ResultError> + Send + 'static,
) -> Result<T, ResultError> {
    let blobs = blobs.clone();
    blocking(move || {
        let bytes = blobs
            .get(&row.blob_sha256)
            .map_err(|e| ResultError::Internal(e.into()))?
            .ok_or_else(|| ResultError::Internal(anyhow::anyhow!("the file of result {} is missing", row.id)))?;
        let t = Trajectory::read(&bytes, &row.name).map_err(|e| ResultError::Internal(anyhow::anyhow!("stored result: {e}")))?;
        f(&t)
    })
    .await
}
