-- Issue 28: closed-loop simulations of a model's drives. A run belongs to a converted version
-- of the model, follows a motion (motion_id; NULL when the drives follow their own references,
-- and set NULL when the motion is deleted) and leaves a MAT v4 result (result_id, a row of
-- `results` like an uploaded file). request_json is what was asked (duration, drives, start,
-- tolerances); answer_json the answer (verdict, per-drive tracking, saturation intervals, tool
-- error).

CREATE TABLE simulations (
    id             TEXT PRIMARY KEY,
    model_id       TEXT NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    version        INTEGER NOT NULL,
    motion_id      TEXT REFERENCES motions(id) ON DELETE SET NULL,
    result_id      TEXT REFERENCES results(id) ON DELETE SET NULL,
    request_json   TEXT NOT NULL,
    answer_json    TEXT NOT NULL,
    created_at     TEXT NOT NULL
);
CREATE INDEX simulations_by_model ON simulations(model_id, created_at);
CREATE INDEX simulations_by_motion ON simulations(motion_id);
