//! Fresh databases for tests (the store's own and the API tests' `TestApp`): on PostgreSQL, a new
//! database `t_<uuid>` on the server a base URL names (`CAD2MO_TEST_DATABASE_URL` in the tests),
//! dropped again by [`drop_database`]. SQL for tests lives here because only `store` has SQL.

use sqlx::{Connection, PgConnection};

use super::StoreError;

/// The URL of `base` with its database name replaced by `name`.
fn with_database(base: &str, name: &str) -> String {
    let (head, query) = match base.split_once('?') {
        Some((h, q)) => (h, Some(q)),
        None => (base, None),
    };
    // postgres://user@host:port/db -> keep up to the slash after the authority.
    let scheme_end = head.find("://").map_or(0, |i| i + 3);
    let root = match head[scheme_end..].find('/') {
        Some(i) => &head[..scheme_end + i],
        None => head,
    };
    match query {
        Some(q) => format!("{root}/{name}?{q}"),
        None => format!("{root}/{name}"),
    }
}

/// Creates an empty database on the PostgreSQL server of `base` and returns its URL.
pub async fn create_database(base: &str) -> Result<String, StoreError> {
    let name = format!("t_{}", uuid::Uuid::new_v4().simple());
    let mut conn = PgConnection::connect(base).await?;
    sqlx::raw_sql(&format!("CREATE DATABASE {name}")).execute(&mut conn).await?;
    conn.close().await?;
    Ok(with_database(base, &name))
}

/// Drops a database [`create_database`] made (closing its other connections).
pub async fn drop_database(base: &str, url: &str) -> Result<(), StoreError> {
    let name = url.split('?').next().unwrap_or(url).rsplit('/').next().unwrap_or_default();
    if !name.starts_with("t_") || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Err(StoreError::Corrupt(format!("{name} is not a test database")));
    }
    let mut conn = PgConnection::connect(base).await?;
    sqlx::raw_sql(&format!("DROP DATABASE IF EXISTS {name} WITH (FORCE)")).execute(&mut conn).await?;
    conn.close().await?;
    Ok(())
}

/// Drops a test database from synchronous code (a `Drop`), on a runtime of its own.
pub fn drop_database_blocking(base: String, url: String) {
    let _ = std::thread::spawn(move || {
        let rt = tokio::runtime::Builder::new_current_thread().enable_all().build();
        if let Ok(rt) = rt {
            if let Err(e) = rt.block_on(drop_database(&base, &url)) {
                eprintln!("dropping test database {url}: {e}");
            }
        }
    })
    .join();
}

#[cfg(test)]
mod tests {
    #[test]
    fn database_names_replace_the_base_one() {
        assert_eq!(super::with_database("postgres://u@h:5/postgres", "t_1"), "postgres://u@h:5/t_1");
        assert_eq!(super::with_database("postgres://u@h:5", "t_1"), "postgres://u@h:5/t_1");
        assert_eq!(super::with_database("postgres://h/x?sslmode=disable", "t_1"), "postgres://h/t_1?sslmode=disable");
    }
}
