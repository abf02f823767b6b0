//! The live view relay: receives the frames running simulations send (UDP, see
//! docs/live-protocol.md), checks them with [`cad2mo_engine::live`], and hands each version's frames to
//! the browsers watching it. One task owns the socket; browsers subscribe to a broadcast channel
//! per version (a slow one skips to the newest frame, it never holds the others up).
//!
//! Memory is bounded whatever arrives: at most [`MAX_VERSIONS`] versions and [`MAX_RUNS`] runs
//! per version are tracked (the least recently seen are forgotten), and version lookups are
//! limited to [`LOOKUPS_PER_SECOND`] so that frames naming random models cannot load the store.

use std::collections::HashMap;
use std::net::SocketAddr;
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::{Duration, Instant};

use serde::Serialize;
use tokio::net::UdpSocket;
use tokio::sync::broadcast;

use crate::store::blobs::Blobs;
use crate::store::Store;
use cad2mo_engine::live::{self, Accept, Drop, RunStats};

pub const MAX_VERSIONS: usize = 256;
pub const MAX_RUNS: usize = 8;
pub const LOOKUPS_PER_SECOND: u32 = 20;
/// How long a version lookup's answer is kept.
const LOOKUP_TTL: Duration = Duration::from_secs(5);
/// How long the token keys are kept before they are read again (a revocation takes this long).
const KEYS_TTL: Duration = Duration::from_secs(10);
/// The least time between two key reads for an unknown key id.
const KEYS_RETRY: Duration = Duration::from_secs(1);

/// A message for the browsers of one version.
#[derive(Clone, Debug)]
pub enum Message {
    /// A frame: u32 run, u32 seq, f64 time, u32 n, u32 flags, then 7 f32 per body.
    Frame(Arc<Vec<u8>>),
    /// `stats` or `end` JSON.
    Text(Arc<String>),
}

/// A converted version as the live view sees it.
#[derive(Clone, Debug)]
pub struct VersionBodies {
    pub bodies: Vec<String>,
    pub layout: [u8; 8],
}

/// Frames counted by what became of them.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Counters {
    pub received: u64,
    pub relayed: u64,
    /// Frames missing from sequence gaps, over all runs.
    pub lost: u64,
    pub dropped: HashMap<&'static str, u64>,
}

/// The newest runs of one version and its subscribers.
struct Channel {
    tx: broadcast::Sender<Message>,
    runs: Vec<(RunStats, Instant)>,
    stats_sent: Option<Instant>,
    seen: Instant,
}

/// A run as `GET .../live` reports it.
#[derive(Clone, Debug, Serialize)]
pub struct RunView {
    #[serde(flatten)]
    pub stats: RunStats,
    /// Wall-clock seconds since its newest frame.
    pub last_seen_s: f64,
}

enum Lookup {
    Found(Arc<VersionBodies>, Instant),
    Missing(Instant),
}

struct State {
    counters: Counters,
    channels: HashMap<(String, u32), Channel>,
    lookups: HashMap<(String, u32), Lookup>,
    lookup_budget: (Instant, u32),
    keys: HashMap<[u8; 8], [u8; 32]>,
    keys_read: Option<Instant>,
}

struct Inner {
    store: Store,
    blobs: Blobs,
    requires_auth: bool,
    addr: Option<SocketAddr>,
    /// Why the live view is off (`addr` is `None`).
    off: Option<String>,
    state: Mutex<State>,
    epoch: Instant,
}

/// The relay (cheap to clone).
#[derive(Clone)]
pub struct Relay {
    inner: Arc<Inner>,
}

impl Relay {
    /// Binds `bind` and starts receiving; without `bind`, or when it cannot be bound, the relay
    /// is off (and says why) but everything else works.
    pub async fn start(bind: Option<SocketAddr>, requires_auth: bool, store: Store, blobs: Blobs) -> Relay {
        let (socket, off) = match bind {
            None => (None, Some("turned off (--live-bind off)".to_string())),
            Some(a) => match UdpSocket::bind(a).await {
                Ok(s) => (Some(s), None),
                Err(e) => {
                    tracing::warn!(%a, error = %e, "the live view could not bind its UDP port: it is off");
                    (None, Some(format!("could not listen on {a}: {e}")))
                }
            },
        };
        let addr = socket.as_ref().and_then(|s| s.local_addr().ok());
        let now = Instant::now();
        let relay = Relay {
            inner: Arc::new(Inner {
                store,
                blobs,
                requires_auth,
                addr,
                off,
                state: Mutex::new(State {
                    counters: Counters::default(),
                    channels: HashMap::new(),
                    lookups: HashMap::new(),
                    lookup_budget: (now, 0),
                    keys: HashMap::new(),
                    keys_read: None,
                }),
                epoch: now,
            }),
        };
        if let Some(s) = socket {
            tracing::info!(addr = ?addr, "live view listening (UDP)");
            let r = relay.clone();
            tokio::spawn(async move { r.receive(s).await });
        }
        relay
    }

