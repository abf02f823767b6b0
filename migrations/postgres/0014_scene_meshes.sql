-- PostgreSQL twin of migrations/sqlite/0014_scene_meshes.sql: the same tables and columns (tests check it).
-- Types: INTEGER -> BIGINT, TEXT -> TEXT COLLATE "C" (byte order, like SQLite's). `rowid BIGINT
-- GENERATED ALWAYS AS IDENTITY` stands in for SQLite's implicit rowid; the schema test leaves it out.

-- Issue 29: meshes uploaded for a model's scene objects, by name (a mesh object's shape names
-- one). The mesh itself is a blob (a binary STL in the file's own units, as the engine's
-- `scene::mesh::read` writes it); `triangles` is its triangle count.

CREATE TABLE scene_meshes (
    rowid       BIGINT GENERATED ALWAYS AS IDENTITY,
    model_id    TEXT COLLATE "C" NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    name        TEXT COLLATE "C" NOT NULL,
    blob_sha256 TEXT COLLATE "C" NOT NULL,
    triangles   BIGINT NOT NULL,
    updated_at  TEXT COLLATE "C" NOT NULL,
    PRIMARY KEY (model_id, name)
);
