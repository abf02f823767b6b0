//! The one error type at the HTTP boundary: RFC 9457 `application/problem+json`.
//!
//! Bad input is always a 4xx with a stable `type` and a human `detail`; conversion errors carry
//! their diagnostics. A 5xx logs the cause and returns a generic message.

use axum::extract::rejection::{PathRejection, QueryRejection};
use axum::http::{header, StatusCode};
use axum::response::{IntoResponse, Response};
use serde::Serialize;

use crate::store::StoreError;
use cad2mo_engine::pipeline::{ConvertError, Diagnostic};

use crate::jobs::JobError;
use crate::service::collisions::CollisionError;
use crate::service::drives::DriveError;
use crate::service::export::ExportError;
use crate::service::models::ModelError;
use crate::service::motions::MotionError;
use crate::service::results::ResultError;
use crate::service::scene::SceneError;
use crate::service::simulations::SimulationError;
pub use crate::service::FieldError;

#[derive(Debug, thiserror::Error)]
pub enum ApiError {
    #[error("{0} not found")]
    NotFound(String),
    #[error("{0}")]
    BadRequest(String),
    #[error("{detail}")]
    Invalid { detail: String, errors: Vec<FieldError> },
    /// A motion that cannot be planned (IK failed, limits violated, unknown joint, ...).
    #[error("{detail}")]
    MotionInvalid { detail: String, errors: Vec<FieldError> },
    #[error("{0}")]
    Conflict(String),
    #[error("the upload exceeds the limit of {limit} bytes")]
    PayloadTooLarge { limit: u64 },
    /// A request body that paused longer than `--body-timeout` (the connection is closed after).
    #[error("the request body stalled longer than the body timeout (--body-timeout); the upload is dropped")]
    BodyTimeout,
    #[error("a valid bearer token is required")]
    Unauthorized,
    #[error("conversion failed: {0}")]
    Conversion(#[from] ConvertError),
    #[error(
        "the conversion stopped the service {times} times (it was running alone at each stop); \
         it is not tried again: check the bundle (size, meshes) or upload a new version"
    )]
    Aborted { times: i64 },
    #[error("too many uploads are being checked right now; retry in {retry_after} s")]
    Busy { retry_after: u64 },
    /// A simulation while `--workers` simulations run.
    #[error("{limit} simulation(s) are running (--workers); retry in 1 s")]
    SimulationsBusy { limit: usize },
    /// A request over the connection cap (`--max-connections`); only health is answered there.
    #[error("the service is serving its limit of {limit} connections (--max-connections); retry in 1 s")]
    TooManyConnections { limit: usize },
    /// A state-changing request from another web origin.
    #[error("{0}")]
    CrossOrigin(String),
    /// A state-changing request without a token that a web page could have sent cross-site.
    #[error("{0}")]
    ClientHeaderRequired(String),
    #[error("{0}")]
    MisdirectedHost(String),
    #[error("internal error")]
    Internal(#[from] anyhow::Error),
}

impl From<PathRejection> for ApiError {
    fn from(e: PathRejection) -> Self {
        ApiError::BadRequest(format!("invalid path parameter: {}", e.body_text()))
    }
}

impl From<QueryRejection> for ApiError {
    fn from(e: QueryRejection) -> Self {
        ApiError::BadRequest(format!("invalid query string: {}", e.body_text()))
    }
}

impl From<StoreError> for ApiError {
    fn from(e: StoreError) -> Self {
        if e.is_unique_violation() {
            ApiError::Conflict("an item with the same unique name already exists".into())
        } else if e.is_foreign_key_violation() {
            ApiError::Conflict("the item is still referred to by others (or refers to a missing item)".into())
        } else {
            ApiError::Internal(e.into())
        }
    }
}

// The use cases' errors, each mapped to its problem here and nowhere else.

impl From<ExportError> for ApiError {
    fn from(e: ExportError) -> Self {
        match e {
            ExportError::Bundle(b) => ApiError::Invalid {
                detail: format!("the bundle cannot be read: {b}"),
                errors: vec![FieldError { field: "bundle".into(), message: b.to_string() }],
            },
            ExportError::Convert(c) => ApiError::Conversion(c),
            ExportError::Zip(io) => ApiError::Internal(anyhow::Error::new(io).context("writing the package zip")),
        }
    }
}

