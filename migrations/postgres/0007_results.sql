-- PostgreSQL twin of migrations/sqlite/0007_results.sql: the same tables and columns (tests check it).
-- Types: INTEGER -> BIGINT, REAL -> DOUBLE PRECISION, TEXT -> TEXT COLLATE "C" (byte order,
-- like SQLite's). `rowid BIGINT GENERATED ALWAYS AS IDENTITY` stands in for SQLite's implicit
-- rowid (insertion order for ORDER BY ... rowid); the schema test leaves it out.

-- Issue 13: simulation result files (MAT v4 from Dymola or OpenModelica), uploaded to a model
-- version or standalone (model_id and version NULL: a result of any Modelica model). The file
-- is a blob; its summary (variables, time span, where each body's pose comes from, the
-- self-checks, visual shapes) is kept with it.

CREATE TABLE results (
    rowid       BIGINT GENERATED ALWAYS AS IDENTITY,
    id             TEXT COLLATE "C" PRIMARY KEY,
    model_id       TEXT COLLATE "C",
    version        BIGINT,
    name           TEXT COLLATE "C" NOT NULL,                -- the uploaded file's (safe) name
    size           BIGINT NOT NULL,
    blob_sha256    TEXT COLLATE "C" NOT NULL,
    summary_json   TEXT COLLATE "C" NOT NULL,
    created_at     TEXT COLLATE "C" NOT NULL,
    FOREIGN KEY (model_id, version) REFERENCES versions(model_id, version) ON DELETE CASCADE
);
CREATE INDEX results_by_version ON results(model_id, version, created_at);

