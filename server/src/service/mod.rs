//! The service's use cases: what a user can do with a model, between the HTTP routes and the
//! computation (`cad2mo_engine`). Each returns its own error type; none knows HTTP (the
//! mapping to problem+json is `api::error`'s) and none writes SQL (that is `store`'s).
//!
//! - [`models`]: models and versions: uploads checked and stored, conversions queued, stored
//!   outputs, diffs.
//! - [`export`]: a version's package from its stored bundle (check, convert, zip).
//! - [`drives`]: which motor, gear and controller drive which joint, resolved for the package.
//! - [`motions`]: motions on a version (joints, planning, trajectories, sizing).
//! - [`results`]: simulation result files checked, stored and read.
//! - [`simulations`]: closed-loop simulations of the drives (issue 28): answer and result file.
//! - [`collisions`]: a version's collision shapes, the allowed-collision matrix, checks along a
//!   motion.

use serde::Serialize;

pub mod collisions;
pub mod drives;
pub mod export;
pub mod models;
pub mod motions;
pub mod results;
pub mod scene;
pub mod simulations;

/// Runs blocking work (file store, analysis, conversion) off the async runtime, in the caller's
/// span; a task that panics is an internal error of the use case.
pub(crate) async fn blocking<T, E>(f: impl FnOnce() -> Result<T, E> + Send + 'static) -> Result<T, E>
where
    T: Send + 'static,
    E: From<anyhow::Error> + Send + 'static,
{
    let span = tracing::Span::current();
    tokio::task::spawn_blocking(move || span.in_scope(f)).await.map_err(|e| E::from(e.into()))?
}

/// A field-level validation message: which input field (dotted path) and what is wrong with it.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct FieldError {
    pub field: String,
    pub message: String,
}

impl From<cad2mo_engine::library::Issue> for FieldError {
    fn from(i: cad2mo_engine::library::Issue) -> Self {
        FieldError { field: i.field, message: i.message }
    }
}
