//! SQL for simulation results (issue 13).

use super::{now, Store, StoreError};

/// A stored result row.
#[derive(Clone, Debug, PartialEq)]
pub struct ResultRow {
    pub id: String,
    /// `None` for a standalone result.
    pub model_id: Option<String>,
    pub version: Option<i64>,
    pub name: String,
    pub size: i64,
    pub blob_sha256: String,
    pub summary_json: String,
    pub created_at: String,
}

type Row = (String, Option<String>, Option<i64>, String, i64, String, String, String);
const COLUMNS: &str = "id, model_id, version, name, size, blob_sha256, summary_json, created_at";

fn from_row((id, model_id, version, name, size, blob_sha256, summary_json, created_at): Row) -> ResultRow {
    ResultRow { id, model_id, version, name, size, blob_sha256, summary_json, created_at }
}

/// Stores a result (the blob is already written); returns its row.
pub async fn insert(
    store: &Store,
    model_id: Option<&str>,
    version: Option<i64>,
    name: &str,
    size: i64,
    blob_sha256: &str,
    summary_json: &str,
) -> Result<ResultRow, StoreError> {
    let t = now(&store.pool).await?;
    let id = uuid::Uuid::new_v4().to_string();
    sqlx::query(&store.pool.sql(format!("INSERT INTO results ({COLUMNS}) VALUES (?, ?, ?, ?, ?, ?, ?, ?)")))
        .bind(&id)
        .bind(model_id)
        .bind(version)
        .bind(name)
        .bind(size)
        .bind(blob_sha256)
        .bind(summary_json)
        .bind(&t)
        .execute(&store.pool)
        .await?;
    Ok(ResultRow {
        id,
        model_id: model_id.map(str::to_string),
        version,
        name: name.into(),
        size,
        blob_sha256: blob_sha256.into(),
        summary_json: summary_json.into(),
        created_at: t,
    })
}

/// The results of a model version, oldest first.
pub async fn list(store: &Store, model_id: &str, version: i64) -> Result<Vec<ResultRow>, StoreError> {
    let rows: Vec<Row> = sqlx::query_as(
        &store.pool.sql(format!("SELECT {COLUMNS} FROM results WHERE model_id = ? AND version = ? ORDER BY created_at, rowid")),
    )
    .bind(model_id)
    .bind(version)
    .fetch_all(&store.pool)
    .await?;
    Ok(rows.into_iter().map(from_row).collect())
}

/// The standalone results (no model), oldest first.
pub async fn list_standalone(store: &Store) -> Result<Vec<ResultRow>, StoreError> {
    let rows: Vec<Row> =
        sqlx::query_as(&store.pool.sql(format!("SELECT {COLUMNS} FROM results WHERE model_id IS NULL ORDER BY created_at, rowid")))
            .fetch_all(&store.pool)
            .await?;
    Ok(rows.into_iter().map(from_row).collect())
}

pub async fn get(store: &Store, id: &str) -> Result<Option<ResultRow>, StoreError> {
    let row: Option<Row> =
        sqlx::query_as(&store.pool.sql(format!("SELECT {COLUMNS} FROM results WHERE id = ?"))).bind(id).fetch_optional(&store.pool).await?;
    Ok(row.map(from_row))
}

/// Removes a result; false when there was none. (Its blob stays: blobs are content-addressed and
/// may be shared.)
pub async fn delete(store: &Store, id: &str) -> Result<bool, StoreError> {
    let r = sqlx::query(&store.pool.sql("DELETE FROM results WHERE id = ?")).bind(id).execute(&store.pool).await?;
    Ok(r.rows_affected() > 0)
}
