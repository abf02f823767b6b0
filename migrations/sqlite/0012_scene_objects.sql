-- Issue 29: a model's scene (the machine's environment: tables, pallets, conveyors, floors),
-- one row per object keyed by its name like the collision matrix, so the scene survives CAD
-- changes. `ord` keeps the user's order; `object_json` is the object as the API takes it
-- (shape, pose, kind, motion, mass), checked by the engine's `scene::check` before it is stored.

CREATE TABLE scene_objects (
    model_id    TEXT NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    name        TEXT NOT NULL,
    ord         INTEGER NOT NULL,
    object_json TEXT NOT NULL,
    updated_at  TEXT NOT NULL,
    PRIMARY KEY (model_id, name)
);
