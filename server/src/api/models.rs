//! The models resource: uploads (a model's first version, or a new version), their conversions'
//! outputs, the original bundles, and the diff between two versions.
//!
//! | route | answer |
//! |---|---|
//! | `POST /api/models` (multipart) | 202 `{model_id, version, job_id}`, `Location: /api/jobs/{job_id}` |
//! | `GET /api/models` | 200 `[model]` (id, name, created_at, latest_version {version, status}) |
//! | `GET /api/models/{id}` | 200 model with `versions` |
//! | `DELETE /api/models/{id}` | 204 (versions, jobs and drives go with it) |
//! | `POST /api/models/{id}/versions` (multipart) | 202 as above; 404 unknown model |
//! | `GET /api/models/{id}/versions` | 200 `[version]` |
//! | `GET /api/models/{id}/versions/{v}` | 200 version (status, job, bundle, options, error, summary) |
//! | `DELETE /api/models/{id}/versions/{v}` | 204 |
//! | `GET .../versions/{v}/package.zip` | 200 zip; 409 not converted yet; the stored problem if failed |
//! | `GET .../versions/{v}/diagram.svg?model=Mechanics\|Mechatronics` | 200 the model's diagram drawn from its annotations; same errors |
//! | `GET .../versions/{v}/robot.urdf` | 200 the package's `<Pkg>/<Pkg>.urdf`; same errors; 404 when the package has none |
//! | `GET .../versions/{v}/report` | 200 report.json; same errors |
//! | `GET .../versions/{v}/bundle` | 200 the uploaded zip, byte for byte |
//! | `GET /api/models/{id}/diff?from=1&to=2` | 200 bodies and joints added, removed, changed |
//!
//! Uploads: multipart parts `bundle` (the zip, required), `name`, `package_name`, `gravity`
//! ("x,y,z") and `lump_welds` ("true"/"false"); `name` names a new model (default: the
//! assembly's name from the XML) and is ignored for a new version. The body may not exceed `settings.max_upload`
//! (413). The bundle is read and analysed at once, off the runtime, at most `settings.max_checks`
//! at a time (beyond that, after `settings.check_wait`, a 503 with `Retry-After`): an unreadable or unsafe zip
//! is a 422 naming the bundle, bad XML a 422 with the diagnostics; nothing is stored then.
//! Otherwise the bundle blob is stored, then the model/version/job rows in one transaction, and
//! the conversion is left to the workers (`crate::jobs`).

