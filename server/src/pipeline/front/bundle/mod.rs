//! Input bundles: a zip or a directory's files, held in memory.
