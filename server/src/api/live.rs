//! The live view over HTTP (docs/live-protocol.md): the relay's state, a version's live streams,
//! and the WebSocket that carries a version's frames to a browser.

use axum::extract::ws::rejection::WebSocketUpgradeRejection;
use axum::extract::ws::{Message as WsMessage, WebSocket, WebSocketUpgrade};
use axum::extract::State;
use axum::response::Response;
use axum::routing::get;
use axum::{Json, Router};
use serde::Serialize;
use tokio::sync::broadcast::error::RecvError;

use super::extract::Path;
use super::ApiError;
use crate::app::AppState;
use crate::relay::{Counters, Message, RunView};

pub fn router() -> Router<AppState> {
    Router::new()
        .route("/api/live", get(status))
        .route("/api/models/{model_id}/versions/{version}/live", get(version_info))
        .route("/api/models/{model_id}/versions/{version}/live/ws", get(watch))
}

/// The sub-protocol browsers offer (with `bearer.<token>` where tokens are required).
pub const PROTOCOL: &str = "cad2mo.live";

#[derive(Serialize)]
struct Status {
    enabled: bool,
    /// Where simulations send frames (`null` when off).
    udp: Option<String>,
    /// Why the live view is off.
    #[serde(skip_serializing_if = "Option::is_none")]
    reason: Option<String>,
    auth_required: bool,
    counters: Counters,
}

async fn status(State(state): State<AppState>) -> Json<Status> {
    let r = &state.relay;
    Json(Status {
        enabled: r.addr().is_some(),
        udp: r.addr().map(|a| a.to_string()),
        reason: r.off_reason().map(str::to_string),
        auth_required: r.requires_auth(),
        counters: r.counters(),
    })
}

#[derive(Serialize)]
struct VersionLive {
    model: String,
    version: u32,
    bodies: Vec<String>,
    /// The layout id the frames must carry (16 hex digits).
    layout: String,
    udp: Option<String>,
    auth_required: bool,
    /// The runs seen, newest first.
    streams: Vec<RunView>,
}

/// A version number as frames carry it (u32); anything else has no live view (404).
fn version_of(model_id: &str, v: i64) -> Result<u32, ApiError> {
    u32::try_from(v).ok().filter(|v| *v >= 1).ok_or_else(|| ApiError::NotFound(format!("converted version {v} of model {model_id}")))
}

async fn bodies(state: &AppState, model_id: &str, version: u32) -> Result<std::sync::Arc<crate::relay::VersionBodies>, ApiError> {
    state
        .relay
        .bodies(model_id, version)
        .await?
        .ok_or_else(|| ApiError::NotFound(format!("converted version {version} of model {model_id}")))
}

async fn version_info(
    State(state): State<AppState>,
    Path((model_id, version)): Path<(String, i64)>,
) -> Result<Json<VersionLive>, ApiError> {
    let version = version_of(&model_id, version)?;
    let b = bodies(&state, &model_id, version).await?;
    Ok(Json(VersionLive {
        streams: state.relay.runs(&model_id, version),
        model: model_id,
        version,
        bodies: b.bodies.clone(),
        layout: hex::encode(b.layout),
        udp: state.relay.addr().map(|a| a.to_string()),
        auth_required: state.relay.requires_auth(),
    }))
}

async fn watch(
    State(state): State<AppState>,
    Path((model_id, version)): Path<(String, i64)>,
    ws: Result<WebSocketUpgrade, WebSocketUpgradeRejection>,
) -> Result<Response, ApiError> {
    let version = version_of(&model_id, version)?;
    let b = bodies(&state, &model_id, version).await?;
    let ws = ws.map_err(|e| {
        ApiError::BadRequest(format!("this is a WebSocket endpoint: open it with the sub-protocol {PROTOCOL} ({})", e.body_text()))
    })?;
    let rx = state.relay.subscribe(&model_id, version);
    let hello = serde_json::json!({ "type": "hello", "model": model_id, "version": version, "bodies": b.bodies }).to_string();
    Ok(ws.protocols([PROTOCOL]).on_upgrade(move |socket| relay_to(socket, hello, rx)))
}

/// Sends the hello, then every message of the version until either side goes away. A browser
/// that falls behind skips to the newest messages.
async fn relay_to(mut socket: WebSocket, hello: String, mut rx: tokio::sync::broadcast::Receiver<Message>) {
    if socket.send(WsMessage::Text(hello.into())).await.is_err() {
        return;
    }
    loop {
        tokio::select! {
            m = rx.recv() => {
                let out = match m {
                    Ok(Message::Frame(b)) => WsMessage::Binary(b.as_ref().clone().into()),
                    Ok(Message::Text(t)) => WsMessage::Text(t.as_str().into()),
                    Err(RecvError::Lagged(_)) => continue,
                    Err(RecvError::Closed) => break,
                };
                if socket.send(out).await.is_err() {
                    break;
                }
            }
            incoming = socket.recv() => match incoming {
                Some(Ok(WsMessage::Close(_))) | None | Some(Err(_)) => break,
                Some(Ok(_)) => {}
            },
        }
    }
}
