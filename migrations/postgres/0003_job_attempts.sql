-- PostgreSQL twin of migrations/sqlite/0003_job_attempts.sql: the same tables and columns (tests check it).
-- Types: INTEGER -> BIGINT, REAL -> DOUBLE PRECISION, TEXT -> TEXT COLLATE "C" (byte order,
-- like SQLite's). `rowid BIGINT GENERATED ALWAYS AS IDENTITY` stands in for SQLite's implicit
-- rowid (insertion order for ORDER BY ... rowid); the schema test leaves it out.

-- Poison jobs (the hardening issue): a conversion that kills the process would be re-queued at
-- every start and kill it again, forever.
--
-- jobs.attempts: how many times a worker claimed the job (incremented by the claim). A job that
-- is claimed again after reaching the limit (crate::jobs::MAX_ATTEMPTS) is marked failed instead
-- of being run. Existing jobs start at 0.
ALTER TABLE jobs ADD COLUMN attempts BIGINT NOT NULL DEFAULT 0;
