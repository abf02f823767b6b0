//! The cad2mo service: everything that runs behind `cad2mo serve`. The computation it calls is
//! `cad2mo-engine` (no IO there); this crate adds the IO around it.
//!
//! - [`service`]: the use cases (versions and their packages, drives, motions and sizing,
//!   collisions), each with its own error type; no HTTP and no SQL of their own.
//! - [`api`]: HTTP (axum): routes, extractors, the mapping of the use cases' errors to
//!   problem+json, the embedded browser UI. Nothing else imports it.
//! - [`store`]: SQL (sqlx, SQLite or PostgreSQL) and the content-addressed blob store.
//! - [`jobs`]: the bounded conversion worker pool and its queue.
//! - [`relay`]: the live view's UDP relay (frames decoded by `cad2mo_engine::live`).
//! - [`app`], [`config`], [`telemetry`]: start-up, settings, logging.

pub mod api;
pub mod app;
pub mod config;
pub mod jobs;
pub mod relay;
pub mod service;
pub mod store;
pub mod telemetry;
