-- PostgreSQL twin of migrations/sqlite/0012_scene_objects.sql: the same tables and columns (tests check it).
-- Types: INTEGER -> BIGINT, REAL -> DOUBLE PRECISION, TEXT -> TEXT COLLATE "C" (byte order,
-- like SQLite's). `rowid BIGINT GENERATED ALWAYS AS IDENTITY` stands in for SQLite's implicit
-- rowid (insertion order for ORDER BY ... rowid); the schema test leaves it out.

-- Issue 29: a model's scene (the machine's environment: tables, pallets, conveyors, floors),
-- one row per object keyed by its name like the collision matrix, so the scene survives CAD
-- changes. `ord` keeps the user's order; `object_json` is the object as the API takes it
-- (shape, pose, kind, motion, mass), checked by the engine's `scene::check` before it is stored.

CREATE TABLE scene_objects (
    rowid       BIGINT GENERATED ALWAYS AS IDENTITY,
    model_id    TEXT COLLATE "C" NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    name        TEXT COLLATE "C" NOT NULL,
    ord         BIGINT NOT NULL,
    object_json TEXT COLLATE "C" NOT NULL,
    updated_at  TEXT COLLATE "C" NOT NULL,
    PRIMARY KEY (model_id, name)
);
