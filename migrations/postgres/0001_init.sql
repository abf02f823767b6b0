-- PostgreSQL twin of migrations/sqlite/0001_init.sql: the same tables and columns (tests check it).
-- Types: INTEGER -> BIGINT, REAL -> DOUBLE PRECISION, TEXT -> TEXT COLLATE "C" (byte order,
-- like SQLite's). `rowid BIGINT GENERATED ALWAYS AS IDENTITY` stands in for SQLite's implicit
-- rowid (insertion order for ORDER BY ... rowid); the schema test leaves it out.

-- cad2mo's store: models and their versions, conversion jobs, the motor library, drive
-- assignments and API tokens. Applied by sqlx::migrate! at start-up. Never edit an applied
-- migration: add a new one.
--
-- Conventions: ids are UUIDs (TEXT); times are RFC 3339 UTC (TEXT); JSON columns hold
-- serde-serialised structs; files (bundles, packages, reports) live on disk, content-addressed
-- by SHA-256, and are referred to by their hex digest.

-- A model: one CAD assembly across all its exports.
CREATE TABLE models (
    rowid       BIGINT GENERATED ALWAYS AS IDENTITY,
    id          TEXT COLLATE "C" PRIMARY KEY,
    name        TEXT COLLATE "C" NOT NULL,
    created_at  TEXT COLLATE "C" NOT NULL
);

-- One uploaded export of a model and its conversion.
CREATE TABLE versions (
    rowid       BIGINT GENERATED ALWAYS AS IDENTITY,
    model_id        TEXT COLLATE "C" NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    version         BIGINT NOT NULL,
    created_at      TEXT COLLATE "C" NOT NULL,
    bundle_name     TEXT COLLATE "C" NOT NULL,
    bundle_sha256   TEXT COLLATE "C" NOT NULL,
    options_json    TEXT COLLATE "C" NOT NULL,               -- conversion options used
    status          TEXT COLLATE "C" NOT NULL CHECK (status IN ('queued', 'running', 'succeeded', 'failed')),
    package_sha256  TEXT COLLATE "C",                        -- output zip, once converted
    report_sha256   TEXT COLLATE "C",                        -- report.json, once converted
    error_json      TEXT COLLATE "C",                        -- problem details, when failed
    PRIMARY KEY (model_id, version)
);

-- Background work: a conversion of one version, or a re-export.
CREATE TABLE jobs (
    rowid       BIGINT GENERATED ALWAYS AS IDENTITY,
    id           TEXT COLLATE "C" PRIMARY KEY,
    kind         TEXT COLLATE "C" NOT NULL CHECK (kind IN ('convert', 'reexport')),
    model_id     TEXT COLLATE "C" NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    version      BIGINT NOT NULL,
    status       TEXT COLLATE "C" NOT NULL CHECK (status IN ('queued', 'running', 'succeeded', 'failed')),
    error_json   TEXT COLLATE "C",
    created_at   TEXT COLLATE "C" NOT NULL,
    started_at   TEXT COLLATE "C",
    finished_at  TEXT COLLATE "C"
);
CREATE INDEX jobs_by_status ON jobs(status);

-- The motor library (the paper's object library): classes and their typed parameters.
CREATE TABLE library_classes (
    rowid       BIGINT GENERATED ALWAYS AS IDENTITY,
    id              TEXT COLLATE "C" PRIMARY KEY,
    name            TEXT COLLATE "C" NOT NULL UNIQUE,
    domain          TEXT COLLATE "C" NOT NULL,               -- motor, gear, controller, ...
    modelica_class  TEXT COLLATE "C" NOT NULL,               -- full path; `cad2mo.` = our own Components
    description     TEXT COLLATE "C" NOT NULL DEFAULT ''
);

CREATE TABLE library_parameters (
    rowid       BIGINT GENERATED ALWAYS AS IDENTITY,
    class_id       TEXT COLLATE "C" NOT NULL REFERENCES library_classes(id) ON DELETE CASCADE,
    name           TEXT COLLATE "C" NOT NULL,                -- the Modelica parameter it sets
    position       BIGINT NOT NULL,             -- display order
    type           TEXT COLLATE "C" NOT NULL CHECK (type IN ('Real', 'Integer', 'Boolean', 'String')),
    unit           TEXT COLLATE "C" NOT NULL DEFAULT '',     -- SI unit string, '' for none
    min_value      DOUBLE PRECISION,
    max_value      DOUBLE PRECISION,
    editable       BIGINT NOT NULL,             -- 1: users may override per drive
    default_json   TEXT COLLATE "C",                         -- JSON value, NULL for none
    comment        TEXT COLLATE "C" NOT NULL DEFAULT '',
    PRIMARY KEY (class_id, name)
);

-- Instances: a class with a value for every parameter (e.g. one motor from a datasheet).
CREATE TABLE library_instances (
    rowid       BIGINT GENERATED ALWAYS AS IDENTITY,
    id           TEXT COLLATE "C" PRIMARY KEY,
    class_id     TEXT COLLATE "C" NOT NULL REFERENCES library_classes(id) ON DELETE RESTRICT,
    name         TEXT COLLATE "C" NOT NULL,
    values_json  TEXT COLLATE "C" NOT NULL,                  -- {"param": value, ...}
    source       TEXT COLLATE "C" NOT NULL DEFAULT '',       -- where the values come from (datasheet)
    UNIQUE (class_id, name)
);

-- Drive assignments of a model, keyed by joint (its stable Modelica name).
CREATE TABLE drives (
    rowid       BIGINT GENERATED ALWAYS AS IDENTITY,
    model_id             TEXT COLLATE "C" NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    joint                TEXT COLLATE "C" NOT NULL,
    joint_node_id        TEXT COLLATE "C" NOT NULL,
    motor_instance       TEXT COLLATE "C" NOT NULL REFERENCES library_instances(id) ON DELETE RESTRICT,
    gear_instance        TEXT COLLATE "C" NOT NULL REFERENCES library_instances(id) ON DELETE RESTRICT,
    controller_instance  TEXT COLLATE "C" NOT NULL REFERENCES library_instances(id) ON DELETE RESTRICT,
    overrides_json       TEXT COLLATE "C" NOT NULL DEFAULT '{}',   -- {"instance_id.param": value}
    reference_json       TEXT COLLATE "C" NOT NULL,
    updated_at           TEXT COLLATE "C" NOT NULL,
    PRIMARY KEY (model_id, joint)
);

-- Bearer tokens for a service listening beyond loopback; only the SHA-256 is stored.
CREATE TABLE tokens (
    rowid       BIGINT GENERATED ALWAYS AS IDENTITY,
    id          TEXT COLLATE "C" PRIMARY KEY,
    name        TEXT COLLATE "C" NOT NULL,
    sha256      TEXT COLLATE "C" NOT NULL UNIQUE,
    created_at  TEXT COLLATE "C" NOT NULL
);
