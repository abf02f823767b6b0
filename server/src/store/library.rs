//! SQL for library (being written).