use axum::body::Bytes;
use axum::extract::rejection::{PathRejection, QueryRejection};
use axum::extract::{DefaultBodyLimit, FromRequest, Multipart, Path, Query, Request, State};
use axum::http::{header, HeaderMap, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use axum::{Json, Router};
use serde::{Deserialize, Serialize};
use serde_json::Value;

use super::error::{blocking, FieldError};
use super::ApiError;
use crate::app::AppState;
use crate::service::export::{ExportOptions, Summary};
use crate::service::models::{self, Output};
use crate::store::models::{self as db, Created, ModelRow, VersionRow};

pub fn router() -> Router<AppState> {
    Router::new()
        .route("/api/models", get(list_models).post(create_model))
        .route("/api/models/{model_id}", get(get_model).delete(delete_model))
        .route("/api/models/{model_id}/versions", get(list_versions).post(create_version))
        .route("/api/models/{model_id}/versions/{version}", get(get_version).delete(delete_version))
        .route("/api/models/{model_id}/versions/{version}/package.zip", get(package))
        .route("/api/models/{model_id}/versions/{version}/robot.urdf", get(robot_urdf))
        .route("/api/models/{model_id}/versions/{version}/diagram.svg", get(diagram_svg))
        .route("/api/models/{model_id}/versions/{version}/report", get(report))
        .route("/api/models/{model_id}/versions/{version}/bundle", get(bundle))
        .route("/api/models/{model_id}/diff", get(diff))
}

// ---------------------------------------------------------------------------------------------
// Responses

#[derive(Serialize)]
struct Accepted {
    model_id: String,
    version: i64,
    job_id: String,
}

#[derive(Serialize)]
struct LatestVersion {
    version: i64,
    status: String,
}

#[derive(Serialize)]
struct ModelView {
    id: String,
    name: String,
    created_at: String,
    latest_version: Option<LatestVersion>,
}

#[derive(Serialize)]
struct ModelDetail {
    #[serde(flatten)]
    model: ModelView,
    versions: Vec<VersionView>,
}

#[derive(Serialize)]
struct BundleInfo {
    name: String,
    size: i64,
    sha256: String,
}

#[derive(Serialize)]
struct Links {
    package: String,
    urdf: String,
    diagram: String,
    report: String,
    bundle: String,
    job: Option<String>,
}

#[derive(Serialize)]
struct VersionView {
    model_id: String,
    version: i64,
    created_at: String,
    status: String,
    job_id: Option<String>,
    bundle: BundleInfo,
    options: ExportOptions,
    /// The problem document, when the conversion failed.
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<Value>,
    /// Counts from the report, once converted.
    #[serde(skip_serializing_if = "Option::is_none")]
    summary: Option<Summary>,
    links: Links,
}

impl From<ModelRow> for ModelView {
    fn from(m: ModelRow) -> Self {
        let latest_version = match (m.latest_version, m.latest_status) {
            (Some(version), Some(status)) => Some(LatestVersion { version, status }),
            _ => None,
        };
        ModelView { id: m.id, name: m.name, created_at: m.created_at, latest_version }
    }
}

fn version_view(v: VersionRow) -> Result<VersionView, ApiError> {
    let corrupt = |what: &str, e: serde_json::Error| ApiError::Internal(anyhow::anyhow!("stored {what} is corrupt: {e}"));
    let options = serde_json::from_str(&v.options_json).map_err(|e| corrupt("options", e))?;
    let error = v.error_json.as_deref().map(serde_json::from_str).transpose().map_err(|e| corrupt("problem", e))?;
    let summary = v.summary_json.as_deref().map(serde_json::from_str).transpose().map_err(|e| corrupt("summary", e))?;
    let base = format!("/api/models/{}/versions/{}", v.model_id, v.version);
    Ok(VersionView {
        links: Links {
            package: format!("{base}/package.zip"),
            urdf: format!("{base}/robot.urdf"),
            diagram: format!("{base}/diagram.svg"),
            report: format!("{base}/report"),
            bundle: format!("{base}/bundle"),
            job: v.job_id.as_ref().map(|j| format!("/api/jobs/{j}")),
        },
        model_id: v.model_id,
        version: v.version,
        created_at: v.created_at,
        status: v.status,
        job_id: v.job_id,
        bundle: BundleInfo { name: v.bundle_name, size: v.bundle_size, sha256: v.bundle_sha256 },
        options,
        error,
        summary,
    })
}

fn accepted(c: Created) -> Response {
    tracing::info!(model_id = %c.model_id, version = c.version, job_id = %c.job_id, "upload accepted");
    let location = HeaderValue::from_str(&format!("/api/jobs/{}", c.job_id)).ok();
    let mut resp = (StatusCode::ACCEPTED, Json(Accepted { model_id: c.model_id, version: c.version, job_id: c.job_id })).into_response();
    if let Some(l) = location {
        resp.headers_mut().insert(header::LOCATION, l);
    }
    resp
}

/// A problem document stored with a failed conversion, answered as it was recorded.
fn stored_problem(error_json: &str) -> Response {
    match serde_json::from_str::<Value>(error_json) {
        Ok(problem) => {
            let status = problem
                .get("status")
                .and_then(Value::as_u64)
                .and_then(|s| u16::try_from(s).ok())
                .and_then(|s| StatusCode::from_u16(s).ok())
                .unwrap_or(StatusCode::UNPROCESSABLE_ENTITY);
            (status, [(header::CONTENT_TYPE, "application/problem+json")], problem.to_string()).into_response()
        }
        Err(e) => ApiError::Internal(anyhow::anyhow!("stored problem is corrupt: {e}")).into_response(),
    }
}

fn file(bytes: Vec<u8>, content_type: &'static str, attachment: Option<&str>, sha256: &str) -> Response {
    let mut headers = HeaderMap::new();
    headers.insert(header::CONTENT_TYPE, HeaderValue::from_static(content_type));
    if let Ok(etag) = HeaderValue::from_str(&format!("\"{sha256}\"")) {
        headers.insert(header::ETAG, etag);
    }
    if let Some(name) = attachment {
        if let Ok(v) = HeaderValue::from_str(&format!("attachment; filename=\"{}\"", safe_file_name(name))) {
            headers.insert(header::CONTENT_DISPOSITION, v);
        }
    }
    (headers, bytes).into_response()
}

// ---------------------------------------------------------------------------------------------
// Extractors that answer in problem+json

/// `{model_id}` (and `{version}`) from the path; a version that is not a number is not found.
fn model_id(path: Result<Path<String>, PathRejection>) -> Result<String, ApiError> {
    path.map(|Path(id)| id).map_err(|e| ApiError::BadRequest(e.body_text()))
}

fn version_ids(path: Result<Path<(String, String)>, PathRejection>) -> Result<(String, i64), ApiError> {
    let Path((id, v)) = path.map_err(|e| ApiError::BadRequest(e.body_text()))?;
    match v.parse::<i64>() {
        Ok(n) => Ok((id, n)),
        Err(_) => Err(ApiError::NotFound(format!("version \"{v}\" of model {id}"))),
    }
}

/// A parsed upload.
struct Upload {
    bundle: Bytes,
    bundle_name: String,
    name: Option<String>,
    options: ExportOptions,
}

pub(super) fn invalid(field: &str, message: impl Into<String>) -> ApiError {
    let message = message.into();
    ApiError::Invalid { detail: format!("{field}: {message}"), errors: vec![FieldError { field: field.into(), message }] }
}

/// A multipart upload within `--max-upload` (413 beyond it, from the declared length when there
/// is one); `part` names the file part for the error message. Returns the reader and the limit.
pub(super) async fn multipart_upload(mut req: Request, state: &AppState, part: &str) -> Result<(Multipart, u64), ApiError> {
    let limit = state.settings.max_upload;
    let declared = req.headers().get(header::CONTENT_LENGTH).and_then(|v| v.to_str().ok()).and_then(|v| v.parse::<u64>().ok());
    if declared.is_some_and(|n| n > limit) {
        return Err(ApiError::PayloadTooLarge { limit });
    }
    DefaultBodyLimit::max(usize::try_from(limit).unwrap_or(usize::MAX)).apply(&mut req);
    let multipart = Multipart::from_request(req, state)
        .await
        .map_err(|e| ApiError::BadRequest(format!("expected a multipart/form-data upload with a `{part}` part: {}", e.body_text())))?;
    Ok((multipart, limit))
}

pub(super) fn multipart_error(e: axum::extract::multipart::MultipartError, limit: u64) -> ApiError {
    let mut source: Option<&(dyn std::error::Error + 'static)> = Some(&e);
    while let Some(s) = source {
        if s.is::<tower_http::timeout::TimeoutError>() {
            return ApiError::BodyTimeout;
        }
        source = s.source();
    }
    if e.status() == StatusCode::PAYLOAD_TOO_LARGE {
        ApiError::PayloadTooLarge { limit }
    } else {
        ApiError::BadRequest(format!("reading the multipart upload: {}", e.body_text()))
    }
}

impl FromRequest<AppState> for Upload {
    type Rejection = ApiError;

    async fn from_request(req: Request, state: &AppState) -> Result<Self, ApiError> {
        let (mut multipart, limit) = multipart_upload(req, state, "bundle").await?;
        let mut bundle: Option<(Bytes, String)> = None;
        let mut name = None;
        let mut options = ExportOptions::default();
        let mut seen: Vec<String> = Vec::new();
        while let Some(field) = multipart.next_field().await.map_err(|e| multipart_error(e, limit))? {
            let part = field.name().unwrap_or_default().to_string();
            if seen.contains(&part) {
                return Err(invalid(&part, "given more than once"));
            }
            seen.push(part.clone());
            if part == "bundle" {
                let file_name = safe_file_name(field.file_name().unwrap_or_default());
                let bytes = field.bytes().await.map_err(|e| multipart_error(e, limit))?;
                bundle = Some((bytes, file_name));
                continue;
            }
            let known = ["name", "package_name", "gravity", "lump_welds"];
            if !known.contains(&part.as_str()) {
                return Err(invalid(&part, "unknown part (expected bundle, name, package_name, gravity, lump_welds)"));
            }
            let text = field.text().await.map_err(|e| multipart_error(e, limit))?;
            let text = text.trim();
            if text.is_empty() {
                continue; // an empty form field means "not given"
            }
            match part.as_str() {
                "name" => {
                    if text.chars().count() > 200 || text.chars().any(char::is_control) {
                        return Err(invalid("name", "at most 200 characters, no control characters"));
                    }
                    name = Some(text.to_string());
                }
                "package_name" => {
                    if cad2mo_engine::pipeline::back::modelica::sanitize(text, "P") != text {
                        return Err(invalid(
                            "package_name",
                            format!("\"{text}\" is not a Modelica identifier ([A-Za-z_][A-Za-z0-9_]*, not a keyword)"),
                        ));
                    }
                    options.package_name = Some(text.to_string());
                }
                "gravity" => options.gravity = Some(parse_gravity(text).map_err(|m| invalid("gravity", m))?),
                _ => {
                    options.lump_welds = match text.to_ascii_lowercase().as_str() {
                        "true" | "1" | "on" | "yes" => true,
                        "false" | "0" | "off" | "no" => false,
                        _ => return Err(invalid("lump_welds", format!("expected true or false, got \"{text}\""))),
                    }
                }
            }
        }
        let Some((bundle, bundle_name)) = bundle else {
            return Err(invalid("bundle", "a file part named `bundle` (the zip of the CAD export) is required"));
        };
        Ok(Upload { bundle, bundle_name, name, options })
    }
}

fn parse_gravity(s: &str) -> Result<[f64; 3], String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    let [x, y, z] = parts.as_slice() else {
        return Err(format!("expected three numbers \"x,y,z\" in m/s², got \"{s}\""));
    };
    let mut g = [0.0; 3];
    for (k, p) in [x, y, z].into_iter().enumerate() {
        g[k] = p.parse::<f64>().ok().filter(|v| v.is_finite()).ok_or_else(|| format!("\"{p}\" is not a finite number"))?;
    }
    Ok(g)
}

/// A file name safe for storing and for a `Content-Disposition` header: the last path segment,
/// ASCII letters, digits and `._-+()` kept, anything else `_`; `bundle.zip` when empty.
pub(super) fn safe_file_name(raw: &str) -> String {
    let last = raw.rsplit(['/', '\\']).next().unwrap_or_default();
    let cleaned: String = last.chars().take(200).map(|c| if c.is_ascii_alphanumeric() || "._-+()".contains(c) { c } else { '_' }).collect();
    if cleaned.trim_matches(['.', '_']).is_empty() {
        "bundle.zip".to_string()
    } else {
        cleaned
    }
}

// ---------------------------------------------------------------------------------------------
// Uploads

/// The upload use cases' view of the service.
fn ctx(state: &AppState) -> models::Ctx<'_> {
    models::Ctx {
        store: &state.store,
        blobs: &state.blobs,
        jobs: &state.jobs,
        checks: models::Checks { permits: &state.checks, wait: state.settings.check_wait },
    }
}

