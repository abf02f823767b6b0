-- Poison jobs (the hardening issue): a conversion that kills the process would be re-queued at
-- every start and kill it again, forever.
--
-- jobs.attempts: how many times a worker claimed the job (incremented by the claim). A job that
-- is claimed again after reaching the limit (crate::jobs::MAX_ATTEMPTS) is marked failed instead
-- of being run. Existing jobs start at 0.
ALTER TABLE jobs ADD COLUMN attempts INTEGER NOT NULL DEFAULT 0;
