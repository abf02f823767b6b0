//! Shared helpers for cad2mo's integration tests.
