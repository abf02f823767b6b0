//! Shared helpers for cad2mo's integration tests.
//!
//! - [`common`]: locating fixtures and tools, converting bundles, writing packages to disk.
//! - [`modelica`], [`fk`]: an independent reader of the `Mechanics.mo` we emit and a forward
//!   kinematics walker over it (they deliberately use nothing from the converter).
//! - [`truth`]: frames and CGs scanned straight from an XML export; [`xml2_truth`] the same for
//!   second-generation Simscape Multibody XML.
//! - [`check`]: the FK comparison of an output against that truth.
//! - [`structure`]: structural rank of closed loops (redundant equations, mobility) of the emitted
//!   model and of the XML assembly.
//! - [`app`]: `TestApp`, the real service spawned on port 0 with a fresh database.
//! - [`s3`]: the S3-compatible test server (a bucket, a prefix per test); [`instances`]: real
//!   `cad2mo serve` processes for the multi-instance tests.

pub mod app;
pub mod app_library;
pub mod app_models;
pub mod check;
pub mod common;
pub mod diagram;
pub mod fk;
pub mod instances;
pub mod live;
pub mod modelica;
pub mod s3;
pub mod structure;
pub mod truth;
pub mod urdf_truth;
pub mod xml2_truth;
