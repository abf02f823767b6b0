//! SQL for joint limits and motions (issue 12).

use std::collections::BTreeMap;

use serde::Serialize;

use super::{now, Store, StoreError};
use cad2mo_engine::motion::plan::{LimitsEdit, MotionSpec};

/// The limit edits of a model, by joint.
pub async fn limits(store: &Store, model_id: &str) -> Result<BTreeMap<String, LimitsEdit>, StoreError> {
    let rows: Vec<(String, String)> =
        sqlx::query_as(&store.pool.sql("SELECT joint, limits_json FROM joint_limits WHERE model_id = ? ORDER BY joint"))
            .bind(model_id)
            .fetch_all(&store.pool)
            .await?;
    rows.into_iter()
        .map(|(j, text)| {
            let e: LimitsEdit = serde_json::from_str(&text).map_err(|e| StoreError::Corrupt(format!("limits of {j}: {e}")))?;
            Ok((j, e))
        })
        .collect()
}

/// Inserts or replaces the limits of `joint`.
pub async fn put_limits(store: &Store, model_id: &str, joint: &str, e: &LimitsEdit) -> Result<(), StoreError> {
    let t = now(&store.pool).await?;
    sqlx::query(&store.pool.sql(
        "INSERT INTO joint_limits (model_id, joint, limits_json, updated_at) VALUES (?, ?, ?, ?)
         ON CONFLICT (model_id, joint) DO UPDATE SET limits_json = excluded.limits_json, updated_at = excluded.updated_at",
    ))
    .bind(model_id)
    .bind(joint)
    .bind(serde_json::to_string(e).map_err(|e| StoreError::Corrupt(e.to_string()))?)
    .bind(t)
    .execute(&store.pool)
    .await?;
    Ok(())
}

/// Removes the limits of `joint`; false when there were none.
pub async fn delete_limits(store: &Store, model_id: &str, joint: &str) -> Result<bool, StoreError> {
    let r = sqlx::query(&store.pool.sql("DELETE FROM joint_limits WHERE model_id = ? AND joint = ?"))
        .bind(model_id)
        .bind(joint)
        .execute(&store.pool)
        .await?;
    Ok(r.rows_affected() > 0)
}

/// A stored motion.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Motion {
    pub id: String,
    pub name: String,
    pub spec: MotionSpec,
    pub created_at: String,
    pub updated_at: String,
}

type Row = (String, String, String, String, String);
const COLUMNS: &str = "id, name, spec_json, created_at, updated_at";

fn from_row((id, name, spec, created_at, updated_at): Row) -> Result<Motion, StoreError> {
    let spec: MotionSpec = serde_json::from_str(&spec).map_err(|e| StoreError::Corrupt(format!("motion {id}: {e}")))?;
    Ok(Motion { id, name, spec, created_at, updated_at })
}

/// The motions of a model, oldest first.
pub async fn list(store: &Store, model_id: &str) -> Result<Vec<Motion>, StoreError> {
    let rows: Vec<Row> =
        sqlx::query_as(&store.pool.sql(format!("SELECT {COLUMNS} FROM motions WHERE model_id = ? ORDER BY created_at, rowid")))
            .bind(model_id)
            .fetch_all(&store.pool)
            .await?;
    rows.into_iter().map(from_row).collect()
}

pub async fn get(store: &Store, model_id: &str, id: &str) -> Result<Option<Motion>, StoreError> {
    let row: Option<Row> = sqlx::query_as(&store.pool.sql(format!("SELECT {COLUMNS} FROM motions WHERE model_id = ? AND id = ?")))
        .bind(model_id)
        .bind(id)
        .fetch_optional(&store.pool)
        .await?;
    row.map(from_row).transpose()
}

/// Stores a new motion (the name must be new in the model: a unique violation otherwise).
pub async fn create(store: &Store, model_id: &str, spec: &MotionSpec) -> Result<Motion, StoreError> {
    let t = now(&store.pool).await?;
    let id = uuid::Uuid::new_v4().to_string();
    sqlx::query(&store.pool.sql("INSERT INTO motions (id, model_id, name, spec_json, created_at, updated_at) VALUES (?, ?, ?, ?, ?, ?)"))
        .bind(&id)
        .bind(model_id)
        .bind(&spec.name)
        .bind(serde_json::to_string(spec).map_err(|e| StoreError::Corrupt(e.to_string()))?)
        .bind(&t)
        .bind(&t)
        .execute(&store.pool)
        .await?;
    Ok(Motion { id, name: spec.name.clone(), spec: spec.clone(), created_at: t.clone(), updated_at: t })
}

/// Replaces a motion; `None` when it does not exist.
pub async fn update(store: &Store, model_id: &str, id: &str, spec: &MotionSpec) -> Result<Option<Motion>, StoreError> {
    let t = now(&store.pool).await?;
    let r = sqlx::query(&store.pool.sql("UPDATE motions SET name = ?, spec_json = ?, updated_at = ? WHERE model_id = ? AND id = ?"))
        .bind(&spec.name)
        .bind(serde_json::to_string(spec).map_err(|e| StoreError::Corrupt(e.to_string()))?)
        .bind(&t)
        .bind(model_id)
        .bind(id)
        .execute(&store.pool)
        .await?;
    if r.rows_affected() == 0 {
        return Ok(None);
    }
    get(store, model_id, id).await
}

/// Removes a motion; false when there was none.
pub async fn delete(store: &Store, model_id: &str, id: &str) -> Result<bool, StoreError> {
    let r = sqlx::query(&store.pool.sql("DELETE FROM motions WHERE model_id = ? AND id = ?"))
        .bind(model_id)
        .bind(id)
        .execute(&store.pool)
        .await?;
    Ok(r.rows_affected() > 0)
}
