//! Routes of the motor library: classes, instances, XML export and import.
//!
//! | route | |
//! |---|---|
//! | `GET /api/library/classes` | every class with its parameters |
//! | `POST /api/library/classes` | create (201 + Location) |
//! | `GET/PUT/DELETE /api/library/classes/{id}` | one class; DELETE is 409 while instances exist |
//! | `GET /api/library/instances?class_id=&domain=` | instances, optionally filtered |
//! | `POST /api/library/instances` | create (201 + Location) |
//! | `GET/PUT/DELETE /api/library/instances/{id}` | one instance; PUT keeps nameplate values; DELETE is 409 while a drive uses it |
//! | `GET /api/library/export` | the library as XML (`docs/library-xml.md`) |
//! | `POST /api/library/import` | XML in; all or nothing; counts out |
//!
//! The rules are in [`cad2mo_engine::library`]; bodies that are not JSON, or not of the expected shape,
//! become problem documents like every other error. DTOs are private to this module.

use axum::body::Bytes;
use axum::extract::rejection::{BytesRejection, JsonRejection};
use axum::extract::{DefaultBodyLimit, State};
use axum::http::{header, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use axum::{Json, Router};
use serde::{Deserialize, Serialize};
use serde_json::{Map, Value as Json_};

use super::error::FieldError;
use super::extract::{Path, Query};
use super::ApiError;
use crate::app::AppState;
use crate::store::library as db;
use crate::store::library::{Change, Removal};
use crate::store::StoreError;
use cad2mo_engine::library::{
    self, check_class, check_instance, check_instance_update, migrate_instance, ClassDraft, Instance, InstanceDraft, Issue, ParameterDraft,
};

/// Largest accepted import file.
const IMPORT_LIMIT: usize = 16 * 1024 * 1024;

pub fn router() -> Router<AppState> {
    Router::new()
        .route("/api/library/classes", get(list_classes).post(create_class))
        .route("/api/library/classes/{id}", get(get_class).put(update_class).delete(delete_class))
        .route("/api/library/instances", get(list_instances).post(create_instance))
        .route("/api/library/instances/{id}", get(get_instance).put(update_instance).delete(delete_instance))
        .route("/api/library/export", get(export))
        .route("/api/library/import", post(import).layer(DefaultBodyLimit::max(IMPORT_LIMIT)))
}

// ---------------------------------------------------------------------------------------------
// DTOs

#[derive(Deserialize)]
struct ParameterIn {
    name: String,
    #[serde(rename = "type")]
    ty: String,
    #[serde(default)]
    unit: String,
    #[serde(default)]
    min: Option<f64>,
    #[serde(default)]
    max: Option<f64>,
    #[serde(default)]
    editable: bool,
    #[serde(default)]
    datasheet: bool,
    #[serde(default)]
    default: Option<Json_>,
    #[serde(default)]
    comment: String,
}

#[derive(Deserialize)]
struct ClassIn {
    name: String,
    domain: String,
    modelica_class: String,
    #[serde(default)]
    description: String,
    #[serde(default)]
    parameters: Vec<ParameterIn>,
}

impl ClassIn {
    fn draft(self) -> ClassDraft {
        ClassDraft {
            name: self.name,
            domain: self.domain,
            modelica_class: self.modelica_class,
            description: self.description,
            parameters: self
                .parameters
                .into_iter()
                .map(|p| ParameterDraft {
                    name: p.name,
                    ty: p.ty,
                    unit: p.unit,
                    min: p.min,
                    max: p.max,
                    editable: p.editable,
                    datasheet: p.datasheet,
                    default: p.default,
                    comment: p.comment,
                })
                .collect(),
        }
    }
}

#[derive(Deserialize)]
struct InstanceIn {
    class_id: String,
    name: String,
    #[serde(default)]
    source: String,
    values: Map<String, Json_>,
}

/// A PUT body: like a GET result (extra fields are ignored); `class_id`, when given, must be the
/// instance's class.
#[derive(Deserialize)]
struct InstanceUpdate {
    #[serde(default)]
    class_id: Option<String>,
    name: String,
    #[serde(default)]
    source: String,
    values: Map<String, Json_>,
}

#[derive(Deserialize)]
struct InstanceFilter {
    class_id: Option<String>,
    domain: Option<String>,
}

#[derive(Serialize)]
struct ParameterOut<'a> {
    name: &'a str,
    #[serde(rename = "type")]
    ty: &'static str,
    unit: &'a str,
    min: Option<f64>,
    max: Option<f64>,
    editable: bool,
    datasheet: bool,
    default: Option<&'a library::Value>,
    comment: &'a str,
}

