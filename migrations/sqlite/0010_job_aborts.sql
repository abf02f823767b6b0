-- Issue 26: a process abort is charged only to the job whose work caused it.
--
-- jobs.isolate: the job was running, with others, when its instance stopped (a crash, a kill):
-- it is re-run alone (no other job of the instance at the same time) before anything else, so
-- that a crash during that run can be blamed on it (crate::jobs, store::models::requeue_unfinished).
-- jobs.aborts: stops of its instance while the job was the only one running there. A job with 2
-- is quarantined: failed with /problems/conversion-aborted, not run again, listed by GET /api/jobs.
ALTER TABLE jobs ADD COLUMN isolate INTEGER NOT NULL DEFAULT 0;
ALTER TABLE jobs ADD COLUMN aborts INTEGER NOT NULL DEFAULT 0;
