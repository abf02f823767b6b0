-- PostgreSQL twin of migrations/sqlite/0008_collision_pairs.sql: the same tables and columns (tests check it).
-- Types: INTEGER -> BIGINT, REAL -> DOUBLE PRECISION, TEXT -> TEXT COLLATE "C" (byte order,
-- like SQLite's). `rowid BIGINT GENERATED ALWAYS AS IDENTITY` stands in for SQLite's implicit
-- rowid (insertion order for ORDER BY ... rowid); the schema test leaves it out.

-- Issue 14: the allowed-collision matrix of a model: the pairs of bodies the user set as allowed
-- to touch (not checked) or not, keyed by the bodies' stable Modelica names like drives, so the
-- edits survive CAD changes. Pairs without a row take the default (bodies joined by a joint are
-- allowed). `body_a < body_b` (byte order) names each pair once.

CREATE TABLE collision_pairs (
    rowid       BIGINT GENERATED ALWAYS AS IDENTITY,
    model_id    TEXT COLLATE "C" NOT NULL REFERENCES models(id) ON DELETE CASCADE,
    body_a      TEXT COLLATE "C" NOT NULL,
    body_b      TEXT COLLATE "C" NOT NULL,
    allowed     BIGINT NOT NULL CHECK (allowed IN (0, 1)),
    updated_at  TEXT COLLATE "C" NOT NULL,
    PRIMARY KEY (model_id, body_a, body_b),
    CHECK (body_a < body_b)
);