#[derive(Serialize)]
struct ClassOut<'a> {
    id: &'a str,
    name: &'a str,
    domain: &'a str,
    modelica_class: &'a str,
    description: &'a str,
    parameters: Vec<ParameterOut<'a>>,
}

fn class_out(c: &library::Class) -> ClassOut<'_> {
    ClassOut {
        id: &c.id,
        name: &c.name,
        domain: &c.domain,
        modelica_class: &c.modelica_class,
        description: &c.description,
        parameters: c
            .parameters
            .iter()
            .map(|p| ParameterOut {
                name: &p.name,
                ty: p.ty.as_str(),
                unit: &p.unit,
                min: p.min,
                max: p.max,
                editable: p.editable,
                datasheet: p.datasheet,
                default: p.default.as_ref(),
                comment: &p.comment,
            })
            .collect(),
    }
}

#[derive(Serialize)]
struct InstanceOut<'a> {
    id: &'a str,
    class_id: &'a str,
    class_name: &'a str,
    domain: &'a str,
    modelica_class: &'a str,
    name: &'a str,
    source: &'a str,
    /// In each parameter's unit (see the class).
    values: Map<String, Json_>,
}

fn instance_out<'a>(i: &'a Instance, c: &'a library::Class) -> InstanceOut<'a> {
    InstanceOut {
        id: &i.id,
        class_id: &i.class_id,
        class_name: &c.name,
        domain: &c.domain,
        modelica_class: &c.modelica_class,
        name: &i.name,
        source: &i.source,
        values: i.values.iter().map(|(k, v)| (k.clone(), v.to_json())).collect(),
    }
}

// ---------------------------------------------------------------------------------------------
// Errors

/// A JSON body that cannot be read becomes a problem document (not axum's plain text): bad
/// syntax is a 400, a body of the wrong shape a 422 naming the field.
fn json_rejection(e: JsonRejection) -> ApiError {
    const PREFIX: &str = "Failed to deserialize the JSON body into the target type: ";
    const SYNTAX: &str = "Failed to parse the request body as JSON: ";
    match e {
        JsonRejection::JsonDataError(e) => {
            let text = e.body_text();
            let text = text.strip_prefix(PREFIX).unwrap_or(&text);
            let (field, message) = match text.split_once(": ") {
                Some((f, m)) if !f.is_empty() && !f.contains(' ') => (f.to_string(), m.to_string()),
                _ => ("body".to_string(), text.to_string()),
            };
            ApiError::Invalid {
                detail: "the JSON body does not have the expected fields and types".into(),
                errors: vec![FieldError { field, message }],
            }
        }
        JsonRejection::JsonSyntaxError(e) => {
            let text = e.body_text();
            ApiError::BadRequest(format!("malformed JSON: {}", text.strip_prefix(SYNTAX).unwrap_or(&text)))
        }
        JsonRejection::MissingJsonContentType(_) => {
            ApiError::BadRequest("expected a JSON body with the header Content-Type: application/json".into())
        }
        other => ApiError::BadRequest(other.body_text()),
    }
}

fn body<T>(b: Result<Json<T>, JsonRejection>) -> Result<T, ApiError> {
    b.map(|Json(t)| t).map_err(json_rejection)
}

fn invalid(detail: impl Into<String>, issues: Vec<Issue>) -> ApiError {
    let errors: Vec<FieldError> = issues.into_iter().map(|i| FieldError { field: i.field, message: i.message }).collect();
    let detail = detail.into();
    let detail = match errors.len() {
        1 => format!("{detail}: {}", errors[0].message),
        n => format!("{detail} ({n} problems)"),
    };
    ApiError::Invalid { detail, errors }
}

/// A UNIQUE violation as a 409 with `message`; anything else as usual.
fn unique_conflict(e: StoreError, message: String) -> ApiError {
    if e.is_unique_violation() {
        ApiError::Conflict(message)
    } else {
        e.into()
    }
}

/// Ids are UUIDs; any spelling of one finds the item, anything else finds nothing.
fn canonical(id: &str) -> String {
    library::parse_id(id).unwrap_or_else(|| id.to_string())
}

