//! The store: the only module with SQL (`tests/tidy.rs` checks). One binary, two engines, chosen
//! by the database URL: SQLite (the default, `sqlite://<data-dir>/cad2mo.db`: WAL mode, a busy
//! timeout, foreign keys) or PostgreSQL (`postgres://...`, for several service instances on one
//! database). Both are reached through sqlx's `AnyPool` and migrated on open from
//! `migrations/sqlite/` or `migrations/postgres/` (the same versions, the same tables and columns:
//! `tests::schemas_match` checks).
//!
//! Queries are written once, in SQLite's spelling with `?` / `?N` placeholders, and passed through
//! [`sql`], which turns placeholders into `$N` for PostgreSQL and expands the two clock tokens
//! `%NOW%` (now, RFC 3339 UTC with milliseconds) and `%UNTIL%` (now plus a bound number of
//! seconds). Where the dialects differ beyond that (the job claim, the library's write lock, a
//! token's expiry), the function branches on [`Engine`].

pub mod blobs;
pub mod collision;
pub mod drives;
pub mod library;
pub mod models;
pub mod motions;
pub mod results;
pub mod tokens;

pub mod testdb;

use std::time::Duration;

use sqlx::any::AnyPoolOptions;
use sqlx::{AnyConnection, AnyPool, Executor};

/// Errors of the store.
#[derive(Debug, thiserror::Error)]
pub enum StoreError {
    #[error("database: {0}")]
    Db(#[from] sqlx::Error),
    #[error("migration: {0}")]
    Migrate(#[from] sqlx::migrate::MigrateError),
    #[error("file store: {0}")]
    Io(#[from] std::io::Error),
    #[error("stored data is corrupt: {0}")]
    Corrupt(String),
}

impl StoreError {
    /// True when the error is a UNIQUE constraint violation (a conflict, for the API).
    pub fn is_unique_violation(&self) -> bool {
        matches!(self, StoreError::Db(sqlx::Error::Database(e)) if e.is_unique_violation())
    }
    /// True when the error is a FOREIGN KEY violation (something still refers to the row).
    pub fn is_foreign_key_violation(&self) -> bool {
        matches!(self, StoreError::Db(sqlx::Error::Database(e)) if e.is_foreign_key_violation())
    }
}

/// The database engine behind a [`Pool`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Engine {
    Sqlite,
    Postgres,
}

impl Engine {
    /// The engine a database URL names (`postgres://` or `postgresql://`, else SQLite).
    pub fn of_url(url: &str) -> Engine {
        if url.starts_with("postgres://") || url.starts_with("postgresql://") {
            Engine::Postgres
        } else {
            Engine::Sqlite
        }
    }

    /// The engine of a connection (inside a transaction).
    pub fn of(conn: &AnyConnection) -> Engine {
        if conn.backend_name() == "PostgreSQL" {
            Engine::Postgres
        } else {
            Engine::Sqlite
        }
    }

    /// Now as RFC 3339 UTC with milliseconds, as an SQL expression.
    fn now(self) -> &'static str {
        match self {
            Engine::Sqlite => "strftime('%Y-%m-%dT%H:%M:%fZ', 'now')",
            Engine::Postgres => r#"to_char(clock_timestamp() AT TIME ZONE 'UTC', 'YYYY-MM-DD"T"HH24:MI:SS.MS"Z"')"#,
        }
    }

    /// Now plus a bound number of seconds (one `?`, an f64), in the same format.
    fn until(self) -> &'static str {
        match self {
            Engine::Sqlite => "strftime('%Y-%m-%dT%H:%M:%fZ', 'now', '+' || ? || ' seconds')",
            Engine::Postgres => {
                r#"to_char((clock_timestamp() + ? * interval '1 second') AT TIME ZONE 'UTC', 'YYYY-MM-DD"T"HH24:MI:SS.MS"Z"')"#
            }
        }
    }
}

/// A query for `engine`: `%NOW%` and `%UNTIL%` expanded, and for PostgreSQL `?` / `?N`
/// placeholders (outside quoted literals) turned into `$N`.
pub fn sql(engine: Engine, q: impl AsRef<str>) -> String {
    let q = q.as_ref().replace("%NOW%", engine.now()).replace("%UNTIL%", engine.until());
    if engine == Engine::Sqlite {
        return q;
    }
    let mut out = String::with_capacity(q.len() + 8);
    let mut next = 0;
    let mut quoted: Option<char> = None;
    let mut chars = q.chars().peekable();
    while let Some(c) = chars.next() {
        match quoted {
            Some(quote) => {
                out.push(c);
                if c == quote {
                    quoted = None;
                }
            }
            None if c == '\'' || c == '"' => {
                quoted = Some(c);
                out.push(c);
            }
            None if c == '?' => {
                let mut digits = String::new();
                while let Some(d) = chars.peek().filter(|d| d.is_ascii_digit()) {
                    digits.push(*d);
                    chars.next();
                }
                if digits.is_empty() {
                    next += 1;
                    digits = next.to_string();
                }
                out.push('$');
                out.push_str(&digits);
            }
            None => out.push(c),
        }
    }
    out
}

