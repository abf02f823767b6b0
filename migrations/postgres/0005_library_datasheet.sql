-- PostgreSQL twin of migrations/sqlite/0005_library_datasheet.sql: the same tables and columns (tests check it).
-- Types: INTEGER -> BIGINT, REAL -> DOUBLE PRECISION, TEXT -> TEXT COLLATE "C" (byte order,
-- like SQLite's). `rowid BIGINT GENERATED ALWAYS AS IDENTITY` stands in for SQLite's implicit
-- rowid (insertion order for ORDER BY ... rowid); the schema test leaves it out.

-- Datasheet parameters of library classes (issue 12, drive sizing).
--
-- The drive sizing (server/src/sizing/) needs catalog values that are not Modelica parameters of
-- the classes: a motor's nominal torque, peak torque and maximum speed, a gear's rated and peak
-- output torque, maximum input speed and inertia. They are library parameters like the others
-- (typed, with units and limits, shown by the API, exchanged in the XML), marked as datasheet
-- values: never written as Modelica modifiers, and optional per instance (a check that needs a
-- missing one is reported as not evaluated).
--
-- library_parameters.datasheet: 1 for a datasheet value, 0 (every existing parameter) for a
-- Modelica parameter.
ALTER TABLE library_parameters ADD COLUMN datasheet BIGINT NOT NULL DEFAULT 0;

-- The data part of the SQLite migration (datasheet parameters and values for an old seed) has
-- nothing to do here: a PostgreSQL database is always new, seeded after the migrations from
-- server/src/library/seed.rs, which already has them.
