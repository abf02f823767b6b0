// Pure helpers of the Live tab (unit-tested, no DOM): the WebSocket's address and
// sub-protocols, the binary frames decoded in place into reused typed arrays, its text messages,
// which run the page follows, the frame rate received, the recording the player replays, the
// reconnection backoff and the modifier that starts a stream. The contract: docs/live-protocol.md.

/** Bytes before the poses in a relayed frame: u32 run, u32 seq, f64 time, u32 n, u32 flags. */
export const FRAME_HEADER = 24;
/** Floats per body in a relayed frame: x, y, z, qx, qy, qz, qw. */
export const POSE = 7;
/** Frame flag: the simulation's final frame. */
export const FINAL = 2;

/** The WebSocket of a model version's live view, on the page's own host (ws: or wss:). */
export function liveUrl(location, modelId, version) {
  const scheme = location.protocol === 'https:' ? 'wss:' : 'ws:';
  return `${scheme}//${location.host}/api/models/${encodeURIComponent(modelId)}/versions/${version}/live/ws`;
}

/** Sub-protocols to offer: browsers cannot set headers on a WebSocket, so the token rides here. */
export function liveProtocols(token) {
  return token ? ['cad2mo.live', `bearer.${token}`] : ['cad2mo.live'];
}

/** A frame to decode into; `decodeFrame` grows its pose array when a frame has more bodies. */
export function newFrame(n = 0) {
  return { run: 0, seq: 0, time: 0, n: 0, flags: 0, poses: new Float64Array(n * POSE), received: 0 };
}

/**
 * Decodes a relayed binary frame into `frame` (its arrays reused): little-endian u32 run, u32
 * seq, f64 time, u32 n, u32 flags, then n × 7 f32. Returns null when the message is not a whole
 * frame (the frame is then left as it was).
 * @param {ArrayBuffer} buffer
 * @param {ReturnType<typeof newFrame>} frame
 */
export function decodeFrame(buffer, frame) {
  if (!(buffer instanceof ArrayBuffer) || buffer.byteLength < FRAME_HEADER) return null;
  const view = new DataView(buffer);
  const n = view.getUint32(16, true);
  if (buffer.byteLength !== FRAME_HEADER + 4 * POSE * n) return null;
  frame.run = view.getUint32(0, true);
  frame.seq = view.getUint32(4, true);
  frame.time = view.getFloat64(8, true);
  frame.n = n;
  frame.flags = view.getUint32(20, true);
  if (frame.poses.length < n * POSE) frame.poses = new Float64Array(n * POSE);
  const p = frame.poses;
  for (let k = 0, at = FRAME_HEADER; k < n * POSE; k++, at += 4) p[k] = view.getFloat32(at, true);
  return frame;
}

/** Copies frame `from` into `to` (arrays reused): the frame the 3D view shows. */
export function copyFrame(from, to) {
  to.run = from.run;
  to.seq = from.seq;
  to.time = from.time;
  to.n = from.n;
  to.flags = from.flags;
  to.received = from.received;
  if (to.poses.length < from.n * POSE) to.poses = new Float64Array(from.n * POSE);
  to.poses.set(from.poses.subarray(0, from.n * POSE));
  return to;
}

/** A text message of the live socket ({type: hello|stats|end, ...}), or null if it is none. */
export function parseMessage(text) {
  let m;
  try {
    m = JSON.parse(text);
  } catch {
    return null;
  }
  if (!m || typeof m !== 'object') return null;
  if (m.type === 'hello' && Array.isArray(m.bodies)) return m;
  if ((m.type === 'stats' || m.type === 'end') && Number.isFinite(m.run)) return m;
  return null;
}

/**
 * Frames received per second: the count of frames in the last `window` seconds, from a ring of
 * arrival times (no allocation per frame).
 */
export class RateMeter {
  constructor(window = 1, capacity = 512) {
    this.window = window;
    this.times = new Float64Array(capacity);
    this.head = 0; // next slot
    this.count = 0;
  }

  /** A frame arrived at `now` (seconds). */
  tick(now) {
    this.times[this.head] = now;
    this.head = (this.head + 1) % this.times.length;
    if (this.count < this.times.length) this.count += 1;
  }

