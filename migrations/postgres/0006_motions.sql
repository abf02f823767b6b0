-- PostgreSQL twin of migrations/sqlite/0006_motions.sql: the same tables and columns (tests check it).
-- Types: INTEGER -> BIGINT, REAL -> DOUBLE PRECISION, TEXT -> TEXT COLLATE "C" (byte order,
-- like SQLite's). `rowid BIGINT GENERATED ALWAYS AS IDENTITY` stands in for SQLite's implicit
-- rowid (insertion order for ORDER BY ... rowid); the schema test leaves it out.

-- Issue 12: joint limits and motions of a model. Both are keyed like drives (the joint's stable
-- Modelica name), belong to the model (not one version) and survive CAD changes; a joint that
-- vanishes leaves its limits orphaned (reported, never deleted).

CREATE TABLE joint_limits (
    rowid       BIGINT GENERATED ALWAYS AS IDENTITY,
    model_id     TEXT COLLATE "C" NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    joint        TEXT COLLATE "C" NOT NULL,
    limits_json  TEXT COLLATE "C" NOT NULL,                  -- motion::plan::LimitsEdit (absent = default)
    updated_at   TEXT COLLATE "C" NOT NULL,
    PRIMARY KEY (model_id, joint)
);

CREATE TABLE motions (
    rowid       BIGINT GENERATED ALWAYS AS IDENTITY,
    id          TEXT COLLATE "C" PRIMARY KEY,
    model_id    TEXT COLLATE "C" NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    name        TEXT COLLATE "C" NOT NULL,
    spec_json   TEXT COLLATE "C" NOT NULL,                   -- motion::plan::MotionSpec
    created_at  TEXT COLLATE "C" NOT NULL,
    updated_at  TEXT COLLATE "C" NOT NULL,
    UNIQUE (model_id, name)
);
CREATE INDEX motions_by_model ON motions(model_id, created_at);
