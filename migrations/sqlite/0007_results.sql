-- Issue 13: simulation result files (MAT v4 from Dymola or OpenModelica), uploaded to a model
-- version or standalone (model_id and version NULL: a result of any Modelica model). The file
-- is a blob; its summary (variables, time span, where each body's pose comes from, the
-- self-checks, visual shapes) is kept with it.

CREATE TABLE results (
    id             TEXT PRIMARY KEY,
    model_id       TEXT,
    version        INTEGER,
    name           TEXT NOT NULL,                -- the uploaded file's (safe) name
    size           INTEGER NOT NULL,
    blob_sha256    TEXT NOT NULL,
    summary_json   TEXT NOT NULL,
    created_at     TEXT NOT NULL,
    FOREIGN KEY (model_id, version) REFERENCES versions(model_id, version) ON DELETE CASCADE
);
CREATE INDEX results_by_version ON results(model_id, version, created_at);

