-- PostgreSQL twin of migrations/sqlite/0012_simulations.sql: the same tables and columns (tests check it).
-- Types: INTEGER -> BIGINT, TEXT -> TEXT COLLATE "C"; `rowid` stands in for SQLite's implicit rowid.

-- Issue 28: closed-loop simulations of a model's drives. A run belongs to a converted version
-- of the model, follows a motion (motion_id; NULL when the drives follow their own references,
-- and set NULL when the motion is deleted) and leaves a MAT v4 result (result_id, a row of
-- `results` like an uploaded file). request_json is what was asked (duration, drives, start,
-- tolerances); answer_json the answer (verdict, per-drive tracking, saturation intervals, tool
-- error).

CREATE TABLE simulations (
    rowid          BIGINT GENERATED ALWAYS AS IDENTITY,
    id             TEXT COLLATE "C" PRIMARY KEY,
    model_id       TEXT COLLATE "C" NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    version        BIGINT NOT NULL,
    motion_id      TEXT COLLATE "C" REFERENCES motions(id) ON DELETE SET NULL,
    result_id      TEXT COLLATE "C" REFERENCES results(id) ON DELETE SET NULL,
    request_json   TEXT COLLATE "C" NOT NULL,
    answer_json    TEXT COLLATE "C" NOT NULL,
    created_at     TEXT COLLATE "C" NOT NULL
);
CREATE INDEX simulations_by_model ON simulations(model_id, created_at);
CREATE INDEX simulations_by_motion ON simulations(motion_id);
