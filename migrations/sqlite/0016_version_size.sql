-- Issue 26: memory-aware job admission. What a version's conversion will hold, known at upload
-- (the upload's check analyses the bundle): versions.triangles, its meshes' triangles counted
-- after instancing (a mesh named by several links counts once per use), and
-- versions.bundle_bytes, the bundle's inflated size. crate::jobs estimates a job's peak memory
-- from them (cad2mo_engine::pipeline::peak_memory_estimate) and starts it only when the estimate
-- fits beside the running jobs within --job-memory. NULL for versions uploaded before: their
-- jobs are estimated at the whole budget (run alone).
ALTER TABLE versions ADD COLUMN triangles INTEGER;
ALTER TABLE versions ADD COLUMN bundle_bytes INTEGER;
