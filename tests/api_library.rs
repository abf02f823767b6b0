//! API tests of the library endpoints (being written).