impl From<Upload> for models::Upload {
    fn from(u: Upload) -> Self {
        models::Upload { bundle: Vec::from(u.bundle), bundle_name: u.bundle_name, name: u.name, options: u.options }
    }
}

async fn create_model(State(state): State<AppState>, upload: Upload) -> Result<Response, ApiError> {
    Ok(accepted(models::create_model(ctx(&state), upload.into()).await?))
}

async fn create_version(
    State(state): State<AppState>,
    path: Result<Path<String>, PathRejection>,
    upload: Upload,
) -> Result<Response, ApiError> {
    let id = model_id(path)?;
    Ok(accepted(models::create_version(ctx(&state), &id, upload.into()).await?))
}

// ---------------------------------------------------------------------------------------------
// Models and versions

async fn list_models(State(state): State<AppState>) -> Result<Json<Vec<ModelView>>, ApiError> {
    Ok(Json(db::list_models(&state.store.pool).await?.into_iter().map(ModelView::from).collect()))
}

async fn get_model(State(state): State<AppState>, path: Result<Path<String>, PathRejection>) -> Result<Json<ModelDetail>, ApiError> {
    let id = model_id(path)?;
    let model = models::model(&state.store, &id).await?;
    let versions = models::versions(&state.store, &id).await?.into_iter().map(version_view).collect::<Result<_, _>>()?;
    Ok(Json(ModelDetail { model: model.into(), versions }))
}

