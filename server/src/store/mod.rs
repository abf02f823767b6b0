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
pub mod integrity;
pub mod library;
pub mod models;
pub mod motions;
pub mod results;
pub mod scene;
pub mod simulations;
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

    fn fetch_optional<'e, 'q: 'e, E>(self, query: E) -> futures_core::future::BoxFuture<'e, Result<Option<sqlx::any::AnyRow>, sqlx::Error>>
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

    fn describe<'e, 'q: 'e>(self, sql: &'q str) -> futures_core::future::BoxFuture<'e, Result<sqlx::Describe<sqlx::Any>, sqlx::Error>>
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

/// Tests on both engines: SQLite always, PostgreSQL when `CAD2MO_TEST_DATABASE_URL` names a
/// server (`scripts/test` starts one), each on a fresh database.
#[cfg(test)]
mod tests {
    use std::collections::{BTreeMap, BTreeSet};

    use super::models::{self, Claimer, JobOutputs, NewVersion};
    use super::*;

    /// A fresh database: `(keep-alive, url)`.
    async fn fresh(engine: Engine) -> Option<(Option<tempfile::TempDir>, String)> {
        match engine {
            Engine::Sqlite => {
                let dir = tempfile::tempdir().expect("tempdir");
                let url = format!("sqlite://{}?mode=rwc", dir.path().join("t.db").display());
                Some((Some(dir), url))
            }
            Engine::Postgres => {
                let Ok(base) = std::env::var("CAD2MO_TEST_DATABASE_URL") else {
                    eprintln!("NOTICE: CAD2MO_TEST_DATABASE_URL is not set: the PostgreSQL half of this test is skipped");
                    return None;
                };
                Some((None, testdb::create_database(&base).await.expect("test database")))
            }
        }
    }

    async fn drop_fresh(url: &str) {
        if let (Engine::Postgres, Ok(base)) = (Engine::of_url(url), std::env::var("CAD2MO_TEST_DATABASE_URL")) {
            testdb::drop_database(&base, url).await.expect("drop test database");
        }
    }

