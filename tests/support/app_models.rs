//! `TestApp` methods for the models endpoints (being written).