/// The connection pool with its engine (cheap to clone). Derefs to sqlx's `AnyPool`, and
/// `&Pool` runs queries like the pool itself.
#[derive(Clone, Debug)]
pub struct Pool {
    any: AnyPool,
    engine: Engine,
}

impl Pool {
    pub fn engine(&self) -> Engine {
        self.engine
    }

    /// [`sql`] for this pool's engine.
    pub fn sql(&self, q: impl AsRef<str>) -> String {
        sql(self.engine, q)
    }
}

impl std::ops::Deref for Pool {
    type Target = AnyPool;
    fn deref(&self) -> &AnyPool {
        &self.any
    }
}

impl<'p> sqlx::Executor<'p> for &Pool {
    type Database = sqlx::Any;

    fn fetch_many<'e, 'q: 'e, E>(
        self,
        query: E,
    ) -> futures_core::stream::BoxStream<'e, Result<sqlx::Either<sqlx::any::AnyQueryResult, sqlx::any::AnyRow>, sqlx::Error>>
    where
        'p: 'e,
        E: 'q + sqlx::Execute<'q, sqlx::Any>,
    {
        (&self.any).fetch_many(query)
    }

    fn fetch_optional<'e, 'q: 'e, E>(
        self,
        query: E,
    ) -> futures_core::future::BoxFuture<'e, Result<Option<sqlx::any::AnyRow>, sqlx::Error>>
    where
        'p: 'e,
        E: 'q + sqlx::Execute<'q, sqlx::Any>,
    {
        (&self.any).fetch_optional(query)
    }

    fn prepare_with<'e, 'q: 'e>(
        self,
        sql: &'q str,
        parameters: &'e [sqlx::any::AnyTypeInfo],
    ) -> futures_core::future::BoxFuture<'e, Result<sqlx::any::AnyStatement<'q>, sqlx::Error>>
    where
        'p: 'e,
    {
        (&self.any).prepare_with(sql, parameters)
    }

    fn describe<'e, 'q: 'e>(
        self,
        sql: &'q str,
    ) -> futures_core::future::BoxFuture<'e, Result<sqlx::Describe<sqlx::Any>, sqlx::Error>>
    where
        'p: 'e,
    {
        (&self.any).describe(sql)
    }
}

/// Connections per instance, by default (`--db-pool-size`).
pub const POOL_SIZE: u32 = 8;

/// A handle on the database (cheap to clone).
#[derive(Clone, Debug)]
pub struct Store {
    pub pool: Pool,
}

impl Store {
    /// Opens (creating if needed, for SQLite) and migrates the database.
    pub async fn open(url: &str) -> Result<Store, StoreError> {
        Self::open_with(url, POOL_SIZE).await
    }

    /// [`Store::open`] with `max_connections` connections at most.
    pub async fn open_with(url: &str, max_connections: u32) -> Result<Store, StoreError> {
        sqlx::any::install_default_drivers();
        let engine = Engine::of_url(url);
        let options = AnyPoolOptions::new().max_connections(max_connections.max(1));
        let any = match engine {
            Engine::Sqlite => {
                options
                    .after_connect(|conn, _| {
                        Box::pin(async move {
                            for pragma in [
                                "PRAGMA journal_mode = WAL",
                                "PRAGMA synchronous = NORMAL",
                                "PRAGMA busy_timeout = 10000",
                                "PRAGMA foreign_keys = ON",
                            ] {
                                conn.execute(pragma).await?;
                            }
                            Ok(())
                        })
                    })
                    .connect(url)
                    .await?
            }
            Engine::Postgres => options.acquire_timeout(Duration::from_secs(30)).connect(url).await?,
        };
        match engine {
            Engine::Sqlite => sqlx::migrate!("../migrations/sqlite").run(&any).await?,
            Engine::Postgres => sqlx::migrate!("../migrations/postgres").run(&any).await?,
        }
        Ok(Store { pool: Pool { any, engine } })
    }
}

/// Now, as RFC 3339 UTC with milliseconds (the database's own clock, so no time crate is needed
/// and every instance agrees).
pub async fn now(pool: &Pool) -> Result<String, StoreError> {
    let (t,): (String,) = sqlx::query_as(&pool.sql("SELECT %NOW%")).fetch_one(pool).await?;
    Ok(t)
}
