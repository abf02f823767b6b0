//! cad2mo: converts CAD assembly exports into Modelica packages, as a command line and a service.
//!
//! - [`pipeline`]: the converter itself. Bytes and options in, files and diagnostics out; no IO.
//! - [`cli`]: the command line (reads bundles from disk, writes zips atomically, runs the service).
//! - [`app`], [`config`], [`telemetry`]: the service's start-up.
//! - [`api`]: HTTP (axum); [`store`]: SQLite (sqlx) and the content-addressed file store.
//! - [`jobs`]: the bounded conversion worker pool; [`export`]: a version's package from its
//!   bundle; [`diff`]: what changed between two conversions; [`library`]: the motor library's rules.
//! - [`mechanism`]: motion and inverse dynamics of a validated model (kinematics, loop assembly,
//!   IK, RNEA), in the emitted Modelica model's joint coordinates.
//! - [`sizing`]: drive sizing of a motion's joint loads against the motor library (checks,
//!   operating points, ranked alternatives).

pub mod api;
pub mod app;
pub mod cli;
pub mod collision;
pub mod collisions;
pub mod config;
pub mod drives;
pub mod diff;
pub mod export;
pub mod jobs;
pub mod library;
pub mod mechanism;
pub mod motion;
pub mod live;
pub mod motions;
pub mod relay;
pub mod pipeline;
pub mod results;
pub mod sizing;
pub mod store;
pub mod telemetry;

/// Generated test models (shared with the benchmarks).
#[cfg(test)]
#[path = "../benches/support/gen.rs"]
#[allow(dead_code)]
pub(crate) mod testgen;
