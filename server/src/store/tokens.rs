//! API tokens: only their SHA-256 is stored; the token itself is shown once, at creation. A token
//! may expire (`expires_at`, checked by [`verify`] against the database's clock).

use super::{now, Engine, Store, StoreError};
use crate::store::blobs::sha256_hex;

/// The database's clock as RFC 3339 UTC with milliseconds (the format of `created_at`; expanded by `sql`).
const NOW: &str = "%NOW%";

/// A stored token as `cad2mo token list` shows it: never the token, only the end of its hash.
#[derive(Debug, Clone, PartialEq)]
pub struct TokenInfo {
    pub id: String,
    pub name: String,
    pub created_at: String,
    pub expires_at: Option<String>,
    pub sha256: String,
    /// Whether `expires_at` has passed.
    pub expired: bool,
}

/// What [`revoke`] did.
#[derive(Debug, Clone, PartialEq)]
pub enum Revoked {
    /// The token with this id (or the one token with this name) was deleted.
    One(TokenInfo),
    NotFound,
    /// Several tokens have this name: revoke one by id.
    Ambiguous(Vec<TokenInfo>),
}

/// Creates a token named `name`, valid for `expires_in_secs` (forever when `None`), and returns
/// it (`c2m_` and 64 random hex digits).
pub async fn create(store: &Store, name: &str, expires_in_secs: Option<u64>) -> Result<String, StoreError> {
    let token = format!("c2m_{}{}", uuid::Uuid::new_v4().simple(), uuid::Uuid::new_v4().simple());
    let created = now(&store.pool).await?;
    let expires =
        match expires_in_secs {
            Some(secs) => {
                let secs = i64::try_from(secs).map_err(|_| StoreError::Corrupt("expiry out of range".into()))?;
                let (t,): (Option<String>,) = match store.pool.engine() {
                Engine::Sqlite => sqlx::query_as("SELECT strftime('%Y-%m-%dT%H:%M:%fZ', ?, ?)")
                    .bind(&created)
                    .bind(format!("+{secs} seconds"))
                    .fetch_one(&store.pool)
                    .await?,
                Engine::Postgres => sqlx::query_as(
                    r#"SELECT to_char(($1::timestamptz + $2 * interval '1 second') AT TIME ZONE 'UTC', 'YYYY-MM-DD"T"HH24:MI:SS.MS"Z"')"#,
                )
                .bind(&created)
                .bind(secs as f64)
                .fetch_one(&store.pool)
                .await?,
            };
                Some(t.ok_or_else(|| StoreError::Corrupt(format!("expiry {secs} s is out of range")))?)
            }
            None => None,
        };
    sqlx::query(&store.pool.sql("INSERT INTO tokens (id, name, sha256, created_at, expires_at) VALUES (?, ?, ?, ?, ?)"))
        .bind(uuid::Uuid::new_v4().to_string())
        .bind(name)
        .bind(sha256_hex(token.as_bytes()))
        .bind(created)
        .bind(expires)
        .execute(&store.pool)
        .await?;
    Ok(token)
}

/// Whether `token` is a stored token that has not expired.
pub async fn verify(store: &Store, token: &str) -> Result<bool, StoreError> {
    let row: Option<(String,)> =
        sqlx::query_as(&store.pool.sql(format!("SELECT id FROM tokens WHERE sha256 = ? AND (expires_at IS NULL OR expires_at > {NOW})")))
            .bind(sha256_hex(token.as_bytes()))
            .fetch_optional(&store.pool)
            .await?;
    Ok(row.is_some())
}

