-- Issue 29: meshes uploaded for a model's scene objects, by name (a mesh object's shape names
-- one). The mesh itself is a blob (a binary STL in the file's own units, as the engine's
-- `scene::mesh::read` writes it); `triangles` is its triangle count.

CREATE TABLE scene_meshes (
    model_id    TEXT NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    name        TEXT NOT NULL,
    blob_sha256 TEXT NOT NULL,
    triangles   INTEGER NOT NULL,
    updated_at  TEXT NOT NULL,
    PRIMARY KEY (model_id, name)
);