    fn upload() -> NewVersion<'static> {
        NewVersion { bundle_name: "b.zip", bundle_sha256: "ab", bundle_size: 2, options_json: "{}", triangles: None, bundle_bytes: None }
    }

    fn claimer(instance: &str, lease_secs: f64) -> Claimer {
        Claimer { instance: instance.into(), lease_secs }
    }

    const OUT: JobOutputs<'static> = JobOutputs { package_sha256: "p", report_sha256: "r", summary_json: "{}" };

    /// SQLite databases made before the migrations moved to `migrations/sqlite/` still open: sqlx
    /// records each applied migration's SHA-384 and refuses a database whose files changed. These
    /// are the digests of the files as they were applied (never edit an applied migration).
    #[test]
    fn applied_sqlite_migrations_are_byte_identical() {
        use sha2::Digest;
        let applied = [
            ("0001_init.sql", "403287fe7abb052666819f310348e437edbeebcace0ad4ee7dd63829a7f1db9d3da21c4bd8eeefce4ba1c7719c7ac96f"),
            ("0002_versions.sql", "99699dea2b0a2ca99ea552f78b9f2b139e4cbeb087feddceefdc4aaff6c76ee2cda680ced48a43ebbc3cafbc3b26d649"),
            ("0003_job_attempts.sql", "9e8ec94eb2fa73b054d7764b736ba8936c40c1d63a00b7eb16bbd1945bdbd52af5d6b68e671959ecc68adac977075364"),
            ("0004_token_expiry.sql", "9fa0a47517a8dcd09680a4f33ef8dac826549fe9448dfc23a1ef1f4fa7f5b6732c89650335777ab3ae624f89f1bbdf3f"),
            (
                "0005_library_datasheet.sql",
                "a9c0c613806d5cc48c19ba8ad992328c3672b716168e17cf79594a8712ece0d3a4a5694b4aee7cbec82cea9718c93743",
            ),
            ("0006_motions.sql", "dc0f3117036c9a715bf11e9df6ef1109cd5a57473af28ff279bbfaad0a5d6ab415a544aa8eda4cb524b709c0018299c1"),
            ("0007_results.sql", "6ae9fa4e16e2467df3021a2780f4dcf9e3f82d35e08ba6f86c84dc28fedc98471fcf51a97a0d7e0b500463e09b63ac71"),
            (
                "0008_collision_pairs.sql",
                "bcd3412e4defa56bb1820c6d436498fc8e8f771bc59d193b6a35b001ed179accd66955b35777bc1bc6c3c758c22bc471",
            ),
        ];
        let migrator = sqlx::migrate!("../migrations/sqlite");
        for (file, digest) in applied {
            let version: i64 = file[..4].parse().expect("version");
            let m = migrator.iter().find(|m| m.version == version).expect("migration");
            assert_eq!(hex::encode(&*m.checksum), digest, "{file} changed");
            let on_disk = std::fs::read(format!("{}/../migrations/sqlite/{file}", env!("CARGO_MANIFEST_DIR"))).expect("file");
            assert_eq!(hex::encode(sha2::Sha384::digest(&on_disk)), digest, "{file} changed");
        }
    }

    #[test]
    fn placeholders_become_numbered_for_postgres_outside_literals() {
        let q = "SELECT a FROM t WHERE x = ? AND y = '?' AND z = ? AND w = ?2";
        assert_eq!(sql(Engine::Sqlite, q), q);
        assert_eq!(sql(Engine::Postgres, q), "SELECT a FROM t WHERE x = $1 AND y = '?' AND z = $2 AND w = $2");
        assert!(sql(Engine::Postgres, "SELECT %NOW%").contains("clock_timestamp()"));
        assert!(sql(Engine::Sqlite, "SELECT %UNTIL%").contains("'now', '+' || ? || ' seconds'"));
    }

    /// Table -> column -> type class (int, real, text) of a database, without sqlx's own table
    /// and PostgreSQL's rowid stand-in.
    async fn schema(store: &Store) -> BTreeMap<String, BTreeMap<String, String>> {
        let rows: Vec<(String, String, String)> = match store.pool.engine() {
            Engine::Sqlite => sqlx::query_as(
                "SELECT m.name, p.name, lower(p.type) FROM sqlite_master m JOIN pragma_table_info(m.name) p
                 WHERE m.type = 'table' AND m.name NOT LIKE 'sqlite_%' AND m.name <> '_sqlx_migrations'",
            )
            .fetch_all(&store.pool)
            .await
            .expect("sqlite schema"),
            Engine::Postgres => sqlx::query_as(
                "SELECT table_name::text, column_name::text, data_type::text FROM information_schema.columns
                 WHERE table_schema = 'public' AND table_name <> '_sqlx_migrations' AND column_name <> 'rowid'",
            )
            .fetch_all(&store.pool)
            .await
            .expect("postgres schema"),
        };
        let mut tables: BTreeMap<String, BTreeMap<String, String>> = BTreeMap::new();
        for (table, column, ty) in rows {
            let class = match ty.as_str() {
                "integer" | "bigint" => "int",
                "real" | "double precision" => "real",
                "text" => "text",
                other => panic!("{table}.{column}: unexpected type {other}"),
            };
            tables.entry(table).or_default().insert(column, class.to_string());
        }
        tables
    }

    /// Both engines' migrations give the same tables with the same columns of the same type class.
    #[tokio::test]
    async fn schemas_match() {
        let Some((_keep, pg)) = fresh(Engine::Postgres).await else { return };
        let (_dir, lite) = fresh(Engine::Sqlite).await.expect("sqlite");
        let (a, b) = (Store::open(&lite).await.expect("sqlite"), Store::open(&pg).await.expect("postgres"));
        let (sa, sb) = (schema(&a).await, schema(&b).await);
        assert!(sa.contains_key("jobs") && sa["jobs"].contains_key("lease_until"), "{sa:?}");
        assert_eq!(sa, sb, "SQLite's schema (left) differs from PostgreSQL's (right)");
        drop(b);
        drop_fresh(&pg).await;
    }

    /// 50 jobs, two instances (two pools) with four claimers each, all claiming at once: every
    /// job is claimed exactly once.
    #[tokio::test(flavor = "multi_thread", worker_threads = 4)]
    async fn concurrent_claims_from_two_instances_never_share_a_job() {
        for engine in [Engine::Sqlite, Engine::Postgres] {
            let Some((_keep, url)) = fresh(engine).await else { continue };
            let stores = [Store::open(&url).await.expect("a"), Store::open(&url).await.expect("b")];
            let mut made = BTreeSet::new();
            for i in 0..50 {
                made.insert(models::create_model(&stores[0].pool, &format!("m{i}"), &upload()).await.expect("model").job_id);
            }
            let started = std::time::Instant::now();
            let mut tasks = Vec::new();
            for (n, store) in stores.iter().enumerate() {
                for k in 0..4 {
                    let store = store.clone();
                    let me = claimer(&format!("i{n}c{k}"), 30.0);
                    tasks.push(tokio::spawn(async move {
                        let mut got = Vec::new();
                        while let Some(j) = models::claim_next_job(&store.pool, &me).await.expect("claim") {
                            got.push(j.id);
                        }
                        got
                    }));
                }
            }
            let mut claimed = Vec::new();
            let mut per_instance = [0, 0];
            for (t, task) in tasks.into_iter().enumerate() {
                let got = task.await.expect("claimer");
                per_instance[t / 4] += got.len();
                claimed.extend(got);
            }
            let elapsed = started.elapsed();
            eprintln!("{engine:?}: 50 claims by 2x4 claimers in {elapsed:?} ({:?} each), per instance {per_instance:?}", elapsed / 50);
            let distinct: BTreeSet<String> = claimed.iter().cloned().collect();
            assert_eq!(claimed.len(), 50, "{engine:?}: a job was claimed twice or never");
            assert_eq!(distinct, made, "{engine:?}");
            drop(stores);
            drop_fresh(&url).await;
        }
    }

    /// A claim not renewed passes: another instance takes the job over (an attempt more) and the
    /// first can no longer record anything; a renewed claim holds.
    #[tokio::test]
    async fn an_expired_lease_is_taken_over_and_a_renewed_one_is_not() {
        for engine in [Engine::Sqlite, Engine::Postgres] {
            let Some((_keep, url)) = fresh(engine).await else { continue };
            let (a, b) = (Store::open(&url).await.expect("a"), Store::open(&url).await.expect("b"));
            let (ca, cb) = (claimer("a", 0.6), claimer("b", 30.0));
            let m = models::create_model(&a.pool, "m", &upload()).await.expect("model");
            // Renewed: held well past its first lease.
            let ja = models::claim_next_job(&a.pool, &ca).await.expect("claim").expect("job");
            assert_eq!(ja.attempts, 1);
            for _ in 0..6 {
                tokio::time::sleep(Duration::from_millis(200)).await;
                assert!(models::renew_lease(&a.pool, &ja, ca.lease_secs).await.expect("renew"), "{engine:?}");
                assert!(models::claim_next_job(&b.pool, &cb).await.expect("claim").is_none(), "{engine:?}: taken while renewed");
            }
            // Not renewed: after the lease, b takes it.
            tokio::time::sleep(Duration::from_millis(900)).await;
            let jb = models::claim_next_job(&b.pool, &cb).await.expect("claim").expect("taken over after expiry");
            assert_eq!((jb.id.as_str(), jb.attempts), (m.job_id.as_str(), 2), "{engine:?}");
            assert!(!models::renew_lease(&a.pool, &ja, ca.lease_secs).await.expect("renew"), "{engine:?}: a's lease is gone");
            assert!(!models::set_progress(&a.pool, &ja, "{}").await.expect("progress"), "{engine:?}");
            assert!(!models::finish_failed(&a.pool, &ja, "{\"late\":1}").await.expect("finish"), "{engine:?}: a late finish wrote");
            assert!(models::finish_succeeded(&b.pool, &jb, &OUT).await.expect("finish"), "{engine:?}");
            let v = models::get_version(&a.pool, &m.model_id, 1).await.expect("version").expect("v1");
            assert_eq!((v.status.as_str(), v.error_json), ("succeeded", None), "{engine:?}");
            drop((a, b));
            drop_fresh(&url).await;
        }
    }

    /// A model's versions run in order even when two instances claim: version 2 waits while
    /// version 1 runs on the other instance; another model's job does not wait.
    #[tokio::test]
    async fn a_models_jobs_run_in_version_order_across_instances() {
        for engine in [Engine::Sqlite, Engine::Postgres] {
            let Some((_keep, url)) = fresh(engine).await else { continue };
            let (a, b) = (Store::open(&url).await.expect("a"), Store::open(&url).await.expect("b"));
            let (ca, cb) = (claimer("a", 30.0), claimer("b", 30.0));
            let m = models::create_model(&a.pool, "m", &upload()).await.expect("model");
            let v2 = models::create_version(&a.pool, &m.model_id, &upload()).await.expect("v2").expect("model");
            let v3 = models::create_version(&b.pool, &m.model_id, &upload()).await.expect("v3").expect("model");
            let other = models::create_model(&b.pool, "other", &upload()).await.expect("model");
            let j1 = models::claim_next_job(&a.pool, &ca).await.expect("claim").expect("v1");
            assert_eq!(j1.version, 1);
            let jo = models::claim_next_job(&b.pool, &cb).await.expect("claim").expect("other model");
            assert_eq!(jo.id, other.job_id, "{engine:?}: version 2 must wait for version 1");
            assert!(models::claim_next_job(&b.pool, &cb).await.expect("claim").is_none(), "{engine:?}");
            assert!(models::finish_succeeded(&a.pool, &j1, &OUT).await.expect("finish"));
            let j2 = models::claim_next_job(&b.pool, &cb).await.expect("claim").expect("v2");
            assert_eq!(j2.id, v2.job_id, "{engine:?}");
            assert!(models::claim_next_job(&a.pool, &ca).await.expect("claim").is_none(), "{engine:?}: v3 waits for v2");
            assert!(models::finish_failed(&b.pool, &j2, "{}").await.expect("finish"));
            assert_eq!(models::claim_next_job(&a.pool, &ca).await.expect("claim").expect("v3").id, v3.job_id, "{engine:?}");
            drop((a, b));
            drop_fresh(&url).await;
        }
    }

    /// Progress one instance records is read by another; requeue at start-up leaves a live
    /// instance's job alone on PostgreSQL.
    #[tokio::test]
    async fn progress_is_shared_and_requeue_spares_live_leases() {
        for engine in [Engine::Sqlite, Engine::Postgres] {
            let Some((_keep, url)) = fresh(engine).await else { continue };
            let (a, b) = (Store::open(&url).await.expect("a"), Store::open(&url).await.expect("b"));
            let m = models::create_model(&a.pool, "m", &upload()).await.expect("model");
            let j = models::claim_next_job(&a.pool, &claimer("a", 30.0)).await.expect("claim").expect("job");
            assert!(models::set_progress(&a.pool, &j, "{\"stage\":\"meshes\"}").await.expect("progress"));
            let seen = models::get_job(&b.pool, &m.job_id).await.expect("job").expect("job");
            assert_eq!(seen.progress_json.as_deref(), Some("{\"stage\":\"meshes\"}"), "{engine:?}");
            let requeued = models::requeue_unfinished(&b.pool).await.expect("requeue");
            match engine {
                // One server per SQLite database: a start re-queues every running job.
                Engine::Sqlite => assert_eq!(requeued, 1),
                Engine::Postgres => {
                    assert_eq!(requeued, 0, "a live instance's job was re-queued");
                    assert!(models::finish_succeeded(&a.pool, &j, &OUT).await.expect("finish"));
                    assert_eq!(models::get_job(&b.pool, &m.job_id).await.expect("job").expect("job").progress_json, None);
                }
            }
            drop((a, b));
            drop_fresh(&url).await;
        }
    }
}
