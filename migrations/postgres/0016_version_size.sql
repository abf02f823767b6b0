-- PostgreSQL twin of migrations/sqlite/0016_version_size.sql: the same tables and columns (tests check it).
--
-- versions.triangles: the meshes' triangles after instancing; versions.bundle_bytes: the bundle's
-- inflated size. Known at upload; the job's peak memory is estimated from them (NULL: the whole
-- --job-memory budget, run alone).
ALTER TABLE versions ADD COLUMN triangles BIGINT;
ALTER TABLE versions ADD COLUMN bundle_bytes BIGINT;
