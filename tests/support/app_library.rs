//! `TestApp` methods for the library endpoints (being written).
