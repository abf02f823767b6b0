//! SQL of the motor library: `library_classes`, `library_parameters`, `library_instances`.
//!
//! The rules live in [`cad2mo_engine::library`]; the functions that change data take them as a closure
//! and run it inside one `BEGIN IMMEDIATE` transaction, on the rows as they are in that
//! transaction: check and write cannot interleave with another writer.
//!
//! Values are stored as JSON (`{"R": 0.317, ...}`) in the parameter's unit. They are read back
//! through `RawValue` and Rust's own float parser, so a stored Real comes back bit for bit
//! (serde_json's default float parsing may be off by one unit in the last place).

use std::collections::{BTreeMap, HashMap};

use serde_json::value::RawValue;
use sqlx::AnyConnection;
use sqlx::{Any, Transaction};

use super::{sql, Engine, Store, StoreError};
use cad2mo_engine::library::{self, Class, ImportCounts, ImportPlan, Instance, Issue, Library, ParamType, Parameter, Value};

/// The outcome of a checked change.
#[derive(Debug)]
pub enum Change<T> {
    Done(T),
    /// The item (or the class it refers to) does not exist.
    NotFound,
    /// The library rules refused the change.
    Rejected(Vec<Issue>),
}

/// The outcome of a deletion.
#[derive(Debug, PartialEq, Eq)]
pub enum Removal {
    Deleted,
    NotFound,
    /// Still referred to; the text says by what.
    InUse(String),
}