  /** Frames per second over the window ending at `now`. */
  rate(now) {
    const cap = this.times.length;
    let n = 0;
    let oldest = now;
    for (let i = 1; i <= this.count; i++) {
      const t = this.times[(this.head - i + cap) % cap];
      if (now - t > this.window) break;
      n += 1;
      oldest = t;
    }
    if (n === this.count && n === cap) return n / Math.max(now - oldest, 1e-3); // the ring is too short for the window
    return n / this.window;
  }

  reset() {
    this.count = 0;
    this.head = 0;
  }
}

/**
 * The run the page follows and its numbers: the newest run (the last to start sending); frames
 * of an older run are ignored while the followed one is live, unless it fell silent for
 * `silence` seconds. Server numbers (lost, stale, rate, real-time factor) come from `stats`
 * messages of the followed run; `ended` from its `end` message.
 */
export class LiveRuns {
  constructor({ silence = 2, remember = 64 } = {}) {
    this.silence = silence;
    this.remember = remember;
    this.seen = [];
    this.reset();
  }

  reset() {
    this.run = null;
    this.frames = 0; // frames of the followed run received here
    this.time = null; // its newest simulated time
    this.lastAt = -Infinity;
    this.stats = null; // the service's last stats message of the run
    this.ended = false;
    this.endTime = null;
  }

  /** Whether a frame of `run` arriving at `now` (s) is followed; starts following a new run. */
  accept(run, now) {
    if (run !== this.run) {
      const known = this.seen.includes(run);
      const free = this.run === null || this.ended || now - this.lastAt > this.silence;
      if (known && !free) return false;
      this.reset();
      this.run = run;
      if (!known) {
        this.seen.push(run);
        if (this.seen.length > this.remember) this.seen.shift();
      }
    }
    return true;
  }

  /** A followed frame arrived. */
  frame(frame, now) {
    this.frames += 1;
    this.time = frame.time;
    this.lastAt = now;
    if (frame.flags & FINAL) {
      this.ended = true;
      this.endTime = frame.time;
    }
  }

  /** A text message: stats and end of the followed run are kept. */
  message(m) {
    if (m.type === 'stats') {
      if (this.run === null || m.run !== this.run) return false;
      this.stats = m;
      return true;
    }
    if (m.type === 'end') {
      if (m.run !== this.run) return false;
      this.ended = true;
      this.endTime = Number.isFinite(m.time) ? m.time : this.time;
      return true;
    }
    return false;
  }
}

/**
 * Milliseconds before reconnection attempt `attempt` (0, 1, ...): doubling from `base` up to
 * `max`, with up to `jitter` of it random so many pages do not come back at once.
 */
export function backoff(attempt, { base = 500, max = 10_000, jitter = 0.2, random = Math.random } = {}) {
  const d = Math.min(max, base * 2 ** Math.max(0, Math.min(attempt, 30)));
  return Math.round(d * (1 - jitter + jitter * random()));
}

/** "host:port", "[::1]:7878" → {host, port}; null when there is no port. */
export function splitHostPort(address) {
  const m = /^\[([^\]]+)\]:(\d+)$/.exec(address || '') || /^([^:]*):(\d+)$/.exec(address || '');
  return m ? { host: m[1], port: Number(m[2]) } : null;
}

/**
 * The modifier of `Mechatronics` that sends a live stream to this service: liveHost is the UDP
 * address's host (the page's host when the service listens on every interface), livePort its
 * port, liveToken only where the service requires one.
 * @param {{udp: string, auth_required: boolean}} info
 * @param {string} pageHost  location.hostname
 */
export function startModifier(info, pageHost = '127.0.0.1') {
  const a = splitHostPort(info.udp) || { host: pageHost, port: 7878 };
  const any = a.host === '0.0.0.0' || a.host === '::' || a.host === '';
  const host = any ? pageHost : a.host;
  const parts = ['liveView=true', `liveHost="${host}"`, `livePort=${a.port}`];
  if (info.auth_required) parts.push('liveToken="<an API token>"');
  return `Mechatronics(${parts.join(', ')})`;
}

