//! API tokens: only their SHA-256 is stored; the token itself is shown once, at creation.

use super::{now, Store, StoreError};
use crate::store::blobs::sha256_hex;

/// Creates a token named `name` and returns it (32 random bytes, hex).
pub async fn create(store: &Store, name: &str) -> Result<String, StoreError> {
    let token = format!("c2m_{}{}", uuid::Uuid::new_v4().simple(), uuid::Uuid::new_v4().simple());
    let created = now(&store.pool).await?;
    sqlx::query("INSERT INTO tokens (id, name, sha256, created_at) VALUES (?, ?, ?, ?)")
        .bind(uuid::Uuid::new_v4().to_string())
        .bind(name)
        .bind(sha256_hex(token.as_bytes()))
        .bind(created)
        .execute(&store.pool)
        .await?;
    Ok(token)
}

/// Whether `token` is a valid token.
pub async fn verify(store: &Store, token: &str) -> Result<bool, StoreError> {
    let row: Option<(String,)> = sqlx::query_as("SELECT id FROM tokens WHERE sha256 = ?")
        .bind(sha256_hex(token.as_bytes()))
        .fetch_optional(&store.pool)
        .await?;
    Ok(row.is_some())
}

/// The stored hashes (for tests and audits).
pub async fn hashes(store: &Store) -> Result<Vec<String>, StoreError> {
    let rows: Vec<(String,)> = sqlx::query_as("SELECT sha256 FROM tokens ORDER BY created_at").fetch_all(&store.pool).await?;
    Ok(rows.into_iter().map(|(h,)| h).collect())
}