async fn delete_model(State(state): State<AppState>, path: Result<Path<String>, PathRejection>) -> Result<StatusCode, ApiError> {
    let id = model_id(path)?;
    models::delete_model(&state.store, &id).await?;
    Ok(StatusCode::NO_CONTENT)
}

async fn list_versions(
    State(state): State<AppState>,
    path: Result<Path<String>, PathRejection>,
) -> Result<Json<Vec<VersionView>>, ApiError> {
    let id = model_id(path)?;
    models::model(&state.store, &id).await?;
    let versions = models::versions(&state.store, &id).await?.into_iter().map(version_view).collect::<Result<_, _>>()?;
    Ok(Json(versions))
}

async fn get_version(
    State(state): State<AppState>,
    path: Result<Path<(String, String)>, PathRejection>,
) -> Result<Json<VersionView>, ApiError> {
    let (id, v) = version_ids(path)?;
    Ok(Json(version_view(models::version(&state.store, &id, v).await?)?))
}

async fn delete_version(
    State(state): State<AppState>,
    path: Result<Path<(String, String)>, PathRejection>,
) -> Result<StatusCode, ApiError> {
    let (id, v) = version_ids(path)?;
    models::delete_version(&state.store, &id, v).await?;
    Ok(StatusCode::NO_CONTENT)
}

