//! The conversion pipeline: front ends -> IR -> passes -> validation -> back ends.
//!
//! Architecture invariant: nothing under `pipeline` performs IO or depends on an async runtime,
//! a web framework or a database. Bytes and options come in, files and diagnostics go out.
//! (`tests/tidy.rs` enforces this.)

pub mod back;
pub mod front;
pub mod ir;
