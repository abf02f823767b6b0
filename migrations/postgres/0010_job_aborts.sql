-- PostgreSQL twin of migrations/sqlite/0010_job_aborts.sql: the same tables and columns (tests check it).
--
-- jobs.isolate: the job was running, with others, when its instance stopped: re-run alone first.
-- jobs.aborts: stops of its instance while the job was the only one running there (2: quarantined).
ALTER TABLE jobs ADD COLUMN isolate BIGINT NOT NULL DEFAULT 0;
ALTER TABLE jobs ADD COLUMN aborts BIGINT NOT NULL DEFAULT 0;