    /// The UDP address frames go to (`None`: off).
    pub fn addr(&self) -> Option<SocketAddr> {
        self.inner.addr
    }

    /// Why the live view is off.
    pub fn off_reason(&self) -> Option<&str> {
        self.inner.off.as_deref()
    }

    pub fn requires_auth(&self) -> bool {
        self.inner.requires_auth
    }

    pub fn counters(&self) -> Counters {
        let mut c = self.lock().counters.clone();
        for d in Drop::ALL {
            c.dropped.entry(d.name()).or_insert(0);
        }
        c
    }

    fn lock(&self) -> MutexGuard<'_, State> {
        self.inner.state.lock().unwrap_or_else(|p| p.into_inner())
    }

    fn now_s(&self) -> f64 {
        self.inner.epoch.elapsed().as_secs_f64()
    }

    /// The runs of a version, newest first.
    pub fn runs(&self, model: &str, version: u32) -> Vec<RunView> {
        let st = self.lock();
        let Some(ch) = st.channels.get(&(model.to_string(), version)) else { return Vec::new() };
        let mut runs: Vec<RunView> =
            ch.runs.iter().map(|(s, seen)| RunView { stats: s.clone(), last_seen_s: seen.elapsed().as_secs_f64() }).collect();
        runs.sort_by(|a, b| a.last_seen_s.total_cmp(&b.last_seen_s));
        runs
    }

    /// Subscribes to a version's frames.
    pub fn subscribe(&self, model: &str, version: u32) -> broadcast::Receiver<Message> {
        let mut st = self.lock();
        let ch = channel(&mut st, (model.to_string(), version));
        ch.tx.subscribe()
    }

    /// The bodies of a converted version (`None`: no such converted version). Cached for 5 s.
    pub async fn bodies(&self, model: &str, version: u32) -> Result<Option<Arc<VersionBodies>>, crate::store::StoreError> {
        let key = (model.to_string(), version);
        if let Some(Lookup::Found(b, at)) = self.lock().lookups.get(&key) {
            if at.elapsed() < LOOKUP_TTL {
                return Ok(Some(b.clone()));
            }
        }
        let found = self.read_bodies(model, version).await?;
        let mut st = self.lock();
        if st.lookups.len() >= 4 * MAX_VERSIONS {
            st.lookups.clear();
        }
        let now = Instant::now();
        st.lookups.insert(key, found.clone().map_or(Lookup::Missing(now), |b| Lookup::Found(b, now)));
        Ok(found)
    }

    async fn read_bodies(&self, model: &str, version: u32) -> Result<Option<Arc<VersionBodies>>, crate::store::StoreError> {
        let Some(row) = crate::store::models::get_version(&self.inner.store.pool, model, i64::from(version)).await? else {
            return Ok(None);
        };
        let Some(report) = row.report_sha256.filter(|_| row.status == "succeeded") else { return Ok(None) };
        let blobs = self.inner.blobs.clone();
        let bytes = tokio::task::spawn_blocking(move || blobs.get(&report)).await.ok().and_then(Result::ok).flatten();
        let Some(bytes) = bytes else { return Ok(None) };
        let report: serde_json::Value = serde_json::from_slice(&bytes).unwrap_or_default();
        let bodies: Vec<String> = report["bodies"]
            .as_array()
            .map(|a| a.iter().filter_map(|b| b["modelica_name"].as_str().map(str::to_string)).collect())
            .unwrap_or_default();
        if bodies.is_empty() {
            return Ok(None);
        }
        let layout = live::layout_id(&bodies);
        Ok(Some(Arc::new(VersionBodies { bodies, layout })))
    }

    /// The key of a key id, reading the store's tokens when it is unknown (at most once a second)
    /// or old (every 10 s).
    async fn key(&self, id: [u8; 8]) -> Option<[u8; 32]> {
        let stale = {
            let st = self.lock();
            let fresh = st.keys_read.is_some_and(|t| t.elapsed() < KEYS_TTL);
            match st.keys.get(&id) {
                Some(k) if fresh => return Some(*k),
                _ => !fresh || st.keys_read.is_none_or(|t| t.elapsed() >= KEYS_RETRY),
            }
        };
        if stale {
            if let Ok(hashes) = crate::store::tokens::live_hashes(&self.inner.store).await {
                let keys: HashMap<[u8; 8], [u8; 32]> =
                    hashes.iter().filter_map(|h| <[u8; 32]>::try_from(hex::decode(h).ok()?).ok()).map(|k| (live::key_id(&k), k)).collect();
                let mut st = self.lock();
                st.keys = keys;
                st.keys_read = Some(Instant::now());
            }
        }
        self.lock().keys.get(&id).copied()
    }

    fn count(&self, d: Drop) {
        *self.lock().counters.dropped.entry(d.name()).or_insert(0) += 1;
    }

    async fn receive(self, socket: UdpSocket) {
        let mut buf = vec![0u8; 65_536];
        loop {
            let n = match socket.recv_from(&mut buf).await {
                Ok((n, _)) => n,
                Err(e) => {
                    // ICMP errors and the like: nothing to do with the next datagram.
                    tracing::debug!(error = %e, "live view receive");
                    continue;
                }
            };
            self.lock().counters.received += 1;
            if let Err(d) = self.take(&buf[..n]).await {
                self.count(d);
            }
        }
    }

    /// Checks one datagram and relays it (see the protocol for the order of the checks).
    async fn take(&self, d: &[u8]) -> Result<(), Drop> {
        let f = live::decode(d)?;
        if f.tag.is_some() || self.inner.requires_auth {
            if f.tag.is_none() {
                return Err(Drop::Unauthenticated);
            }
            let key = self.key(f.key_id).await.ok_or(Drop::Unauthenticated)?;
            if !live::verify(&f, &key) {
                return Err(Drop::Unauthenticated);
            }
        }
        let model = f.model_id();
        let bodies = self.known(&model, f.version).await.ok_or(Drop::Foreign)?;
        if bodies.layout != f.layout || bodies.bodies.len() != f.body_count() {
            return Err(Drop::Foreign);
        }
        let mut msg = Vec::with_capacity(24 + 28 * f.body_count());
        msg.extend_from_slice(&f.run.to_le_bytes());
        msg.extend_from_slice(&f.seq.to_le_bytes());
        msg.extend_from_slice(&f.time.to_le_bytes());
        msg.extend_from_slice(&(f.body_count() as u32).to_le_bytes());
        msg.extend_from_slice(&u32::from(f.flags).to_le_bytes());
        let mut poses = Vec::with_capacity(7 * f.body_count());
        live::poses_into(&f, &mut poses)?;
        for x in poses {
            msg.extend_from_slice(&x.to_le_bytes());
        }
        let now = self.now_s();
        let mut st = self.lock();
        let ch = channel(&mut st, (model, f.version));
        let run = match ch.runs.iter().position(|(r, _)| r.run == f.run) {
            Some(i) => i,
            None => {
                if ch.runs.len() >= MAX_RUNS {
                    if let Some(oldest) = ch.runs.iter().enumerate().min_by_key(|(_, (_, seen))| *seen).map(|(i, _)| i) {
                        ch.runs.remove(oldest);
                    }
                }
                ch.runs.push((RunStats::new(f.run), Instant::now()));
                ch.runs.len() - 1
            }
        };
        let (stats, seen) = &mut ch.runs[run];
        let lost = match stats.accept(f.seq, f.time, f.is_final(), now) {
            Accept::Stale => return Err(Drop::Stale),
            Accept::Newer { lost } => lost,
        };
        *seen = Instant::now();
        ch.seen = Instant::now();
        let stats = stats.clone();
        let _ = ch.tx.send(Message::Frame(Arc::new(msg)));
        if ch.stats_sent.is_none_or(|t| t.elapsed() >= Duration::from_secs(1)) || f.is_final() {
            ch.stats_sent = Some(Instant::now());
            let mut j = serde_json::to_value(&stats).unwrap_or_default();
            j["type"] = "stats".into();
            let _ = ch.tx.send(Message::Text(Arc::new(j.to_string())));
        }
        if f.is_final() {
            let j = serde_json::json!({ "type": "end", "run": f.run, "time": f.time });
            let _ = ch.tx.send(Message::Text(Arc::new(j.to_string())));
        }
        st.counters.relayed += 1;
        st.counters.lost += u64::from(lost);
        Ok(())
    }

    /// The bodies of a version frames name, within the lookup budget.
    async fn known(&self, model: &str, version: u32) -> Option<Arc<VersionBodies>> {
        {
            let mut st = self.lock();
            match st.lookups.get(&(model.to_string(), version)) {
                Some(Lookup::Found(b, at)) if at.elapsed() < LOOKUP_TTL => return Some(b.clone()),
                Some(Lookup::Missing(at)) if at.elapsed() < LOOKUP_TTL => return None,
                _ => {}
            }
            let (start, used) = &mut st.lookup_budget;
            if start.elapsed() >= Duration::from_secs(1) {
                *start = Instant::now();
                *used = 0;
            }
            if *used >= LOOKUPS_PER_SECOND {
                return None;
            }
            *used += 1;
        }
        self.bodies(model, version).await.ok().flatten()
    }
}

/// The channel of a version, made on first use; beyond [`MAX_VERSIONS`], the least recently
/// seen one without subscribers is forgotten.
fn channel(st: &mut State, key: (String, u32)) -> &mut Channel {
    if !st.channels.contains_key(&key) && st.channels.len() >= MAX_VERSIONS {
        let idle = st.channels.iter().filter(|(_, c)| c.tx.receiver_count() == 0).min_by_key(|(_, c)| c.seen).map(|(k, _)| k.clone());
        if let Some(k) = idle {
            st.channels.remove(&k);
        }
    }
    st.channels.entry(key).or_insert_with(|| Channel {
        tx: broadcast::channel(16).0,
        runs: Vec::new(),
        stats_sent: None,
        seen: Instant::now(),
    })
}
