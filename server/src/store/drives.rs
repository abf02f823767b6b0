//! SQL for drives (being written).
