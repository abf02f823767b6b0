//! API tests of the models endpoints (being written).
