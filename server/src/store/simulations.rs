//! SQL for closed-loop simulations (issue 28).

use super::{now, Store, StoreError};

/// A stored simulation row.
#[derive(Clone, Debug, PartialEq)]
pub struct SimulationRow {
    pub id: String,
    pub model_id: String,
    pub version: i64,
    pub motion_id: Option<String>,
    pub result_id: Option<String>,
    pub request_json: String,
    pub answer_json: String,
    pub created_at: String,
}

type Row = (String, String, i64, Option<String>, Option<String>, String, String, String);
const COLUMNS: &str = "id, model_id, version, motion_id, result_id, request_json, answer_json, created_at";

fn from_row((id, model_id, version, motion_id, result_id, request_json, answer_json, created_at): Row) -> SimulationRow {
    SimulationRow { id, model_id, version, motion_id, result_id, request_json, answer_json, created_at }
}

/// Stores a finished simulation; returns its row.
pub async fn insert(
    store: &Store,
    model_id: &str,
    version: i64,
    motion_id: Option<&str>,
    result_id: Option<&str>,
    request_json: &str,
    answer_json: &str,
) -> Result<SimulationRow, StoreError> {
    let t = now(&store.pool).await?;
    let id = uuid::Uuid::new_v4().to_string();
    sqlx::query(&store.pool.sql(format!("INSERT INTO simulations ({COLUMNS}) VALUES (?, ?, ?, ?, ?, ?, ?, ?)")))
        .bind(&id)
        .bind(model_id)
        .bind(version)
        .bind(motion_id)
        .bind(result_id)
        .bind(request_json)
        .bind(answer_json)
        .bind(&t)
        .execute(&store.pool)
        .await?;
    Ok(SimulationRow {
        id,
        model_id: model_id.into(),
        version,
        motion_id: motion_id.map(str::to_string),
        result_id: result_id.map(str::to_string),
        request_json: request_json.into(),
        answer_json: answer_json.into(),
        created_at: t,
    })
}

/// A model's simulation `id`.
pub async fn get(store: &Store, model_id: &str, id: &str) -> Result<Option<SimulationRow>, StoreError> {
    let row: Option<Row> = sqlx::query_as(&store.pool.sql(format!("SELECT {COLUMNS} FROM simulations WHERE model_id = ? AND id = ?")))
        .bind(model_id)
        .bind(id)
        .fetch_optional(&store.pool)
        .await?;
    Ok(row.map(from_row))
}

/// A model's simulations, oldest first (`motion_id`: only those of that motion).
pub async fn list(store: &Store, model_id: &str, motion_id: Option<&str>) -> Result<Vec<SimulationRow>, StoreError> {
    let rows: Vec<Row> = match motion_id {
        None => {
            sqlx::query_as(&store.pool.sql(format!("SELECT {COLUMNS} FROM simulations WHERE model_id = ? ORDER BY created_at, rowid")))
                .bind(model_id)
                .fetch_all(&store.pool)
                .await?
        }
        Some(m) => {
            sqlx::query_as(
                &store
                    .pool
                    .sql(format!("SELECT {COLUMNS} FROM simulations WHERE model_id = ? AND motion_id = ? ORDER BY created_at, rowid")),
            )
            .bind(model_id)
            .bind(m)
            .fetch_all(&store.pool)
            .await?
        }
    };
    Ok(rows.into_iter().map(from_row).collect())
}