// ---------------------------------------------------------------------------------------------
// Files

/// Why a version has no outputs: 409 while converting, the stored problem when it failed.
fn not_converted(v: &VersionRow) -> Response {
    if v.status == "failed" {
        if let Some(e) = &v.error_json {
            return stored_problem(e);
        }
    }
    let poll = v.job_id.as_ref().map(|j| format!("; poll /api/jobs/{j}")).unwrap_or_default();
    ApiError::Conflict(format!("version {} of model {} is not converted yet (status {}){poll}", v.version, v.model_id, v.status))
        .into_response()
}

async fn package(State(state): State<AppState>, path: Result<Path<(String, String)>, PathRejection>) -> Result<Response, ApiError> {
    let (id, v) = version_ids(path)?;
    let p = match stored_package(&state, &id, v).await? {
        Ok(found) => found,
        Err(not_yet) => return Ok(not_yet),
    };
    Ok(file(p.bytes, "application/zip", Some(&format!("{}-v{v}.zip", p.stem)), &p.sha256))
}

/// A version's stored package; `Err` with the response for a version that has none (yet).
async fn stored_package(state: &AppState, id: &str, v: i64) -> Result<Result<models::Package, Response>, ApiError> {
    Ok(match models::package(&state.store, &state.blobs, id, v).await? {
        Output::Ready(p) => Ok(p),
        Output::NotConverted(row) => Err(not_converted(&row)),
    })
}

/// The URDF inside the version's package (`<Pkg>/<Pkg>.urdf`, written by `back::urdf`).
async fn robot_urdf(State(state): State<AppState>, path: Result<Path<(String, String)>, PathRejection>) -> Result<Response, ApiError> {
    let (id, v) = version_ids(path)?;
    let models::Package { bytes, stem, sha256: package } = match stored_package(&state, &id, v).await? {
        Ok(found) => found,
        Err(not_yet) => return Ok(not_yet),
    };
    let wanted = format!("{stem}/{stem}.urdf");
    let text = blocking(move || zip_entry(&bytes, &wanted)).await?;
    let Some(text) = text else {
        return Err(ApiError::NotFound(format!(
            "a URDF in the package of version {v} of model {id} (converted before URDF output existed; upload the bundle again)"
        )));
    };
    Ok(file(text, "application/xml", Some(&format!("{stem}-v{v}.urdf")), &package))
}

#[derive(Deserialize)]
struct DiagramQuery {
    model: Option<String>,
}

/// The diagram of the version's `Mechanics` (or `Mechatronics`, drawn over the Mechanics it
/// extends), from the `Placement` and `Line` annotations of the stored package.
async fn diagram_svg(
    State(state): State<AppState>,
    path: Result<Path<(String, String)>, PathRejection>,
    query: Result<Query<DiagramQuery>, QueryRejection>,
) -> Result<Response, ApiError> {
    let (id, v) = version_ids(path)?;
    let Query(q) = query.map_err(|e| ApiError::BadRequest(format!("invalid query: {}", e.body_text())))?;
    let which = match q.model.as_deref() {
        None | Some("Mechanics") => "Mechanics",
        Some("Mechatronics") => "Mechatronics",
        Some(other) => return Err(ApiError::BadRequest(format!("model must be Mechanics or Mechatronics, not \"{other}\""))),
    };
    let models::Package { bytes, stem, sha256: package } = match stored_package(&state, &id, v).await? {
        Ok(found) => found,
        Err(not_yet) => return Ok(not_yet),
    };
    let title = format!("{stem}.{which} (version {v})");
    let svg = blocking(move || {
        use cad2mo_engine::pipeline::back::modelica::diagram::svg;
        let text = |class: &str| -> Result<String, ApiError> {
            let entry = zip_entry(&bytes, &format!("{stem}/{class}.mo"))?
                .ok_or_else(|| ApiError::NotFound(format!("{class}.mo in the package of version {v} of model {id}")))?;
            Ok(String::from_utf8_lossy(&entry).into_owned())
        };
        let mechanics = svg::read(&text("Mechanics")?);
        let own = if which == "Mechatronics" { Some(svg::read(&text("Mechatronics")?)) } else { None };
        let mut drawings = vec![&mechanics];
        drawings.extend(own.as_ref());
        Ok(svg::svg(&drawings, &title).into_bytes())
    })
    .await?;
    Ok(file(svg, "image/svg+xml", None, &format!("{package}-{which}")))
}