fn created(location: String, body: impl Serialize) -> Response {
    (StatusCode::CREATED, [(header::LOCATION, location)], Json(body)).into_response()
}

// ---------------------------------------------------------------------------------------------
// Classes

async fn list_classes(State(s): State<AppState>) -> Result<Response, ApiError> {
    let classes = db::list_classes(&s.store).await?;
    Ok(Json(classes.iter().map(class_out).collect::<Vec<_>>()).into_response())
}

async fn get_class(State(s): State<AppState>, Path(id): Path<String>) -> Result<Response, ApiError> {
    let id = canonical(&id);
    let class = db::get_class(&s.store, &id).await?.ok_or_else(|| ApiError::NotFound(format!("library class {id}")))?;
    Ok(Json(class_out(&class)).into_response())
}

async fn create_class(State(s): State<AppState>, b: Result<Json<ClassIn>, JsonRejection>) -> Result<Response, ApiError> {
    let draft = body(b)?.draft();
    let class = check_class(&library::new_id(), &draft).map_err(|e| invalid("the class is invalid", e))?;
    db::insert_class(&s.store, &class).await.map_err(|e| unique_conflict(e, format!("a class named \"{}\" already exists", class.name)))?;
    Ok(created(format!("/api/library/classes/{}", class.id), class_out(&class)))
}

/// Replaces a class. Its instances are carried over: values converted to changed units and
/// re-checked, removed parameters dropped, new parameters set to their default. If an instance
/// cannot follow (a new parameter without default, a value outside new limits), nothing changes.
async fn update_class(
    State(s): State<AppState>,
    Path(id): Path<String>,
    b: Result<Json<ClassIn>, JsonRejection>,
) -> Result<Response, ApiError> {
    let id = canonical(&id);
    let draft = body(b)?.draft();
    let name = draft.name.clone();
    let change = db::update_class(&s.store, &id, |old, instances| {
        let new = check_class(&old.id, &draft)?;
        let mut migrated = Vec::with_capacity(instances.len());
        let mut issues = Vec::new();
        for i in instances {
            match migrate_instance(old, &new, i) {
                Ok(m) => migrated.push(m),
                Err(e) => issues.extend(e),
            }
        }
        if issues.is_empty() {
            Ok((new, migrated))
        } else {
            Err(issues)
        }
    })
    .await
    .map_err(|e| unique_conflict(e, format!("a class named \"{name}\" already exists")))?;
    match change {
        Change::Done((class, _)) => Ok(Json(class_out(&class)).into_response()),
        Change::NotFound => Err(ApiError::NotFound(format!("library class {id}"))),
        Change::Rejected(issues) => Err(invalid("the class change is invalid", issues)),
    }
}

async fn delete_class(State(s): State<AppState>, Path(id): Path<String>) -> Result<StatusCode, ApiError> {
    let id = canonical(&id);
    match db::delete_class(&s.store, &id).await? {
        Removal::Deleted => Ok(StatusCode::NO_CONTENT),
        Removal::NotFound => Err(ApiError::NotFound(format!("library class {id}"))),
        Removal::InUse(why) => Err(ApiError::Conflict(why)),
    }
}

// ---------------------------------------------------------------------------------------------
// Instances

async fn list_instances(State(s): State<AppState>, Query(f): Query<InstanceFilter>) -> Result<Response, ApiError> {
    let class_id = f.class_id.as_deref().map(canonical);
    let list = db::list_instances(&s.store, class_id.as_deref(), f.domain.as_deref()).await?;
    Ok(Json(list.iter().map(|(i, c)| instance_out(i, c)).collect::<Vec<_>>()).into_response())
}

async fn get_instance(State(s): State<AppState>, Path(id): Path<String>) -> Result<Response, ApiError> {
    let id = canonical(&id);
    let (i, c) = db::get_instance(&s.store, &id).await?.ok_or_else(|| ApiError::NotFound(format!("library instance {id}")))?;
    Ok(Json(instance_out(&i, &c)).into_response())
}

