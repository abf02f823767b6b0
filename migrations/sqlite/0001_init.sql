-- cad2mo's store: models and their versions, conversion jobs, the motor library, drive
-- assignments and API tokens. Applied by sqlx::migrate! at start-up. Never edit an applied
-- migration: add a new one.
--
-- Conventions: ids are UUIDs (TEXT); times are RFC 3339 UTC (TEXT); JSON columns hold
-- serde-serialised structs; files (bundles, packages, reports) live on disk, content-addressed
-- by SHA-256, and are referred to by their hex digest.

-- A model: one CAD assembly across all its exports.
CREATE TABLE models (
    id          TEXT PRIMARY KEY,
    name        TEXT NOT NULL,
    created_at  TEXT NOT NULL
);

-- One uploaded export of a model and its conversion.
CREATE TABLE versions (
    model_id        TEXT NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    version         INTEGER NOT NULL,
    created_at      TEXT NOT NULL,
    bundle_name     TEXT NOT NULL,
    bundle_sha256   TEXT NOT NULL,
    options_json    TEXT NOT NULL,               -- conversion options used
    status          TEXT NOT NULL CHECK (status IN ('queued', 'running', 'succeeded', 'failed')),
    package_sha256  TEXT,                        -- output zip, once converted
    report_sha256   TEXT,                        -- report.json, once converted
    error_json      TEXT,                        -- problem details, when failed
    PRIMARY KEY (model_id, version)
);

-- Background work: a conversion of one version, or a re-export.
CREATE TABLE jobs (
    id           TEXT PRIMARY KEY,
    kind         TEXT NOT NULL CHECK (kind IN ('convert', 'reexport')),
    model_id     TEXT NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    version      INTEGER NOT NULL,
    status       TEXT NOT NULL CHECK (status IN ('queued', 'running', 'succeeded', 'failed')),
    error_json   TEXT,
    created_at   TEXT NOT NULL,
    started_at   TEXT,
    finished_at  TEXT
);
CREATE INDEX jobs_by_status ON jobs(status);

-- The motor library (the paper's object library): classes and their typed parameters.
CREATE TABLE library_classes (
    id              TEXT PRIMARY KEY,
    name            TEXT NOT NULL UNIQUE,
    domain          TEXT NOT NULL,               -- motor, gear, controller, ...
    modelica_class  TEXT NOT NULL,               -- full path; `cad2mo.` = our own Components
    description     TEXT NOT NULL DEFAULT ''
);

CREATE TABLE library_parameters (
    class_id       TEXT NOT NULL REFERENCES library_classes(id) ON DELETE CASCADE,
    name           TEXT NOT NULL,                -- the Modelica parameter it sets
    position       INTEGER NOT NULL,             -- display order
    type           TEXT NOT NULL CHECK (type IN ('Real', 'Integer', 'Boolean', 'String')),
    unit           TEXT NOT NULL DEFAULT '',     -- SI unit string, '' for none
    min_value      REAL,
    max_value      REAL,
    editable       INTEGER NOT NULL,             -- 1: users may override per drive
    default_json   TEXT,                         -- JSON value, NULL for none
    comment        TEXT NOT NULL DEFAULT '',
    PRIMARY KEY (class_id, name)
);

-- Instances: a class with a value for every parameter (e.g. one motor from a datasheet).
CREATE TABLE library_instances (
    id           TEXT PRIMARY KEY,
    class_id     TEXT NOT NULL REFERENCES library_classes(id) ON DELETE RESTRICT,
    name         TEXT NOT NULL,
    values_json  TEXT NOT NULL,                  -- {"param": value, ...}
    source       TEXT NOT NULL DEFAULT '',       -- where the values come from (datasheet)
    UNIQUE (class_id, name)
);

-- Drive assignments of a model, keyed by joint (its stable Modelica name).
CREATE TABLE drives (
    model_id             TEXT NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    joint                TEXT NOT NULL,
    joint_node_id        TEXT NOT NULL,
    motor_instance       TEXT NOT NULL REFERENCES library_instances(id) ON DELETE RESTRICT,
    gear_instance        TEXT NOT NULL REFERENCES library_instances(id) ON DELETE RESTRICT,
    controller_instance  TEXT NOT NULL REFERENCES library_instances(id) ON DELETE RESTRICT,
    overrides_json       TEXT NOT NULL DEFAULT '{}',   -- {"instance_id.param": value}
    reference_json       TEXT NOT NULL,
    updated_at           TEXT NOT NULL,
    PRIMARY KEY (model_id, joint)
);

-- Bearer tokens for a service listening beyond loopback; only the SHA-256 is stored.
CREATE TABLE tokens (
    id          TEXT PRIMARY KEY,
    name        TEXT NOT NULL,
    sha256      TEXT NOT NULL UNIQUE,
    created_at  TEXT NOT NULL
);
