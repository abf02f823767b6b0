-- Issue 12: joint limits and motions of a model. Both are keyed like drives (the joint's stable
-- Modelica name), belong to the model (not one version) and survive CAD changes; a joint that
-- vanishes leaves its limits orphaned (reported, never deleted).

CREATE TABLE joint_limits (
    model_id     TEXT NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    joint        TEXT NOT NULL,
    limits_json  TEXT NOT NULL,                  -- motion::plan::LimitsEdit (absent = default)
    updated_at   TEXT NOT NULL,
    PRIMARY KEY (model_id, joint)
);

CREATE TABLE motions (
    id          TEXT PRIMARY KEY,
    model_id    TEXT NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    name        TEXT NOT NULL,
    spec_json   TEXT NOT NULL,                   -- motion::plan::MotionSpec
    created_at  TEXT NOT NULL,
    updated_at  TEXT NOT NULL,
    UNIQUE (model_id, name)
);
CREATE INDEX motions_by_model ON motions(model_id, created_at);