/// A transaction that holds the library's write lock from its start: SQLite's `BEGIN IMMEDIATE`;
/// on PostgreSQL a transaction-scoped advisory lock (the same number for every library writer).
async fn begin(store: &Store) -> Result<Transaction<'static, Any>, StoreError> {
    match store.pool.engine() {
        Engine::Sqlite => Ok(store.pool.begin_with("BEGIN IMMEDIATE").await?),
        Engine::Postgres => {
            let mut tx = store.pool.begin().await?;
            sqlx::query("SELECT pg_advisory_xact_lock(1616)").execute(&mut *tx).await?;
            Ok(tx)
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Encoding

fn corrupt(what: String) -> StoreError {
    StoreError::Corrupt(what)
}

fn encode_values(values: &[(String, Value)]) -> String {
    let map: serde_json::Map<String, serde_json::Value> = values.iter().map(|(k, v)| (k.clone(), v.to_json())).collect();
    serde_json::Value::Object(map).to_string()
}

fn decode_value(ty: ParamType, raw: &str) -> Option<Value> {
    match ty {
        ParamType::Real => raw.trim().parse::<f64>().ok().filter(|x| x.is_finite()).map(Value::Real),
        ParamType::Integer => raw.trim().parse::<i64>().ok().map(Value::Integer),
        ParamType::Boolean => serde_json::from_str::<bool>(raw).ok().map(Value::Boolean),
        ParamType::String => serde_json::from_str::<String>(raw).ok().map(Value::String),
    }
}

/// Values in class order; stored values of parameters the class no longer has are ignored.
fn decode_values(class: &Class, instance: &str, json: &str) -> Result<Vec<(String, Value)>, StoreError> {
    let raw: BTreeMap<String, Box<RawValue>> =
        serde_json::from_str(json).map_err(|e| corrupt(format!("values of instance {instance}: {e}")))?;
    let mut values = Vec::with_capacity(class.parameters.len());
    for p in &class.parameters {
        if let Some(r) = raw.get(&p.name) {
            let v = decode_value(p.ty, r.get())
                .ok_or_else(|| corrupt(format!("value {} of instance {instance} is not a {}", p.name, p.ty.as_str())))?;
            values.push((p.name.clone(), v));
        }
    }
    Ok(values)
}

type ClassRow = (String, String, String, String, String);
type ParamRow = (String, String, String, String, Option<f64>, Option<f64>, i64, i64, Option<String>, String);
type InstanceRow = (String, String, String, String, String);

fn decode_param(row: ParamRow) -> Result<(String, Parameter), StoreError> {
    let (class_id, name, ty, unit, min, max, editable, datasheet, default_json, comment) = row;
    let ty = ParamType::parse(&ty).ok_or_else(|| corrupt(format!("parameter {name} of class {class_id}: type {ty}")))?;
    let default = match default_json {
        None => None,
        Some(j) => Some(decode_value(ty, &j).ok_or_else(|| corrupt(format!("default of parameter {name} of class {class_id}: {j}")))?),
    };
    Ok((class_id, Parameter { name, ty, unit, min, max, editable: editable != 0, datasheet: datasheet != 0, default, comment }))
}

// ---------------------------------------------------------------------------------------------
// Reading

/// Classes (all, or the one with `id`), by name, with their parameters in order.
async fn load_classes(conn: &mut AnyConnection, id: Option<&str>) -> Result<Vec<Class>, StoreError> {
    let rows: Vec<ClassRow> = sqlx::query_as(&sql(
        Engine::of(conn),
        "SELECT id, name, domain, modelica_class, description FROM library_classes
         WHERE ?1 IS NULL OR id = ?1 ORDER BY name, id",
    ))
    .bind(id)
    .fetch_all(&mut *conn)
    .await?;
    let params: Vec<ParamRow> = sqlx::query_as(&sql(
        Engine::of(conn),
        "SELECT class_id, name, type, unit, min_value, max_value, editable, datasheet, default_json, comment
         FROM library_parameters WHERE ?1 IS NULL OR class_id = ?1 ORDER BY class_id, position, name",
    ))
    .bind(id)
    .fetch_all(&mut *conn)
    .await?;
    let mut by_class: HashMap<String, Vec<Parameter>> = HashMap::new();
    for row in params {
        let (class_id, p) = decode_param(row)?;
        by_class.entry(class_id).or_default().push(p);
    }
    Ok(rows
        .into_iter()
        .map(|(id, name, domain, modelica_class, description)| {
            let parameters = by_class.remove(&id).unwrap_or_default();
            Class { id, name, domain, modelica_class, description, parameters }
        })
        .collect())
}

/// Instances matching the filters, each with its class, ordered by class name then name.
async fn load_instances(
    conn: &mut AnyConnection,
    id: Option<&str>,
    class_id: Option<&str>,
    domain: Option<&str>,
) -> Result<Vec<(Instance, Class)>, StoreError> {
    let rows: Vec<InstanceRow> = sqlx::query_as(&sql(
        Engine::of(conn),
        "SELECT i.id, i.class_id, i.name, i.values_json, i.source
         FROM library_instances i JOIN library_classes c ON c.id = i.class_id
         WHERE (?1 IS NULL OR i.id = ?1) AND (?2 IS NULL OR i.class_id = ?2) AND (?3 IS NULL OR c.domain = ?3)
         ORDER BY c.name, c.id, i.name, i.id",
    ))
    .bind(id)
    .bind(class_id)
    .bind(domain)
    .fetch_all(&mut *conn)
    .await?;
    if rows.is_empty() {
        return Ok(Vec::new());
    }
    let classes: HashMap<String, Class> = if let [(_, only, ..)] = rows.as_slice() {
        load_classes(conn, Some(only)).await?.into_iter().map(|c| (c.id.clone(), c)).collect()
    } else {
        load_classes(conn, None).await?.into_iter().map(|c| (c.id.clone(), c)).collect()
    };
    rows.into_iter()
        .map(|(id, class_id, name, values_json, source)| {
            let class = classes.get(&class_id).ok_or_else(|| corrupt(format!("instance {id}: class {class_id} is missing")))?;
            let values = decode_values(class, &id, &values_json)?;
            Ok((Instance { id, class_id, name, source, values }, class.clone()))
        })
        .collect()
}

async fn load_library(conn: &mut AnyConnection) -> Result<Library, StoreError> {
    let classes = load_classes(conn, None).await?;
    let instances = load_instances(conn, None, None, None).await?.into_iter().map(|(i, _)| i).collect();
    let mut lib = Library { classes, instances };
    lib.sort();
    Ok(lib)
}

/// Every class, by name.
pub async fn list_classes(store: &Store) -> Result<Vec<Class>, StoreError> {
    let mut conn = store.pool.acquire().await?;
    load_classes(&mut conn, None).await
}

pub async fn get_class(store: &Store, id: &str) -> Result<Option<Class>, StoreError> {
    let mut conn = store.pool.acquire().await?;
    Ok(load_classes(&mut conn, Some(id)).await?.into_iter().next())
}

/// Instances, optionally of one class or one domain, each with its class.
pub async fn list_instances(store: &Store, class_id: Option<&str>, domain: Option<&str>) -> Result<Vec<(Instance, Class)>, StoreError> {
    let mut conn = store.pool.acquire().await?;
    load_instances(&mut conn, None, class_id, domain).await
}

/// One instance and its class.
pub async fn get_instance(store: &Store, id: &str) -> Result<Option<(Instance, Class)>, StoreError> {
    let mut conn = store.pool.acquire().await?;
    Ok(load_instances(&mut conn, Some(id), None, None).await?.into_iter().next())
}

/// The whole library in export order ([`Library::sort`]).
pub async fn export(store: &Store) -> Result<Library, StoreError> {
    let mut conn = store.pool.acquire().await?;
    load_library(&mut conn).await
}

// ---------------------------------------------------------------------------------------------
// Writing

/// Creates or replaces a class row and all its parameters.
async fn write_class(conn: &mut AnyConnection, c: &Class) -> Result<(), StoreError> {
    sqlx::query(&sql(
        Engine::of(conn),
        "INSERT INTO library_classes (id, name, domain, modelica_class, description) VALUES (?1, ?2, ?3, ?4, ?5)
         ON CONFLICT(id) DO UPDATE SET name = excluded.name, domain = excluded.domain,
             modelica_class = excluded.modelica_class, description = excluded.description",
    ))
    .bind(&c.id)
    .bind(&c.name)
    .bind(&c.domain)
    .bind(&c.modelica_class)
    .bind(&c.description)
    .execute(&mut *conn)
    .await?;
    sqlx::query(&sql(Engine::of(conn), "DELETE FROM library_parameters WHERE class_id = ?1")).bind(&c.id).execute(&mut *conn).await?;
    for (position, p) in c.parameters.iter().enumerate() {
        sqlx::query(&sql(
            Engine::of(conn),
            "INSERT INTO library_parameters
                 (class_id, name, position, type, unit, min_value, max_value, editable, datasheet, default_json, comment)
             VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11)",
        ))
        .bind(&c.id)
        .bind(&p.name)
        .bind(position as i64)
        .bind(p.ty.as_str())
        .bind(&p.unit)
        .bind(p.min)
        .bind(p.max)
        .bind(i64::from(p.editable))
        .bind(i64::from(p.datasheet))
        .bind(p.default.as_ref().map(|d| d.to_json().to_string()))
        .bind(&p.comment)
        // Not a cached statement: sqlx's Any driver gives a NULL f64 the PostgreSQL type float4,
        // and a statement prepared with it would refuse the next row's float8 limit.
        .persistent(false)
        .execute(&mut *conn)
        .await?;
    }
    Ok(())
}

/// Creates or replaces an instance row.
async fn write_instance(conn: &mut AnyConnection, i: &Instance) -> Result<(), StoreError> {
    sqlx::query(&sql(
        Engine::of(conn),
        "INSERT INTO library_instances (id, class_id, name, values_json, source) VALUES (?1, ?2, ?3, ?4, ?5)
         ON CONFLICT(id) DO UPDATE SET class_id = excluded.class_id, name = excluded.name,
             values_json = excluded.values_json, source = excluded.source",
    ))
    .bind(&i.id)
    .bind(&i.class_id)
    .bind(&i.name)
    .bind(encode_values(&i.values))
    .bind(&i.source)
    .execute(&mut *conn)
    .await?;
    Ok(())
}

/// Creates a class (a taken name is a UNIQUE violation: [`StoreError::is_unique_violation`]).
pub async fn insert_class(store: &Store, class: &Class) -> Result<(), StoreError> {
    let mut tx = begin(store).await?;
    write_class(&mut tx, class).await?;
    tx.commit().await?;
    Ok(())
}

/// Changes a class: `check(old class, its instances)` returns the new class and the instances
/// carried over to it (see [`library::migrate_instance`]), written in the same transaction.
/// Returns the new class and how many instances were rewritten.
pub async fn update_class(
    store: &Store,
    id: &str,
    check: impl FnOnce(&Class, &[Instance]) -> Result<(Class, Vec<Instance>), Vec<Issue>>,
) -> Result<Change<(Class, usize)>, StoreError> {
    let mut tx = begin(store).await?;
    let Some(old) = load_classes(&mut tx, Some(id)).await?.into_iter().next() else {
        return Ok(Change::NotFound);
    };
    let instances: Vec<Instance> = load_instances(&mut tx, None, Some(id), None).await?.into_iter().map(|(i, _)| i).collect();
    let (class, migrated) = match check(&old, &instances) {
        Ok(x) => x,
        Err(issues) => return Ok(Change::Rejected(issues)),
    };
    write_class(&mut tx, &class).await?;
    let mut rewritten = 0;
    for m in &migrated {
        if instances.iter().any(|i| i == m) {
            continue;
        }
        write_instance(&mut tx, m).await?;
        rewritten += 1;
    }
    tx.commit().await?;
    Ok(Change::Done((class, rewritten)))
}

/// Deletes a class and its parameters, unless instances of it exist.
pub async fn delete_class(store: &Store, id: &str) -> Result<Removal, StoreError> {
    let mut tx = begin(store).await?;
    let found: Option<(String,)> =
        sqlx::query_as(&sql(Engine::of(&tx), "SELECT name FROM library_classes WHERE id = ?1")).bind(id).fetch_optional(&mut *tx).await?;
    let Some((name,)) = found else {
        return Ok(Removal::NotFound);
    };
    let users: Vec<(String,)> =
        sqlx::query_as(&sql(Engine::of(&tx), "SELECT name FROM library_instances WHERE class_id = ?1 ORDER BY name"))
            .bind(id)
            .fetch_all(&mut *tx)
            .await?;
    if !users.is_empty() {
        let names: Vec<String> = users.iter().take(5).map(|(n,)| format!("\"{n}\"")).collect();
        let more = if users.len() > 5 { format!(" and {} more", users.len() - 5) } else { String::new() };
        return Ok(Removal::InUse(format!(
            "class \"{name}\" still has {} instance(s): {}{more}; delete them first",
            users.len(),
            names.join(", ")
        )));
    }
    sqlx::query(&sql(Engine::of(&tx), "DELETE FROM library_classes WHERE id = ?1")).bind(id).execute(&mut *tx).await?;
    tx.commit().await?;
    Ok(Removal::Deleted)
}

/// Creates an instance of class `class_id` made by `check(class)`. `NotFound`: no such class.
pub async fn insert_instance(
    store: &Store,
    class_id: &str,
    check: impl FnOnce(&Class) -> Result<Instance, Vec<Issue>>,
) -> Result<Change<(Instance, Class)>, StoreError> {
    let mut tx = begin(store).await?;
    let Some(class) = load_classes(&mut tx, Some(class_id)).await?.into_iter().next() else {
        return Ok(Change::NotFound);
    };
    let instance = match check(&class) {
        Ok(i) => i,
        Err(issues) => return Ok(Change::Rejected(issues)),
    };
    write_instance(&mut tx, &instance).await?;
    tx.commit().await?;
    Ok(Change::Done((instance, class)))
}

/// Changes an instance to `check(class, old instance)`.
pub async fn update_instance(
    store: &Store,
    id: &str,
    check: impl FnOnce(&Class, &Instance) -> Result<Instance, Vec<Issue>>,
) -> Result<Change<(Instance, Class)>, StoreError> {
    let mut tx = begin(store).await?;
    let Some((old, class)) = load_instances(&mut tx, Some(id), None, None).await?.into_iter().next() else {
        return Ok(Change::NotFound);
    };
    let instance = match check(&class, &old) {
        Ok(i) => i,
        Err(issues) => return Ok(Change::Rejected(issues)),
    };
    write_instance(&mut tx, &instance).await?;
    tx.commit().await?;
    Ok(Change::Done((instance, class)))
}

/// Deletes an instance, unless a drive uses it.
pub async fn delete_instance(store: &Store, id: &str) -> Result<Removal, StoreError> {
    let mut tx = begin(store).await?;
    let found: Option<(String,)> =
        sqlx::query_as(&sql(Engine::of(&tx), "SELECT name FROM library_instances WHERE id = ?1")).bind(id).fetch_optional(&mut *tx).await?;
    let Some((name,)) = found else {
        return Ok(Removal::NotFound);
    };
    let drives: Vec<(String, String)> = sqlx::query_as(&sql(
        Engine::of(&tx),
        "SELECT model_id, joint FROM drives
         WHERE motor_instance = ?1 OR gear_instance = ?1 OR controller_instance = ?1 ORDER BY model_id, joint",
    ))
    .bind(id)
    .fetch_all(&mut *tx)
    .await?;
    if !drives.is_empty() {
        let list: Vec<String> = drives.iter().take(5).map(|(m, j)| format!("joint {j} of model {m}")).collect();
        let more = if drives.len() > 5 { format!(" and {} more", drives.len() - 5) } else { String::new() };
        return Ok(Removal::InUse(format!(
            "instance \"{name}\" is used by {} drive(s): {}{more}; assign another instance to those drives first",
            drives.len(),
            list.join(", ")
        )));
    }
    sqlx::query(&sql(Engine::of(&tx), "DELETE FROM library_instances WHERE id = ?1")).bind(id).execute(&mut *tx).await?;
    tx.commit().await?;
    Ok(Removal::Deleted)
}

/// Applies a checked plan: names of the rows being replaced are parked first, so that names may
/// move between items of the same file without tripping the UNIQUE constraints midway.
async fn apply_plan(conn: &mut AnyConnection, plan: &ImportPlan) -> Result<(), StoreError> {
    for c in &plan.classes {
        sqlx::query(&sql(Engine::of(conn), "UPDATE library_classes SET name = ?2 || id WHERE id = ?1"))
            .bind(&c.id)
            .bind("\u{1}")
            .execute(&mut *conn)
            .await?;
    }
    for i in &plan.instances {
        sqlx::query(&sql(Engine::of(conn), "UPDATE library_instances SET name = ?2 || id WHERE id = ?1"))
            .bind(&i.id)
            .bind("\u{1}")
            .execute(&mut *conn)
            .await?;
    }
    for c in &plan.classes {
        write_class(conn, c).await?;
    }
    for i in &plan.instances {
        write_instance(conn, i).await?;
    }
    Ok(())
}

/// Imports: `plan(current library)` checks everything ([`library::plan_import`]); the plan is
/// written in the same transaction, or nothing is.
pub async fn import(
    store: &Store,
    plan: impl FnOnce(&Library) -> Result<ImportPlan, Vec<Issue>>,
) -> Result<Result<ImportCounts, Vec<Issue>>, StoreError> {
    let mut tx = begin(store).await?;
    let current = load_library(&mut tx).await?;
    let plan = match plan(&current) {
        Ok(p) => p,
        Err(issues) => return Ok(Err(issues)),
    };
    apply_plan(&mut tx, &plan).await?;
    tx.commit().await?;
    Ok(Ok(plan.counts))
}

/// Fills an empty library with [`library::seed`] in one transaction. Does nothing (and returns
/// false) when any class exists, so it is safe on every start.
pub async fn seed_if_empty(store: &Store) -> Result<bool, StoreError> {
    let mut tx = begin(store).await?;
    let (count,): (i64,) = sqlx::query_as(&sql(Engine::of(&tx), "SELECT COUNT(*) FROM library_classes")).fetch_one(&mut *tx).await?;
    if count > 0 {
        return Ok(false);
    }
    let seed = seed_library()?;
    let plan = ImportPlan { classes: seed.classes, instances: seed.instances, ..ImportPlan::default() };
    apply_plan(&mut tx, &plan).await?;
    for i in &plan.instances {
        mark_offered(&mut tx, &i.id).await?;
    }
    // The seed's classes are as new as they get: nothing of theirs to offer again.
    for c in &plan.classes {
        mark_offered(&mut tx, &c.id).await?;
        for p in c.parameters.iter().filter(|p| library::seed::ADDED_DATASHEET.contains(&p.name.as_str())) {
            mark_offered(&mut tx, &format!("{}#{}", c.id, p.name)).await?;
        }
    }
    tx.commit().await?;
    tracing::info!(classes = plan.classes.len(), instances = plan.instances.len(), "seeded the motor library");
    Ok(true)
}

/// The built-in seed library (its own rules refusing it is a corrupt build, not bad input).
fn seed_library() -> Result<Library, StoreError> {
    library::seed::library().map_err(|issues| {
        let text: Vec<String> = issues.iter().map(|i| format!("{}: {}", i.field, i.message)).collect();
        corrupt(format!("the built-in seed library is invalid: {}", text.join("; ")))
    })
}

async fn mark_offered(conn: &mut AnyConnection, id: &str) -> Result<(), StoreError> {
    sqlx::query(&sql(Engine::of(conn), "INSERT INTO library_seed_offered (id) VALUES (?1) ON CONFLICT(id) DO NOTHING"))
        .bind(id)
        .execute(&mut *conn)
        .await?;
    Ok(())
}

/// Brings a library seeded by an earlier seed the seed instances it has not been offered yet
/// Brings the classes of an installation seeded before to the seed's: each class of
/// `seed::ADDED_CLASSES` and each datasheet parameter of `seed::ADDED_DATASHEET` (in every seed
/// class that has it) is offered once (`library_seed_offered`, keyed by the class id, or
/// `class id#parameter`): added when absent, so one the user deleted is not brought back. A class
/// is skipped when its name is taken; a datasheet parameter is optional per instance, so adding
/// one changes no instance. Returns the number of classes and parameters added.
pub async fn seed_new_classes(store: &Store) -> Result<usize, StoreError> {
    let seed = seed_library()?;
    let mut tx = begin(store).await?;
    let offered: Vec<(String,)> = sqlx::query_as("SELECT id FROM library_seed_offered").fetch_all(&mut *tx).await?;
    let offered: std::collections::HashSet<String> = offered.into_iter().map(|(id,)| id).collect();
    let current = load_library(&mut tx).await?;
    let mut added = 0;
    for c in seed.classes.iter().filter(|c| library::seed::ADDED_CLASSES.contains(&c.id.as_str()) && !offered.contains(&c.id)) {
        if current.class(&c.id).is_none() && !current.classes.iter().any(|x| x.name == c.name) {
            write_class(&mut tx, c).await?;
            added += 1;
        }
        mark_offered(&mut tx, &c.id).await?;
    }
    for seed_class in &seed.classes {
        let Some(class) = current.class(&seed_class.id) else { continue };
        let mut class = class.clone();
        let mut changed = false;
        for p in seed_class.parameters.iter().filter(|p| p.datasheet && library::seed::ADDED_DATASHEET.contains(&p.name.as_str())) {
            let key = format!("{}#{}", class.id, p.name);
            if offered.contains(&key) {
                continue;
            }
            if class.parameter(&p.name).is_none() {
                class.parameters.push(p.clone());
                changed = true;
                added += 1;
            }
            mark_offered(&mut tx, &key).await?;
        }
        if changed {
            write_class(&mut tx, &class).await?;
        }
    }
    tx.commit().await?;
    if added > 0 {
        tracing::info!(added, "added new seed classes and datasheet parameters to the motor library");
    }
    Ok(added)
}

/// (`library_seed_offered`, migration 0011): each is inserted when its fixed id is absent, its
/// class exists (its values carried over to the class as the installation has it,
/// [`library::migrate_instance`]) and its name is free in the class; otherwise it is skipped and
/// logged. Either way it is recorded as offered, so an instance the user deletes is not brought
/// back, and an existing row is never written. Returns the number inserted.
pub async fn seed_new_instances(store: &Store) -> Result<usize, StoreError> {
    let seed = seed_library()?;
    let mut tx = begin(store).await?;
    let offered: Vec<(String,)> = sqlx::query_as("SELECT id FROM library_seed_offered").fetch_all(&mut *tx).await?;
    let offered: std::collections::HashSet<String> = offered.into_iter().map(|(id,)| id).collect();
    let current = load_library(&mut tx).await?;
    let mut inserted = 0;
    for i in seed.instances.iter().filter(|i| !offered.contains(&i.id)) {
        if current.instances.iter().any(|c| c.id == i.id) {
            mark_offered(&mut tx, &i.id).await?;
            continue;
        }
        let (Some(seed_class), Some(class)) = (seed.class(&i.class_id), current.class(&i.class_id)) else {
            tracing::warn!(instance = %i.name, "seed instance not added: its class is not in the library");
            mark_offered(&mut tx, &i.id).await?;
            continue;
        };
        if current.instances.iter().any(|c| c.class_id == i.class_id && c.name == i.name) {
            tracing::warn!(instance = %i.name, "seed instance not added: its name is taken in its class");
            mark_offered(&mut tx, &i.id).await?;
            continue;
        }
        match library::migrate_instance(seed_class, class, i) {
            Ok(carried) => {
                sqlx::query(&sql(
                    Engine::of(&tx),
                    "INSERT INTO library_instances (id, class_id, name, values_json, source) VALUES (?1, ?2, ?3, ?4, ?5)
                     ON CONFLICT(id) DO NOTHING",
                ))
                .bind(&carried.id)
                .bind(&carried.class_id)
                .bind(&carried.name)
                .bind(encode_values(&carried.values))
                .bind(&carried.source)
                .execute(&mut *tx)
                .await?;
                inserted += 1;
            }
            Err(issues) => {
                let text: Vec<String> = issues.iter().map(|x| format!("{}: {}", x.field, x.message)).collect();
                tracing::warn!(instance = %i.name, problems = %text.join("; "), "seed instance not added: it does not fit its class as changed here");
            }
        }
        mark_offered(&mut tx, &i.id).await?;
    }
    tx.commit().await?;
    if inserted > 0 {
        tracing::info!(instances = inserted, "added new seed instances to the motor library");
    }
    Ok(inserted)
}

#[cfg(test)]
mod tests {
    use super::*;
    use cad2mo_engine::library::seed;

    async fn store() -> (tempfile::TempDir, Store) {
        let dir = tempfile::tempdir().expect("tempdir");
        let url = format!("sqlite://{}?mode=rwc", dir.path().join("t.db").display());
        let store = Store::open(&url).await.expect("store");
        (dir, store)
    }

    #[tokio::test]
    async fn seeding_is_idempotent_and_reads_back_exactly() {
        let (_dir, store) = store().await;
        assert!(seed_if_empty(&store).await.expect("seed"));
        assert!(!seed_if_empty(&store).await.expect("seed again"));
        let lib = export(&store).await.expect("export");
        assert_eq!(lib, seed::library().expect("seed"));
    }

    #[tokio::test]
    async fn reals_survive_the_database_bit_for_bit() {
        let (_dir, store) = store().await;
        seed_if_empty(&store).await.expect("seed");
        // Values whose shortest decimal has 17 digits.
        let awkward = [0.1 + 0.2, std::f64::consts::PI / 30.0 * 6940.0, 1.0 / 3.0, 2.2250738585072014e-308, 5e-324];
        for (k, x) in awkward.into_iter().enumerate() {
            let r = update_instance(&store, seed::GEAR_100, |_, old| {
                let mut i = old.clone();
                i.values = vec![("ratio".into(), Value::Real(x))];
                i.name = format!("gear {k}");
                Ok(i)
            })
            .await
            .expect("update");
            assert!(matches!(r, Change::Done(_)));
            let (back, _) = get_instance(&store, seed::GEAR_100).await.expect("get").expect("found");
            assert_eq!(back.value("ratio"), Some(&Value::Real(x)), "{x:e}");
        }
    }

    #[tokio::test]
    async fn an_instance_used_by_a_drive_cannot_be_deleted() {
        let (_dir, store) = store().await;
        seed_if_empty(&store).await.expect("seed");
        sqlx::query(&store.pool.sql("INSERT INTO models (id, name, created_at) VALUES ('m1', 'Robot', '2024-01-01T00:00:00Z')"))
            .execute(&store.pool)
            .await
            .expect("model");
        sqlx::query(&store.pool.sql(
            "INSERT INTO drives (model_id, joint, joint_node_id, motor_instance, gear_instance, controller_instance,
                 reference_json, updated_at)
             VALUES ('m1', 'J1', '1', ?1, ?2, ?3, '{}', '2024-01-01T00:00:00Z')",
        ))
        .bind(seed::MAXON_RE40)
        .bind(seed::GEAR_100)
        .bind(seed::ROBOT_R3_CONTROLLER)
        .execute(&store.pool)
        .await
        .expect("drive");
        match delete_instance(&store, seed::GEAR_100).await.expect("delete") {
            Removal::InUse(msg) => assert!(msg.contains("joint J1 of model m1"), "{msg}"),
            other => panic!("{other:?}"),
        }
        assert!(get_instance(&store, seed::GEAR_100).await.expect("get").is_some());
        assert_eq!(delete_instance(&store, seed::FAULHABER_1331).await.expect("delete"), Removal::Deleted);
        assert_eq!(delete_instance(&store, seed::FAULHABER_1331).await.expect("delete"), Removal::NotFound);
    }

    /// An installation seeded before migration 0005 (the seed without datasheet parameters,
    /// values and source sentences) ends up with exactly the new seed once 0005 ran.
    #[tokio::test]
    async fn migration_0005_brings_an_old_seed_to_the_new_one() {
        let (_dir, store) = store().await;
        seed_if_empty(&store).await.expect("seed");
        let new = export(&store).await.expect("export");
        // Back to the old seed.
        sqlx::query(&store.pool.sql("DELETE FROM library_parameters WHERE datasheet = 1")).execute(&store.pool).await.expect("params");
        // The amplifier and AC servo classes (with the servos) came after 0005.
        for class in [seed::SERVO_AMPLIFIER, seed::AC_SERVO] {
            sqlx::query(&store.pool.sql("DELETE FROM library_instances WHERE class_id = ?1"))
                .bind(class)
                .execute(&store.pool)
                .await
                .expect("instances");
            sqlx::query(&store.pool.sql("DELETE FROM library_classes WHERE id = ?1"))
                .bind(class)
                .execute(&store.pool)
                .await
                .expect("class");
        }
        for i in &new.instances {
            // Controllers have no datasheet values.
            let Some(cut) = ["Datasheet values for the drive sizing", "No datasheet values for the drive sizing"]
                .iter()
                .filter_map(|m| i.source.find(m))
                .min()
            else {
                continue;
            };
            sqlx::query(&store.pool.sql(
                "UPDATE library_instances SET source = ?2, values_json = json_remove(values_json,
                     '$.T_nom', '$.T_peak', '$.w_max', '$.T_rated', '$.w_in_max', '$.J_in', '$.F_peak') WHERE id = ?1",
            ))
            .bind(&i.id)
            .bind(i.source[..cut].trim_end())
            .execute(&store.pool)
            .await
            .expect("instance");
        }
        let old = export(&store).await.expect("old");
        assert!(old.classes.iter().all(|c| c.parameters.iter().all(|p| !p.datasheet)));
        assert_ne!(old, new);
        // The migration again, without the column it adds.
        let sql = include_str!("../../../migrations/sqlite/0005_library_datasheet.sql");
        let data = sql.split_once("DEFAULT 0;").expect("the ALTER TABLE").1;
        sqlx::raw_sql(data).execute(&store.pool).await.expect("migrate");
        // 0015 corrects the first-seed RE 40's source text that 0005 wrote.
        let fix = include_str!("../../../migrations/sqlite/0015_re40_source.sql");
        sqlx::raw_sql(fix).execute(&store.pool).await.expect("migrate 0015");
        // 0017 removes the first-seed gear's unsourced torque ratings that 0005 wrote.
        let fix = include_str!("../../../migrations/sqlite/0017_gear100_ratings.sql");
        sqlx::raw_sql(fix).execute(&store.pool).await.expect("migrate 0017");
        // The datasheet parameters added since 0005 come at start-up (seed_new_classes).
        sqlx::query("DELETE FROM library_seed_offered").execute(&store.pool).await.expect("offered");
        seed_new_classes(&store).await.expect("new parameters");
        seed_new_instances(&store).await.expect("the servos");
        assert_eq!(export(&store).await.expect("export"), new);
    }

    /// An installation seeded before the amplifier class and the new datasheet parameters
    /// receives them once; a parameter its user deletes afterwards is not brought back.
    #[tokio::test]
    async fn an_old_seed_receives_the_new_classes_and_parameters_once() {
        let (_dir, store) = store().await;
        seed_if_empty(&store).await.expect("seed");
        let new = export(&store).await.expect("export");
        assert_eq!(seed_new_classes(&store).await.expect("nothing to add"), 0);
        sqlx::query(&store.pool.sql("DELETE FROM library_classes WHERE id = ?1"))
            .bind(seed::SERVO_AMPLIFIER)
            .execute(&store.pool)
            .await
            .expect("class");
        sqlx::query(&store.pool.sql("DELETE FROM library_parameters WHERE name IN ('mount', 'motor_mounts')"))
            .execute(&store.pool)
            .await
            .expect("params");
        sqlx::query("DELETE FROM library_seed_offered").execute(&store.pool).await.expect("offered");
        assert_ne!(export(&store).await.expect("old"), new);
        let added = seed_new_classes(&store).await.expect("upgrade");
        assert_eq!(export(&store).await.expect("upgraded"), new);
        assert!(added >= 6, "{added}");
        sqlx::query(&store.pool.sql("DELETE FROM library_parameters WHERE name = 'T_stall'"))
            .execute(&store.pool)
            .await
            .expect("user deletes");
        assert_eq!(seed_new_classes(&store).await.expect("again"), 0);
        let lib = export(&store).await.expect("export");
        assert!(lib.classes.iter().all(|c| c.parameter("T_stall").is_none()));
    }

    /// An installation seeded with the first seed (nine instances, one since deleted by its user,
    /// one changed) receives the catalogue instances once, and nothing it had is rewritten or
    /// brought back.
    #[tokio::test]
    async fn an_old_seed_receives_the_new_instances_once() {
        let (_dir2, fresh) = store().await;
        let (_dir, store) = store().await;
        seed_if_empty(&store).await.expect("seed");
        let new = export(&store).await.expect("export");
        // Back to the first seed, as migration 0011 finds it: catalogue rows absent, nothing offered.
        for id in seed::CATALOGUE {
            sqlx::query(&store.pool.sql("DELETE FROM library_instances WHERE id = ?1"))
                .bind(id)
                .execute(&store.pool)
                .await
                .expect("delete");
        }
        sqlx::query("DELETE FROM library_seed_offered").execute(&store.pool).await.expect("offered");
        let sql = include_str!("../../../migrations/sqlite/0011_library_seed_offered.sql");
        let data = sql.split_once(");\n").expect("the CREATE TABLE").1;
        sqlx::raw_sql(data).execute(&store.pool).await.expect("migrate");
        // The user deleted one first-seed instance and renamed another.
        assert_eq!(delete_instance(&store, seed::FAULHABER_1331).await.expect("delete"), Removal::Deleted);
        let r = update_instance(&store, seed::MAXON_RE40, |_, old| Ok(Instance { name: "my RE 40".into(), ..old.clone() }))
            .await
            .expect("rename");
        assert!(matches!(r, Change::Done(_)));
        let before = export(&store).await.expect("before");
        assert_eq!(seed_new_instances(&store).await.expect("upgrade"), seed::CATALOGUE.len());
        let after = export(&store).await.expect("after");
        for i in &before.instances {
            assert_eq!(after.instances.iter().find(|a| a.id == i.id), Some(i), "{} unchanged", i.name);
        }
        assert!(!after.instances.iter().any(|i| i.id == seed::FAULHABER_1331), "a deleted instance stays deleted");
        for id in seed::CATALOGUE {
            let want = new.instances.iter().find(|i| i.id == id).expect("seed");
            assert_eq!(after.instances.iter().find(|i| i.id == id), Some(want));
        }
        assert_eq!(after.instances.len(), before.instances.len() + seed::CATALOGUE.len());
        // Once only: deleting a catalogue instance and starting again does not bring it back.
        assert_eq!(delete_instance(&store, seed::FAULHABER_2250_024_BX4).await.expect("delete"), Removal::Deleted);
        assert_eq!(seed_new_instances(&store).await.expect("again"), 0);
        assert!(get_instance(&store, seed::FAULHABER_2250_024_BX4).await.expect("get").is_none());
        // A fresh installation has been offered everything: nothing to add.
        seed_if_empty(&fresh).await.expect("seed");
        assert_eq!(seed_new_instances(&fresh).await.expect("fresh"), 0);
        assert_eq!(export(&fresh).await.expect("export"), seed::library().expect("seed"));
    }

    #[tokio::test]
    async fn a_rejected_import_writes_nothing() {
        let (_dir, store) = store().await;
        seed_if_empty(&store).await.expect("seed");
        let before = export(&store).await.expect("export");
        let r = import(&store, |_| Err(vec![Issue::new("x", "no")])).await.expect("import");
        assert!(r.is_err());
        assert_eq!(export(&store).await.expect("export"), before);
    }
}
