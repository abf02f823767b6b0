//! SQL for the allowed-collision matrix (issue 14): the user's edits, by pair of body names.

use super::{now, Store, StoreError};

/// A pair's names in storage order (`a < b`).
pub fn ordered<'a>(a: &'a str, b: &'a str) -> (&'a str, &'a str) {
    if a < b {
        (a, b)
    } else {
        (b, a)
    }
}

/// The edited pairs of a model: (a, b, allowed) with `a < b`.
pub async fn edits(store: &Store, model_id: &str) -> Result<Vec<(String, String, bool)>, StoreError> {
    let rows: Vec<(String, String, i64)> =
        sqlx::query_as(&store.pool.sql("SELECT body_a, body_b, allowed FROM collision_pairs WHERE model_id = ? ORDER BY body_a, body_b"))
            .bind(model_id)
            .fetch_all(&store.pool)
            .await?;
    Ok(rows.into_iter().map(|(a, b, x)| (a, b, x != 0)).collect())
}

/// Applies edits in one transaction: `Some(allowed)` sets a pair, `None` returns it to its default.
pub async fn apply(store: &Store, model_id: &str, changes: &[(String, String, Option<bool>)]) -> Result<(), StoreError> {
    let t = now(&store.pool).await?;
    let mut tx = store.pool.begin().await?;
    for (a, b, allowed) in changes {
        let (a, b) = ordered(a, b);
        match allowed {
            Some(x) => {
                sqlx::query(&store.pool.sql(
                    "INSERT INTO collision_pairs (model_id, body_a, body_b, allowed, updated_at) VALUES (?, ?, ?, ?, ?)
                     ON CONFLICT (model_id, body_a, body_b) DO UPDATE SET allowed = excluded.allowed, updated_at = excluded.updated_at",
                ))
                .bind(model_id)
                .bind(a)
                .bind(b)
                .bind(i64::from(*x))
                .bind(&t)
                .execute(&mut *tx)
                .await?;
            }
            None => {
                sqlx::query(&store.pool.sql("DELETE FROM collision_pairs WHERE model_id = ? AND body_a = ? AND body_b = ?"))
                    .bind(model_id)
                    .bind(a)
                    .bind(b)
                    .execute(&mut *tx)
                    .await?;
            }
        }
    }
    tx.commit().await?;
    Ok(())
}
