//! SQL for scenes (issue 29): a model's scene objects, one row per object by name.

use super::{now, Store, StoreError};
use cad2mo_engine::scene::{ObjectSpec, SceneSpec};

/// The stored scene of a model, in the user's order (empty when it has none).
pub async fn get(store: &Store, model_id: &str) -> Result<SceneSpec, StoreError> {
    let rows: Vec<(String, String)> =
        sqlx::query_as(&store.pool.sql("SELECT name, object_json FROM scene_objects WHERE model_id = ? ORDER BY ord, name"))
            .bind(model_id)
            .fetch_all(&store.pool)
            .await?;
    let objects = rows
        .into_iter()
        .map(|(name, text)| {
            serde_json::from_str::<ObjectSpec>(&text)
                .map_err(|e| StoreError::Corrupt(format!("scene object {name} of model {model_id}: {e}")))
        })
        .collect::<Result<_, _>>()?;
    Ok(SceneSpec { objects })
}

/// Replaces the scene of a model in one transaction (an empty scene removes every object).
pub async fn put(store: &Store, model_id: &str, scene: &SceneSpec) -> Result<(), StoreError> {
    let t = now(&store.pool).await?;
    let mut tx = store.pool.begin().await?;
    sqlx::query(&store.pool.sql("DELETE FROM scene_objects WHERE model_id = ?")).bind(model_id).execute(&mut *tx).await?;
    for (k, o) in scene.objects.iter().enumerate() {
        let text = serde_json::to_string(o).map_err(|e| StoreError::Corrupt(e.to_string()))?;
        sqlx::query(&store.pool.sql("INSERT INTO scene_objects (model_id, name, ord, object_json, updated_at) VALUES (?, ?, ?, ?, ?)"))
            .bind(model_id)
            .bind(&o.name)
            .bind(k as i64)
            .bind(text)
            .bind(&t)
            .execute(&mut *tx)
            .await?;
    }
    tx.commit().await?;
    Ok(())
}

/// A mesh uploaded for a model's scene.
#[derive(Clone, Debug, serde::Serialize)]
pub struct MeshRow {
    pub name: String,
    pub blob_sha256: String,
    pub triangles: i64,
}

/// Stores (or replaces) a scene mesh's row; its blob is stored first by the caller.
pub async fn put_mesh(store: &Store, model_id: &str, name: &str, blob_sha256: &str, triangles: i64) -> Result<(), StoreError> {
    let t = now(&store.pool).await?;
    let mut tx = store.pool.begin().await?;
    sqlx::query(&store.pool.sql("DELETE FROM scene_meshes WHERE model_id = ? AND name = ?"))
        .bind(model_id)
        .bind(name)
        .execute(&mut *tx)
        .await?;
    sqlx::query(&store.pool.sql("INSERT INTO scene_meshes (model_id, name, blob_sha256, triangles, updated_at) VALUES (?, ?, ?, ?, ?)"))
        .bind(model_id)
        .bind(name)
        .bind(blob_sha256)
        .bind(triangles)
        .bind(&t)
        .execute(&mut *tx)
        .await?;
    tx.commit().await?;
    Ok(())
}

/// The meshes uploaded for a model's scene, by name.
pub async fn meshes(store: &Store, model_id: &str) -> Result<Vec<MeshRow>, StoreError> {
    let rows: Vec<(String, String, i64)> =
        sqlx::query_as(&store.pool.sql("SELECT name, blob_sha256, triangles FROM scene_meshes WHERE model_id = ? ORDER BY name"))
            .bind(model_id)
            .fetch_all(&store.pool)
            .await?;
    Ok(rows.into_iter().map(|(name, blob_sha256, triangles)| MeshRow { name, blob_sha256, triangles }).collect())
}
