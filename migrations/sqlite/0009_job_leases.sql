-- Issue 16: several service instances on one database.
--
-- jobs.lease_owner, jobs.lease_until: the instance running a job (its random id, new at every
-- start) and until when its claim holds (RFC 3339 UTC, like the other times). The instance renews
-- the lease while the job runs (crate::jobs); a `running` job whose lease has passed was left by an
-- instance that died, and is claimed again by another (an attempt more). Finishing a job is
-- conditional on still holding its lease, so a late instance never overwrites the result of the
-- one that took over. NULL for jobs not running (and for jobs of a server before this migration).
ALTER TABLE jobs ADD COLUMN lease_owner TEXT;
ALTER TABLE jobs ADD COLUMN lease_until TEXT;

-- jobs.progress_json: the latest progress of a running job (crate::jobs::JobProgress as JSON),
-- written at most a few times a second, so any instance can show a job another one runs.
ALTER TABLE jobs ADD COLUMN progress_json TEXT;
