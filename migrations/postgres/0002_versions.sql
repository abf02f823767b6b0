-- PostgreSQL twin of migrations/sqlite/0002_versions.sql: the same tables and columns (tests check it).
-- Types: INTEGER -> BIGINT, REAL -> DOUBLE PRECISION, TEXT -> TEXT COLLATE "C" (byte order,
-- like SQLite's). `rowid BIGINT GENERATED ALWAYS AS IDENTITY` stands in for SQLite's implicit
-- rowid (insertion order for ORDER BY ... rowid); the schema test leaves it out.

-- Models and versions, second step (issue 4: the models API).
--
-- models.last_version: the highest version number ever given to the model. New versions take
-- last_version + 1, so a number is never reused, even after its version was deleted (a cached
-- package.zip of "version 3" always means the same upload).
ALTER TABLE models ADD COLUMN last_version BIGINT NOT NULL DEFAULT 0;
UPDATE models SET last_version = (SELECT COALESCE(MAX(v.version), 0) FROM versions v WHERE v.model_id = models.id);

-- versions.bundle_size: bytes of the uploaded bundle (the blob's length).
ALTER TABLE versions ADD COLUMN bundle_size BIGINT NOT NULL DEFAULT 0;

-- versions.summary_json: counts taken from report.json once converted
-- ({"bodies", "joints", "loops", "free_bodies", "warnings", "package_name", "model_name"}),
-- so listings need not read the report file.
ALTER TABLE versions ADD COLUMN summary_json TEXT COLLATE "C";

-- The jobs of one version (deleted with it; looked up by the version's page).
CREATE INDEX jobs_by_version ON jobs(model_id, version);
