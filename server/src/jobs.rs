//! Background conversion jobs (being written).
