-- Issue 14: the allowed-collision matrix of a model: the pairs of bodies the user set as allowed
-- to touch (not checked) or not, keyed by the bodies' stable Modelica names like drives, so the
-- edits survive CAD changes. Pairs without a row take the default (bodies joined by a joint are
-- allowed). `body_a < body_b` (byte order) names each pair once.

CREATE TABLE collision_pairs (
    model_id    TEXT NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    body_a      TEXT NOT NULL,
    body_b      TEXT NOT NULL,
    allowed     INTEGER NOT NULL CHECK (allowed IN (0, 1)),
    updated_at  TEXT NOT NULL,
    PRIMARY KEY (model_id, body_a, body_b),
    CHECK (body_a < body_b)
);