impl From<ModelError> for ApiError {
    fn from(e: ModelError) -> Self {
        match e {
            ModelError::NotFound(what) => ApiError::NotFound(what),
            ModelError::Busy { retry_after } => ApiError::Busy { retry_after },
            ModelError::Conflict(why) => ApiError::Conflict(why),
            ModelError::Export(x) => x.into(),
            ModelError::Store(s) => s.into(),
            ModelError::Internal(e) => ApiError::Internal(e),
        }
    }
}

impl From<ResultError> for ApiError {
    fn from(e: ResultError) -> Self {
        match e {
            ResultError::Unreadable { name, message } => ApiError::Invalid {
                errors: vec![FieldError { field: "file".into(), message: format!("{name}: {message}") }],
                detail: message,
            },
            ResultError::NotFound(what) => ApiError::NotFound(what),
            ResultError::Store(s) => s.into(),
            ResultError::Internal(e) => ApiError::Internal(e),
        }
    }
}

impl From<DriveError> for ApiError {
    fn from(e: DriveError) -> Self {
        match e {
            DriveError::InstanceGone { .. } => ApiError::Conflict(e.to_string()),
            DriveError::Overrides { ref errors, .. } => ApiError::Invalid { errors: errors.clone(), detail: e.to_string() },
            DriveError::Store(s) => s.into(),
        }
    }
}

impl From<MotionError> for ApiError {
    fn from(e: MotionError) -> Self {
        match e {
            MotionError::Unsupported(ref what) => {
                ApiError::Invalid { errors: vec![FieldError { field: "model".into(), message: what.clone() }], detail: e.to_string() }
            }
            MotionError::CannotPlan { detail, errors } => ApiError::MotionInvalid { detail, errors },
            MotionError::OutOfRange(m) => ApiError::BadRequest(m),
            MotionError::BadSettings(ref errors) => ApiError::Invalid { errors: errors.clone(), detail: e.to_string() },
            MotionError::Dynamics(_) => ApiError::Internal(anyhow::anyhow!(e.to_string())),
            MotionError::Export(x) => x.into(),
            MotionError::Drive(d) => d.into(),
            MotionError::Store(s) => s.into(),
        }
    }
}

impl From<SceneError> for ApiError {
    fn from(e: SceneError) -> Self {
        match e {
            SceneError::Invalid(ref errors) => ApiError::Invalid { errors: errors.clone(), detail: e.to_string() },
        }
    }
}

impl From<SimulationError> for ApiError {
    fn from(e: SimulationError) -> Self {
        match e {
            SimulationError::Invalid(ref errors) => ApiError::Invalid { errors: errors.clone(), detail: e.to_string() },
            SimulationError::Stopped(ref m) => {
                ApiError::Invalid { errors: vec![FieldError { field: "duration".into(), message: m.clone() }], detail: e.to_string() }
            }
            SimulationError::Cancelled(_) => ApiError::Conflict(e.to_string()),
            SimulationError::NotFound(_) => ApiError::NotFound(e.to_string().trim_end_matches(" not found").to_string()),
            SimulationError::Motion(m) => m.into(),
            SimulationError::Drive(d) => d.into(),
            SimulationError::Result(r) => r.into(),
            SimulationError::Store(s) => s.into(),
            SimulationError::Internal(e) => ApiError::Internal(e),
        }
    }
}

impl From<CollisionError> for ApiError {
    fn from(e: CollisionError) -> Self {
        match e {
            CollisionError::Corrupt(what) => ApiError::Internal(anyhow::anyhow!(what)),
            CollisionError::Motion(m) => m.into(),
            CollisionError::TooLarge(detail) => {
                ApiError::Invalid { errors: vec![FieldError { field: "motion".into(), message: detail.clone() }], detail }
            }
        }
    }
}

impl From<JobError> for ApiError {
    fn from(e: JobError) -> Self {
        match e {
            JobError::NotFound(what) => ApiError::NotFound(what),
            JobError::Aborted { times } => ApiError::Aborted { times },
            JobError::Export(x) => x.into(),
            JobError::Drive(d) => d.into(),
            JobError::Store(s) => s.into(),
            JobError::Internal(e) => ApiError::Internal(e),
        }
    }
}