async fn create_instance(State(s): State<AppState>, b: Result<Json<InstanceIn>, JsonRejection>) -> Result<Response, ApiError> {
    let b = body(b)?;
    let no_class = || {
        invalid("the instance is invalid", vec![Issue::new("class_id", format!("there is no library class with id \"{}\"", b.class_id))])
    };
    let Some(class_id) = library::parse_id(&b.class_id) else {
        return Err(no_class());
    };
    let draft = InstanceDraft { name: b.name.clone(), source: b.source.clone(), values: b.values.clone() };
    let id = library::new_id();
    let change = db::insert_instance(&s.store, &class_id, |class| check_instance(&id, class, &draft))
        .await
        .map_err(|e| unique_conflict(e, format!("the class already has an instance named \"{}\"", draft.name)))?;
    match change {
        Change::Done((i, c)) => Ok(created(format!("/api/library/instances/{}", i.id), instance_out(&i, &c))),
        Change::NotFound => Err(no_class()),
        Change::Rejected(issues) => Err(invalid("the instance is invalid", issues)),
    }
}

/// Changes the name, source and editable values of an instance; nameplate values must stay.
async fn update_instance(
    State(s): State<AppState>,
    Path(id): Path<String>,
    b: Result<Json<InstanceUpdate>, JsonRejection>,
) -> Result<Response, ApiError> {
    let id = canonical(&id);
    let b = body(b)?;
    let draft = InstanceDraft { name: b.name, source: b.source, values: b.values };
    let class_id = b.class_id;
    let change = db::update_instance(&s.store, &id, |class, old| {
        let mut issues = Vec::new();
        if let Some(cid) = &class_id {
            if library::parse_id(cid).as_deref() != Some(old.class_id.as_str()) {
                issues.push(Issue::new(
                    "class_id",
                    format!("an instance cannot change class (it is a \"{}\"); create a new instance", class.name),
                ));
            }
        }
        match check_instance_update(class, old, &draft) {
            Ok(i) if issues.is_empty() => Ok(i),
            Ok(_) => Err(issues),
            Err(e) => {
                issues.extend(e);
                Err(issues)
            }
        }
    })
    .await
    .map_err(|e| unique_conflict(e, format!("the class already has an instance named \"{}\"", draft.name)))?;
    match change {
        Change::Done((i, c)) => Ok(Json(instance_out(&i, &c)).into_response()),
        Change::NotFound => Err(ApiError::NotFound(format!("library instance {id}"))),
        Change::Rejected(issues) => Err(invalid("the instance change is invalid", issues)),
    }
}

async fn delete_instance(State(s): State<AppState>, Path(id): Path<String>) -> Result<StatusCode, ApiError> {
    let id = canonical(&id);
    match db::delete_instance(&s.store, &id).await {
        Ok(Removal::Deleted) => Ok(StatusCode::NO_CONTENT),
        Ok(Removal::NotFound) => Err(ApiError::NotFound(format!("library instance {id}"))),
        Ok(Removal::InUse(why)) => Err(ApiError::Conflict(why)),
        // A drive assigned between the check and the delete.
        Err(e) if e.is_foreign_key_violation() => {
            Err(ApiError::Conflict(format!("library instance {id} is used by a drive; assign another instance first")))
        }
        Err(e) => Err(e.into()),
    }
}

// ---------------------------------------------------------------------------------------------
// XML

async fn export(State(s): State<AppState>) -> Result<Response, ApiError> {
    let lib = db::export(&s.store).await?;
    let text = library::xml::write(&lib);
    Ok((
        [
            (header::CONTENT_TYPE, "application/xml; charset=utf-8"),
            (header::CONTENT_DISPOSITION, "attachment; filename=\"motor-library.xml\""),
        ],
        text,
    )
        .into_response())
}

/// Imports an XML library file: creates or replaces classes and instances by id. Everything is
/// checked first; a file with any problem changes nothing (422 listing every problem).
async fn import(State(s): State<AppState>, b: Result<Bytes, BytesRejection>) -> Result<Response, ApiError> {
    let bytes = b.map_err(|e| {
        if e.status() == StatusCode::PAYLOAD_TOO_LARGE {
            ApiError::PayloadTooLarge { limit: IMPORT_LIMIT as u64 }
        } else {
            ApiError::BadRequest(e.body_text())
        }
    })?;
    const NOTHING: &str = "the library file was not imported (nothing changed)";
    let text =
        std::str::from_utf8(&bytes).map_err(|e| invalid(NOTHING, vec![Issue::new("body", format!("the file is not UTF-8 text: {e}"))]))?;
    let doc = library::xml::read(text).map_err(|e| invalid(NOTHING, e))?;
    let counts = db::import(&s.store, |current| library::plan_import(current, &doc)).await?.map_err(|e| invalid(NOTHING, e))?;
    Ok(Json(counts).into_response())
}
