//! The live view's frames (docs/live-protocol.md): decoding and checking what a simulation sends,
//! the poses a browser gets, and the bookkeeping of runs (loss, order, rate). Plain data in and
//! out: the socket, the store lookups and the browsers are the relay's (`crate::relay`).

use hmac::{Hmac, Mac};
use nalgebra::{Matrix3, Vector3};
use serde::Serialize;
use sha2::{Digest, Sha256};

pub use crate::pipeline::back::modelica::mechatronics::live::{layout_hex, layout_id, MAX_BODIES};

pub const MAGIC: &[u8; 4] = b"C2ML";
pub const PROTOCOL: u8 = 1;
pub const HEADER: usize = 64;
pub const BODY: usize = 48;
pub const TAG: usize = 32;
pub const FLAG_AUTH: u8 = 1;
pub const FLAG_FINAL: u8 = 2;

/// Why a datagram was not relayed, in the order the receiver checks (see the protocol).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Drop {
    Malformed,
    Version,
    Truncated,
    Unauthenticated,
    Foreign,
    Invalid,
    Stale,
}

impl Drop {
    pub const ALL: [Drop; 7] =
        [Drop::Malformed, Drop::Version, Drop::Truncated, Drop::Unauthenticated, Drop::Foreign, Drop::Invalid, Drop::Stale];

    pub fn name(self) -> &'static str {
        match self {
            Drop::Malformed => "malformed",
            Drop::Version => "version",
            Drop::Truncated => "truncated",
            Drop::Unauthenticated => "unauthenticated",
            Drop::Foreign => "foreign",
            Drop::Invalid => "invalid",
            Drop::Stale => "stale",
        }
    }
}

/// A frame whose layout checked out (sizes agree); its content is not yet trusted.
#[derive(Clone, Debug)]
pub struct Frame<'a> {
    pub flags: u8,
    pub model: [u8; 16],
    pub version: u32,
    pub layout: [u8; 8],
    pub seq: u32,
    pub time: f64,
    pub run: u32,
    pub key_id: [u8; 8],
    /// `n` × 48 bytes of body data.
    pub bodies: &'a [u8],
    /// What the tag signs (header and bodies).
    pub signed: &'a [u8],
    pub tag: Option<&'a [u8]>,
}

impl Frame<'_> {
    pub fn body_count(&self) -> usize {
        self.bodies.len() / BODY
    }
    pub fn is_final(&self) -> bool {
        self.flags & FLAG_FINAL != 0
    }
    /// The model id as the service writes it (a hyphenated UUID).
    pub fn model_id(&self) -> String {
        uuid::Uuid::from_bytes(self.model).hyphenated().to_string()
    }
}

fn u32_at(b: &[u8], at: usize) -> u32 {
    let mut w = [0u8; 4];
    w.copy_from_slice(&b[at..at + 4]);
    u32::from_le_bytes(w)
}

fn f32_at(b: &[u8], at: usize) -> f32 {
    f32::from_bits(u32_at(b, at))
}

/// Checks a datagram's form (steps 1 to 3 of the protocol): magic, header, version, sizes.
pub fn decode(d: &[u8]) -> Result<Frame<'_>, Drop> {
    if d.len() < HEADER || &d[..4] != MAGIC || u16::from_le_bytes([d[6], d[7]]) as usize != HEADER {
        return Err(Drop::Malformed);
    }
    if d[4] != PROTOCOL {
        return Err(Drop::Version);
    }
    let flags = d[5];
    let n = u32_at(d, 48) as usize;
    let tag = if flags & FLAG_AUTH != 0 { TAG } else { 0 };
    if n == 0 || n > MAX_BODIES || d.len() != HEADER + BODY * n + tag {
        return Err(Drop::Truncated);
    }
    let mut model = [0u8; 16];
    model.copy_from_slice(&d[8..24]);
    let mut layout = [0u8; 8];
    layout.copy_from_slice(&d[28..36]);
    let mut key_id = [0u8; 8];
    key_id.copy_from_slice(&d[56..64]);
    let mut time = [0u8; 8];
    time.copy_from_slice(&d[40..48]);
    let end = HEADER + BODY * n;
    Ok(Frame {
        flags,
        model,
        version: u32_at(d, 24),
        layout,
        seq: u32_at(d, 36),
        time: f64::from_le_bytes(time),
        run: u32_at(d, 52),
        key_id,
        bodies: &d[HEADER..end],
        signed: &d[..end],
        tag: (tag > 0).then(|| &d[end..]),
    })
}

/// The id frames name a key by: the first 8 bytes of SHA-256 of the key (the key being SHA-256
/// of the token, what the store keeps of it).
pub fn key_id(key: &[u8; 32]) -> [u8; 8] {
    let id = Sha256::digest(key);
    let mut out = [0u8; 8];
    out.copy_from_slice(&id[..8]);
    out
}

/// Whether the frame's tag is the HMAC-SHA256 of its signed bytes under `key` (constant time).
pub fn verify(f: &Frame<'_>, key: &[u8; 32]) -> bool {
    let Some(tag) = f.tag else { return false };
    let Ok(mut mac) = Hmac::<Sha256>::new_from_slice(key) else { return false };
    mac.update(f.signed);
    mac.verify_slice(tag).is_ok()
}

