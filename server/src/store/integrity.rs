//! Consistency of the database and the blob store: which blobs rows refer to, and a check that
//! reads every stored blob (its hash verified) and reports referenced blobs that are missing or
//! corrupt, and stored blobs that no row refers to (orphans).
//!
//! Orphans are expected in two cases and harmless in both (blobs are content-addressed, so a
//! later upload or conversion of the same bytes reuses them): a model or version deleted (its
//! blobs stay, they may be shared), and a write interrupted between the blob and its row (an
//! upload whose row insert failed, a conversion killed after storing its package and before
//! recording it). Missing or corrupt referenced blobs are never expected.

use std::collections::BTreeSet;

use super::blobs::Blobs;
use super::{Store, StoreError};

/// Every blob hash a row refers to: versions' bundles, packages and reports, result files, scene
/// meshes.
/// Read-only.
pub async fn referenced_blobs(store: &Store) -> Result<BTreeSet<String>, StoreError> {
    let rows: Vec<(Option<String>,)> = sqlx::query_as(
        "SELECT bundle_sha256 FROM versions
         UNION SELECT package_sha256 FROM versions
         UNION SELECT report_sha256 FROM versions
         UNION SELECT blob_sha256 FROM results
         UNION SELECT blob_sha256 FROM scene_meshes",
    )
    .fetch_all(&store.pool)
    .await?;
    Ok(rows.into_iter().filter_map(|(h,)| h).collect())
}

/// How often each job was claimed and where it stands: `(status, attempts)` by job id. A job
/// converted exactly once is `succeeded` with one attempt. Read-only.
pub async fn job_attempts(store: &Store) -> Result<std::collections::BTreeMap<String, (String, i64)>, StoreError> {
    let rows: Vec<(String, String, i64)> = sqlx::query_as("SELECT id, status, attempts FROM jobs").fetch_all(&store.pool).await?;
    Ok(rows.into_iter().map(|(id, status, attempts)| (id, (status, attempts))).collect())
}

/// What [`check`] found.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct BlobReport {
    /// Blobs in the store.
    pub stored: usize,
    /// Hashes rows refer to.
    pub referenced: usize,
    /// Referenced, not stored.
    pub missing: Vec<String>,
    /// Stored (referenced or not) with bytes that do not hash to their name, or unreadable.
    pub corrupt: Vec<String>,
    /// Stored, referenced by no row.
    pub orphans: Vec<String>,
}

impl BlobReport {
    /// Every referenced blob is there, whole.
    pub fn is_consistent(&self) -> bool {
        self.missing.is_empty() && self.corrupt.is_empty()
    }
}

/// Lists the blob store, reads and verifies every blob, and compares with the rows' references.
/// Reads everything once: for tests and operators, not for a request path.
pub async fn check(store: &Store, blobs: &Blobs) -> Result<BlobReport, StoreError> {
    let referenced = referenced_blobs(store).await?;
    let blobs = blobs.clone();
    let (stored, corrupt) = tokio::task::spawn_blocking(move || {
        let stored = blobs.list()?;
        let corrupt: Vec<String> = stored.iter().filter(|h| !matches!(blobs.get(h), Ok(Some(_)))).cloned().collect();
        Ok::<_, std::io::Error>((stored, corrupt))
    })
    .await
    .map_err(|e| StoreError::Io(std::io::Error::other(e)))??;
    let stored_set: BTreeSet<&String> = stored.iter().collect();
    Ok(BlobReport {
        stored: stored.len(),
        referenced: referenced.len(),
        missing: referenced.iter().filter(|h| !stored_set.contains(h)).cloned().collect(),
        orphans: stored.iter().filter(|h| !referenced.contains(*h)).cloned().collect(),
        corrupt,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::store::models::{self, NewVersion};

    #[tokio::test]
    async fn check_reports_missing_corrupt_and_orphans() {
        let dir = tempfile::tempdir().unwrap();
        let store = Store::open(&format!("sqlite://{}?mode=rwc", dir.path().join("t.db").display())).await.unwrap();
        let blobs = Blobs::new(dir.path()).unwrap();
        let bundle = blobs.put(b"bundle bytes").unwrap();
        fn v(sha: &str) -> NewVersion<'_> {
            NewVersion { bundle_name: "b.zip", bundle_sha256: sha, bundle_size: 1, options_json: "{}", triangles: None, bundle_bytes: None }
        }
        models::create_model(&store.pool, "m", &v(&bundle)).await.unwrap();
        let r = check(&store, &blobs).await.unwrap();
        assert_eq!(r, BlobReport { stored: 1, referenced: 1, ..Default::default() });
        let jobs = job_attempts(&store).await.unwrap();
        assert_eq!(jobs.values().cloned().collect::<Vec<_>>(), vec![("queued".to_string(), 0)]);
        assert!(r.is_consistent());

        // A row pointing at a blob that is not stored: missing.
        let absent = crate::store::blobs::sha256_hex(b"never stored");
        models::create_model(&store.pool, "m2", &v(&absent)).await.unwrap();
        // A blob no row points at: an orphan.
        let orphan = blobs.put(b"left over").unwrap();
        let r = check(&store, &blobs).await.unwrap();
        assert_eq!((r.missing.clone(), r.orphans.clone(), r.corrupt.clone()), (vec![absent], vec![orphan], vec![]));
        assert!(!r.is_consistent());

        // A converted version's package and report, and a result file, are referenced too.
        let claimer = models::Claimer { instance: "test".into(), lease_secs: 30.0 };
        let job = models::claim_next_job(&store.pool, &claimer).await.unwrap().unwrap();
        let (package, report, result) = (blobs.put(b"package").unwrap(), blobs.put(b"report").unwrap(), blobs.put(b"result").unwrap());
        let out = models::JobOutputs { package_sha256: &package, report_sha256: &report, summary_json: "{}" };
        models::finish_succeeded(&store.pool, &job, &out).await.unwrap();
        crate::store::results::insert(&store, None, None, "r.mat", 6, &result, "{}").await.unwrap();
        let referenced = referenced_blobs(&store).await.unwrap();
        for h in [&bundle, &package, &report, &result] {
            assert!(referenced.contains(h), "{h} is not counted as referenced");
        }
        let r = check(&store, &blobs).await.unwrap();
        assert_eq!((r.stored, r.orphans.len()), (5, 1), "{r:?}");

        // A referenced blob whose bytes changed: corrupt.
        std::fs::write(dir.path().join("blobs").join(&bundle[..2]).join(&bundle), b"bundle bytez").unwrap();
        let r = check(&store, &blobs).await.unwrap();
        assert_eq!(r.corrupt, vec![bundle]);
    }
}