/// The document stored with a failed job (and served with it): its problem; an internal error
/// is logged here as a route's is when it answers.
pub fn job_problem(e: JobError) -> serde_json::Value {
    let api = ApiError::from(e);
    if let ApiError::Internal(cause) = &api {
        tracing::error!(error = ?cause, "job failed: internal error");
    }
    api.problem_json()
}

/// Most field errors or diagnostics listed in one problem document.
const MAX_LISTED: usize = 100;

#[derive(Serialize)]
struct Problem<'a> {
    #[serde(rename = "type")]
    kind: String,
    title: &'a str,
    status: u16,
    detail: String,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    errors: Vec<FieldError>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    diagnostics: Vec<Diagnostic>,
}

impl ApiError {
    /// (status, stable slug, title).
    fn parts(&self) -> (StatusCode, &'static str, &'static str) {
        match self {
            ApiError::NotFound(_) => (StatusCode::NOT_FOUND, "not-found", "Not found"),
            ApiError::BadRequest(_) => (StatusCode::BAD_REQUEST, "bad-request", "Bad request"),
            ApiError::Invalid { .. } => (StatusCode::UNPROCESSABLE_ENTITY, "invalid", "Invalid input"),
            ApiError::MotionInvalid { .. } => (StatusCode::UNPROCESSABLE_ENTITY, "motion-invalid", "Motion cannot be planned"),
            ApiError::Conflict(_) => (StatusCode::CONFLICT, "conflict", "Conflict"),
            ApiError::PayloadTooLarge { .. } => (StatusCode::PAYLOAD_TOO_LARGE, "payload-too-large", "Upload too large"),
            ApiError::BodyTimeout => (StatusCode::REQUEST_TIMEOUT, "request-timeout", "Request timeout"),
            ApiError::Unauthorized => (StatusCode::UNAUTHORIZED, "unauthorized", "Unauthorized"),
            ApiError::Conversion(_) => (StatusCode::UNPROCESSABLE_ENTITY, "conversion-failed", "Conversion failed"),
            ApiError::Aborted { .. } => (StatusCode::UNPROCESSABLE_ENTITY, "conversion-aborted", "Conversion aborted"),
            ApiError::Busy { .. } | ApiError::SimulationsBusy { .. } | ApiError::TooManyConnections { .. } => {
                (StatusCode::SERVICE_UNAVAILABLE, "busy", "Busy")
            }
            ApiError::CrossOrigin(_) => (StatusCode::FORBIDDEN, "cross-origin", "Cross-origin request refused"),
            ApiError::ClientHeaderRequired(_) => {
                (StatusCode::FORBIDDEN, "client-header-required", "Request refused without a token or client header")
            }
            ApiError::MisdirectedHost(_) => (StatusCode::MISDIRECTED_REQUEST, "misdirected-request", "Unknown host"),
            ApiError::Internal(_) => (StatusCode::INTERNAL_SERVER_ERROR, "internal", "Internal error"),
        }
    }

    /// The problem document, for storing with a failed job.
    pub fn problem_json(&self) -> serde_json::Value {
        let (status, slug, title) = self.parts();
        let (errors, diagnostics) = match self {
            ApiError::Invalid { errors, .. } | ApiError::MotionInvalid { errors, .. } => (errors.clone(), Vec::new()),
            ApiError::Conversion(e) => (Vec::new(), e.diagnostics()),
            _ => (Vec::new(), Vec::new()),
        };
        let p = Problem {
            kind: format!("/problems/{slug}"),
            title,
            status: status.as_u16(),
            // Bounded whatever the input: a problem document never carries megabytes.
            detail: cad2mo_engine::pipeline::ir::clip(&compact_numbers(&self.to_string()), cad2mo_engine::pipeline::MAX_MESSAGE_BYTES),
            errors: errors.into_iter().take(MAX_LISTED).map(|e| FieldError { message: compact_numbers(&e.message), ..e }).collect(),
            diagnostics: diagnostics.into_iter().take(MAX_LISTED).collect(),
        };
        serde_json::to_value(p).unwrap_or_default()
    }
}