/// The bytes of the zip entry `wanted`, `None` when the package has no such entry.
fn zip_entry(zip_bytes: &[u8], wanted: &str) -> Result<Option<Vec<u8>>, ApiError> {
    let internal = |e: zip::result::ZipError| ApiError::Internal(anyhow::anyhow!("stored package: {e}"));
    let mut archive = zip::ZipArchive::new(std::io::Cursor::new(zip_bytes)).map_err(internal)?;
    let mut entry = match archive.by_name(wanted) {
        Ok(e) => e,
        Err(zip::result::ZipError::FileNotFound) => return Ok(None),
        Err(e) => return Err(internal(e)),
    };
    let mut out = Vec::new();
    std::io::Read::read_to_end(&mut entry, &mut out).map_err(|e| ApiError::Internal(anyhow::anyhow!("stored package: {e}")))?;
    Ok(Some(out))
}

async fn report(State(state): State<AppState>, path: Result<Path<(String, String)>, PathRejection>) -> Result<Response, ApiError> {
    let (id, v) = version_ids(path)?;
    match models::report(&state.store, &state.blobs, &id, v).await? {
        Output::Ready((bytes, report)) => Ok(file(bytes, "application/json", None, &report)),
        Output::NotConverted(row) => Ok(not_converted(&row)),
    }
}

async fn bundle(State(state): State<AppState>, path: Result<Path<(String, String)>, PathRejection>) -> Result<Response, ApiError> {
    let (id, v) = version_ids(path)?;
    let (bytes, row) = models::bundle(&state.store, &state.blobs, &id, v).await?;
    Ok(file(bytes, "application/zip", Some(&row.bundle_name), &row.bundle_sha256))
}

// ---------------------------------------------------------------------------------------------
// Diff

#[derive(Deserialize)]
struct DiffQuery {
    from: i64,
    to: i64,
}

#[derive(Serialize)]
struct DiffView {
    model_id: String,
    from: i64,
    to: i64,
    #[serde(flatten)]
    diff: cad2mo_engine::diff::Diff,
}

async fn diff(
    State(state): State<AppState>,
    path: Result<Path<String>, PathRejection>,
    query: Result<Query<DiffQuery>, QueryRejection>,
) -> Result<Json<DiffView>, ApiError> {
    let id = model_id(path)?;
    let Query(q) =
        query.map_err(|e| ApiError::BadRequest(format!("expected ?from=<version>&to=<version> (numbers): {}", e.body_text())))?;
    let diff = models::diff(&state.store, &state.blobs, &id, q.from, q.to).await?;
    Ok(Json(DiffView { model_id: id, from: q.from, to: q.to, diff }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn file_names_are_made_safe() {
        assert_eq!(safe_file_name("C:\\exports\\arm v2.zip"), "arm_v2.zip");
        assert_eq!(safe_file_name("../../etc/passwd"), "passwd");
        assert_eq!(safe_file_name("\"quoted\".zip"), "_quoted_.zip");
        assert_eq!(safe_file_name(""), "bundle.zip");
        assert_eq!(safe_file_name(".."), "bundle.zip");
    }

    #[test]
    fn gravity_parses() {
        assert_eq!(parse_gravity("0, 0,-9.81").unwrap(), [0.0, 0.0, -9.81]);
        assert!(parse_gravity("0,0").is_err());
        assert!(parse_gravity("0,nan,1").is_err());
    }
}