/// The poses of a frame's bodies, 7 f32 each (position; quaternion x y z w of frame_a to world,
/// re-orthonormalised as for result files), appended to `out`. `Invalid` for a number that is not
/// finite or a rotation that is not one (residual above 1e-3).
pub fn poses_into(f: &Frame<'_>, out: &mut Vec<f32>) -> Result<(), Drop> {
    for b in f.bodies.chunks_exact(BODY) {
        let v: [f32; 12] = std::array::from_fn(|k| f32_at(b, 4 * k));
        if v.iter().any(|x| !x.is_finite()) {
            return Err(Drop::Invalid);
        }
        let r = Vector3::new(v[0], v[1], v[2]).cast::<f64>();
        let t = Matrix3::from_fn(|i, j| f64::from(v[3 + 3 * i + j]));
        let (pose, residual) = crate::results::poses::pose_of(r, t);
        if residual > 1e-3 || t.determinant() <= 0.0 {
            return Err(Drop::Invalid);
        }
        let (p, q) = (pose.translation.vector, pose.rotation);
        out.extend([p.x, p.y, p.z, q.i, q.j, q.k, q.w].map(|x| x as f32));
    }
    Ok(())
}

/// What a frame says of itself, for [`encode`].
#[derive(Clone, Copy, Debug, Default)]
pub struct Header {
    pub model: [u8; 16],
    pub version: u32,
    pub layout: [u8; 8],
    pub run: u32,
    pub seq: u32,
    pub time: f64,
    pub last: bool,
}

/// A frame as the C sender writes it (for tests, benchmarks and the fuzz seeds): `bodies` holds
/// r_0 and R.T row by row (12 per body); with `token`, signed.
pub fn encode(h: &Header, bodies: &[[f64; 12]], token: Option<&str>) -> Vec<u8> {
    let Header { model, version, layout, run, seq, time, last } = *h;
    let mut d = Vec::with_capacity(HEADER + BODY * bodies.len() + TAG);
    d.extend_from_slice(MAGIC);
    d.push(PROTOCOL);
    d.push(u8::from(token.is_some()) | if last { FLAG_FINAL } else { 0 });
    d.extend_from_slice(&(HEADER as u16).to_le_bytes());
    d.extend_from_slice(&model);
    d.extend_from_slice(&version.to_le_bytes());
    d.extend_from_slice(&layout);
    d.extend_from_slice(&seq.to_le_bytes());
    d.extend_from_slice(&time.to_le_bytes());
    d.extend_from_slice(&(bodies.len() as u32).to_le_bytes());
    d.extend_from_slice(&run.to_le_bytes());
    let key: Option<[u8; 32]> = token.map(|t| Sha256::digest(t.as_bytes()).into());
    match key {
        Some(k) => d.extend_from_slice(&key_id(&k)),
        None => d.extend_from_slice(&[0u8; 8]),
    }
    for b in bodies {
        for x in b {
            d.extend_from_slice(&(*x as f32).to_le_bytes());
        }
    }
    if let Some(k) = key {
        if let Ok(mut mac) = Hmac::<Sha256>::new_from_slice(&k) {
            mac.update(&d);
            d.extend_from_slice(&mac.finalize().into_bytes());
        }
    }
    d
}

/// What the relay knows of one run of a simulation (the frames of one `run` id of a version).
#[derive(Clone, Debug, Default, Serialize)]
pub struct RunStats {
    pub run: u32,
    /// Frames relayed.
    pub frames: u64,
    /// Frames missing between relayed ones (sequence gaps).
    pub lost: u64,
    /// Frames dropped as not newer than the last relayed (reordered, duplicated, replayed).
    pub stale: u64,
    /// Simulated time of the newest frame.
    pub time: f64,
    /// Frames relayed per second of wall-clock time, over the last second or so.
    pub rate_hz: f64,
    /// Simulated seconds per wall-clock second, over the same window.
    pub realtime_factor: f64,
    /// The sender said this was its last frame.
    pub ended: bool,
    #[serde(skip)]
    last_seq: u32,
    /// Window start: (wall-clock s, frames relayed, simulated time).
    #[serde(skip)]
    window: (f64, u64, f64),
}

/// What a run's new frame means.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Accept {
    /// Relay it; `lost` frames were skipped before it.
    Newer { lost: u32 },
    /// Drop it: not newer than the last relayed.
    Stale,
}

impl RunStats {
    pub fn new(run: u32) -> RunStats {
        RunStats { run, ..RunStats::default() }
    }

    /// Takes frame `seq` at simulated `time`, seen at wall-clock `now` (s, any origin).
    /// Sequence numbers are compared modulo 2³² (newer when less than 2³¹ ahead).
    pub fn accept(&mut self, seq: u32, time: f64, last: bool, now: f64) -> Accept {
        if self.frames > 0 {
            let ahead = seq.wrapping_sub(self.last_seq);
            if ahead == 0 || ahead >= 1 << 31 {
                self.stale += 1;
                return Accept::Stale;
            }
            let lost = ahead - 1;
            self.lost += u64::from(lost);
            self.note(seq, time, last, now);
            return Accept::Newer { lost };
        }
        self.window = (now, 0, time);
        self.note(seq, time, last, now);
        Accept::Newer { lost: 0 }
    }

    fn note(&mut self, seq: u32, time: f64, last: bool, now: f64) {
        self.last_seq = seq;
        self.frames += 1;
        self.time = time;
        self.ended |= last;
        let (t0, n0, s0) = self.window;
        let dt = now - t0;
        if dt >= 1.0 {
            self.rate_hz = (self.frames - n0) as f64 / dt;
            self.realtime_factor = (time - s0) / dt;
            self.window = (now, self.frames, time);
        } else if self.rate_hz == 0.0 && dt > 0.2 && self.frames - n0 > 1 {
            // The first estimate, before a whole second has passed.
            self.rate_hz = (self.frames - n0) as f64 / dt;
            self.realtime_factor = (time - s0) / dt;
        }
    }
}

#[cfg(test)]
mod tests;