/// Numbers written out in more than 24 characters (Rust prints `1e308` as 309 digits) in
/// scientific notation: a problem echoes a user's number without its every digit.
fn compact_numbers(text: &str) -> String {
    const LONGEST: usize = 24;
    let mut out = String::with_capacity(text.len().min(4096));
    let mut run = String::new();
    let flush = |run: &mut String, out: &mut String| {
        match run.parse::<f64>() {
            Ok(x) if run.len() > LONGEST => out.push_str(&format!("{x:e}")),
            _ => out.push_str(run),
        }
        run.clear();
    };
    for ch in text.chars() {
        if ch.is_ascii_digit() || (ch == '.' && !run.is_empty()) {
            run.push(ch);
        } else {
            flush(&mut run, &mut out);
            out.push(ch);
        }
    }
    flush(&mut run, &mut out);
    out
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        if let ApiError::Internal(e) = &self {
            tracing::error!(error = ?e, "internal error");
        }
        let (status, _, _) = self.parts();
        let mut resp = (status, [(header::CONTENT_TYPE, "application/problem+json")], self.problem_json().to_string()).into_response();
        match &self {
            ApiError::Unauthorized => {
                resp.headers_mut().insert(header::WWW_AUTHENTICATE, axum::http::HeaderValue::from_static("Bearer"));
            }
            ApiError::Busy { retry_after } => {
                resp.headers_mut().insert(header::RETRY_AFTER, axum::http::HeaderValue::from(*retry_after));
            }
            ApiError::SimulationsBusy { .. } => {
                resp.headers_mut().insert(header::RETRY_AFTER, axum::http::HeaderValue::from(1u64));
            }
            ApiError::TooManyConnections { .. } => {
                resp.headers_mut().insert(header::RETRY_AFTER, axum::http::HeaderValue::from(1u64));
                resp.headers_mut().insert(header::CONNECTION, axum::http::HeaderValue::from_static("close"));
            }
            _ => {}
        }
        resp
    }
}

/// Runs blocking work (IO, conversion) off the async runtime: the use cases' helper with the
/// routes' error type fixed, so closures need no annotation.
pub async fn blocking<T: Send + 'static>(f: impl FnOnce() -> Result<T, ApiError> + Send + 'static) -> Result<T, ApiError> {
    crate::service::blocking(f).await
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn huge_numbers_are_compacted_in_problems() {
        let rate = 1e308;
        let p = ApiError::BadRequest(format!("rate must be between 1 and 10000 Hz (is {rate}). 0.5 stays")).problem_json();
        assert_eq!(p["detail"], "rate must be between 1 and 10000 Hz (is 1e308). 0.5 stays", "{p}");
        let tiny = 1e-30;
        assert_eq!(compact_numbers(&format!("{tiny} and 12345")), "1e-30 and 12345");
    }

    /// Each use case's error becomes the problem the API promises (status and type).
    #[test]
    fn use_case_errors_map_to_problems() {
        let e = crate::service::export::check_bundle(b"not a zip", "x.zip", &Default::default(), None).expect_err("not a zip");
        let p = ApiError::from(e).problem_json();
        assert_eq!((p["status"].as_u64(), p["type"].as_str()), (Some(422), Some("/problems/invalid")));
        assert!(p["detail"].as_str().is_some_and(|d| d.contains("x.zip")), "{p}");
        let cases: [(ApiError, u64, &str); 6] = [
            (MotionError::OutOfRange("rate".into()).into(), 400, "bad-request"),
            (MotionError::BadSettings(vec![FieldError { field: "reserve".into(), message: "m".into() }]).into(), 422, "invalid"),
            (MotionError::CannotPlan { detail: "d".into(), errors: vec![] }.into(), 422, "motion-invalid"),
            (DriveError::InstanceGone { joint: "J".into(), instance: "i".into() }.into(), 409, "conflict"),
            (CollisionError::Corrupt("no CS1".into()).into(), 500, "internal"),
            (CollisionError::TooLarge("limit".into()).into(), 422, "invalid"),
        ];
        for (api, status, slug) in cases {
            let p = api.problem_json();
            assert_eq!((p["status"].as_u64(), p["type"].as_str()), (Some(status), Some(format!("/problems/{slug}").as_str())), "{p}");
        }
        let stored = job_problem(JobError::Aborted { times: 3 });
        assert_eq!(stored["type"], "/problems/conversion-aborted");
        assert!(stored["detail"].as_str().is_some_and(|d| d.contains("3 times")));
    }
}