/** The live view records the last RECORD_SECONDS of simulated time ... */
export const RECORD_SECONDS = 60;
/** ... in at most RECORD_BYTES (frames of many bodies keep fewer seconds). */
export const RECORD_BYTES = 64 * 1024 * 1024;

/**
 * The frames of the followed run, recorded for the player (pause, step back, replay): the last
 * `seconds` of simulated time, its arrays at most `bytes` (f32 poses, exactly as they arrived,
 * and f64 times). Frames are kept in time order in one array with the oldest dropped from its
 * front (compacted when the array's end is reached: a quarter of it stays free for that), so
 * `stream()` is contiguous and the Results tab's interpolation (results-data.js posesAt) reads it.
 */
export class FrameRecorder {
  constructor({ seconds = RECORD_SECONDS, bytes = RECORD_BYTES } = {}) {
    this.seconds = seconds;
    this.bytes = bytes;
    this.reset(0);
  }

  /** Forgets every frame (a new run, or frames of another body count). */
  reset(n = this.n) {
    this.n = n;
    const frameBytes = 8 + 4 * POSE * Math.max(n, 1);
    // The array holds `limit` frames plus a quarter more, all within `bytes`.
    this.limit = Math.max(2, Math.floor(this.bytes / frameBytes / 1.25));
    this.room = Math.max(3, Math.floor(this.limit * 1.25));
    this.cap = Math.min(this.room, 256);
    this.timesBuf = new Float64Array(this.cap);
    this.posesBuf = new Float32Array(this.cap * n * POSE);
    this.first = 0;
    this.end = 0;
    this.version = 0; // bumped by every change
  }

  get count() {
    return this.end - this.first;
  }

  /** The oldest recorded time (0 when empty). */
  get start() {
    return this.count ? this.timesBuf[this.first] : 0;
  }

  /** The newest recorded time (0 when empty). */
  get stop() {
    return this.count ? this.timesBuf[this.end - 1] : 0;
  }

  /** The recorded times, oldest first (a view: valid until the next push). */
  get times() {
    return this.timesBuf.subarray(this.first, this.end);
  }

  /** Bytes the arrays take now. */
  get size() {
    return this.timesBuf.byteLength + this.posesBuf.byteLength;
  }

  /**
   * Records a decoded frame ({time, n, poses}); false when it is not newer than the newest
   * recorded one (a frame out of order) or has no bodies. Frames of another body count start
   * a new recording.
   */
  push(frame) {
    const n = frame.n;
    if (!(n > 0) || !Number.isFinite(frame.time)) return false;
    if (n !== this.n) this.reset(n);
    if (this.count && !(frame.time > this.timesBuf[this.end - 1])) return false;
    // Older than the window, or beyond the frame limit: dropped from the front.
    const cut = frame.time - this.seconds;
    while (this.first < this.end && this.timesBuf[this.first] < cut) this.first++;
    if (this.count >= this.limit) this.first += this.count - this.limit + 1;
    if (this.end === this.cap) this.makeRoom();
    const stride = n * POSE;
    this.timesBuf[this.end] = frame.time;
    this.posesBuf.set(frame.poses.subarray(0, stride), this.end * stride);
    this.end++;
    this.version++;
    return true;
  }

  /** The array is full at its end: grow it (up to `room`) or move the frames to its front. */
  makeRoom() {
    const stride = this.n * POSE;
    const count = this.count;
    if (this.cap < this.room && count > this.cap / 2) {
      const cap = Math.min(this.room, this.cap * 2);
      const times = new Float64Array(cap);
      const poses = new Float32Array(cap * stride);
      times.set(this.timesBuf.subarray(this.first, this.end));
      poses.set(this.posesBuf.subarray(this.first * stride, this.end * stride));
      this.timesBuf = times;
      this.posesBuf = poses;
      this.cap = cap;
    } else {
      this.timesBuf.copyWithin(0, this.first, this.end);
      this.posesBuf.copyWithin(0, this.first * stride, this.end * stride);
    }
    this.first = 0;
    this.end = count;
  }

  /** The recording as a pose stream ({bodies, times, poses}) for results-data.js posesAt. */
  stream(bodies) {
    const stride = this.n * POSE;
    return { bodies, times: this.times, poses: this.posesBuf.subarray(this.first * stride, this.end * stride) };
  }
}
