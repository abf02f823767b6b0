//! SQL for models (being written).
