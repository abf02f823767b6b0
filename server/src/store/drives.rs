//! SQL for drive assignments.

use serde_json::{Map, Value as Json};

use super::{now, Store, StoreError};
use crate::service::drives::{Assignment, ReferenceSpec};

type Row = (String, String, String, String, String, String, String);

fn from_row(r: Row) -> Result<Assignment, StoreError> {
    let (joint, joint_node_id, motor_instance, gear_instance, controller_instance, overrides, reference) = r;
    let overrides: Map<String, Json> =
        serde_json::from_str(&overrides).map_err(|e| StoreError::Corrupt(format!("drive {joint} overrides: {e}")))?;
    let reference: ReferenceSpec =
        serde_json::from_str(&reference).map_err(|e| StoreError::Corrupt(format!("drive {joint} reference: {e}")))?;
    Ok(Assignment { joint, joint_node_id, motor_instance, gear_instance, controller_instance, overrides, reference })
}

const COLUMNS: &str = "joint, joint_node_id, motor_instance, gear_instance, controller_instance, overrides_json, reference_json";

pub async fn list(store: &Store, model_id: &str) -> Result<Vec<Assignment>, StoreError> {
    let rows: Vec<Row> = sqlx::query_as(&store.pool.sql(format!("SELECT {COLUMNS} FROM drives WHERE model_id = ? ORDER BY joint")))
        .bind(model_id)
        .fetch_all(&store.pool)
        .await?;
    rows.into_iter().map(from_row).collect()
}

pub async fn get(store: &Store, model_id: &str, joint: &str) -> Result<Option<Assignment>, StoreError> {
    let row: Option<Row> = sqlx::query_as(&store.pool.sql(format!("SELECT {COLUMNS} FROM drives WHERE model_id = ? AND joint = ?")))
        .bind(model_id)
        .bind(joint)
        .fetch_optional(&store.pool)
        .await?;
    row.map(from_row).transpose()
}

/// Inserts or replaces the assignment of `a.joint`.
pub async fn put(store: &Store, model_id: &str, a: &Assignment) -> Result<(), StoreError> {
    let t = now(&store.pool).await?;
    sqlx::query(&store.pool.sql(
        "INSERT INTO drives (model_id, joint, joint_node_id, motor_instance, gear_instance, controller_instance, overrides_json, reference_json, updated_at)
         VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)
         ON CONFLICT (model_id, joint) DO UPDATE SET
           joint_node_id = excluded.joint_node_id, motor_instance = excluded.motor_instance,
           gear_instance = excluded.gear_instance, controller_instance = excluded.controller_instance,
           overrides_json = excluded.overrides_json, reference_json = excluded.reference_json,
           updated_at = excluded.updated_at",
    ))
    .bind(model_id)
    .bind(&a.joint)
    .bind(&a.joint_node_id)
    .bind(&a.motor_instance)
    .bind(&a.gear_instance)
    .bind(&a.controller_instance)
    .bind(Json::Object(a.overrides.clone()).to_string())
    .bind(serde_json::to_string(&a.reference).map_err(|e| StoreError::Corrupt(e.to_string()))?)
    .bind(t)
    .execute(&store.pool)
    .await?;
    Ok(())
}

/// Removes an assignment; false when there was none.
pub async fn delete(store: &Store, model_id: &str, joint: &str) -> Result<bool, StoreError> {
    let r = sqlx::query(&store.pool.sql("DELETE FROM drives WHERE model_id = ? AND joint = ?"))
        .bind(model_id)
        .bind(joint)
        .execute(&store.pool)
        .await?;
    Ok(r.rows_affected() > 0)
}