/// Every token, oldest first.
pub async fn list(store: &Store) -> Result<Vec<TokenInfo>, StoreError> {
    type Row = (String, String, String, Option<String>, String, i64);
    let rows: Vec<Row> = sqlx::query_as(&store.pool.sql(format!(
        "SELECT id, name, created_at, expires_at, sha256,
                CASE WHEN expires_at IS NOT NULL AND expires_at <= {NOW} THEN 1 ELSE 0 END AS expired
         FROM tokens ORDER BY created_at, rowid"
    )))
    .fetch_all(&store.pool)
    .await?;
    Ok(rows
        .into_iter()
        .map(|(id, name, created_at, expires_at, sha256, expired)| TokenInfo {
            id,
            name,
            created_at,
            expires_at,
            sha256,
            expired: expired != 0,
        })
        .collect())
}

/// Deletes the token with id `name_or_id`, or else the one token named so.
pub async fn revoke(store: &Store, name_or_id: &str) -> Result<Revoked, StoreError> {
    let all = list(store).await?;
    let by_id: Vec<&TokenInfo> = all.iter().filter(|t| t.id == name_or_id).collect();
    let matches: Vec<&TokenInfo> = if by_id.is_empty() { all.iter().filter(|t| t.name == name_or_id).collect() } else { by_id };
    match matches.as_slice() {
        [] => Ok(Revoked::NotFound),
        [one] => {
            sqlx::query(&store.pool.sql("DELETE FROM tokens WHERE id = ?")).bind(&one.id).execute(&store.pool).await?;
            Ok(Revoked::One((*one).clone()))
        }
        many => Ok(Revoked::Ambiguous(many.iter().map(|t| (*t).clone()).collect())),
    }
}

/// The SHA-256 (hex) of every token that has not expired: the keys live view frames are signed with.
pub async fn live_hashes(store: &Store) -> Result<Vec<String>, StoreError> {
    let rows: Vec<(String,)> =
        sqlx::query_as(&store.pool.sql(format!("SELECT sha256 FROM tokens WHERE expires_at IS NULL OR expires_at > {NOW}")))
            .fetch_all(&store.pool)
            .await?;
    Ok(rows.into_iter().map(|(h,)| h).collect())
}

/// The stored hashes (for tests and audits).
pub async fn hashes(store: &Store) -> Result<Vec<String>, StoreError> {
    let rows: Vec<(String,)> =
        sqlx::query_as(&store.pool.sql("SELECT sha256 FROM tokens ORDER BY created_at")).fetch_all(&store.pool).await?;
    Ok(rows.into_iter().map(|(h,)| h).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[tokio::test]
    async fn tokens_expire_list_and_revoke() {
        let dir = tempfile::tempdir().unwrap();
        let s = Store::open(&format!("sqlite://{}?mode=rwc", dir.path().join("t.db").display())).await.unwrap();
        let forever = create(&s, "ci", None).await.unwrap();
        let gone = create(&s, "short", Some(0)).await.unwrap();
        let later = create(&s, "ci", Some(3600)).await.unwrap();
        assert!(verify(&s, &forever).await.unwrap());
        assert!(!verify(&s, &gone).await.unwrap(), "expires at its creation");
        assert!(verify(&s, &later).await.unwrap());
        let l = list(&s).await.unwrap();
        assert_eq!(l.iter().map(|t| (t.name.as_str(), t.expired)).collect::<Vec<_>>(), [("ci", false), ("short", true), ("ci", false)]);
        assert!(l[0].expires_at.is_none() && l[2].expires_at.as_deref() > Some(l[2].created_at.as_str()));
        // Two named "ci": by name is ambiguous, by id is not.
        assert!(matches!(revoke(&s, "ci").await.unwrap(), Revoked::Ambiguous(v) if v.len() == 2));
        assert!(matches!(revoke(&s, &l[0].id).await.unwrap(), Revoked::One(t) if t.id == l[0].id));
        assert!(!verify(&s, &forever).await.unwrap());
        assert!(matches!(revoke(&s, "ci").await.unwrap(), Revoked::One(_)));
        assert!(!verify(&s, &later).await.unwrap());
        assert_eq!(revoke(&s, "ci").await.unwrap(), Revoked::NotFound);
    }
}
