// Pure helpers of the Results tab (unit-tested, no DOM): the binary pose stream of a result,
// body poses between its steps (position lerped, quaternion slerped), a signal's value at a
// time, and the CSV of the plotted signals (the playback clock is the dock player's, player-data.js).

const MAGIC = 'C2MP';

/**
 * Parses GET /api/results/{id}/poses: "C2MP", u32 version 1, u32 bodies B, u32 steps N, then
 * per step f32 time and B × 7 f32 (x, y, z, qx, qy, qz, qw), little-endian.
 * @param {ArrayBuffer} buffer
 * @param {string[]} bodies  Result.bodies, the stream's body order
 * @returns {{bodies: string[], times: Float64Array, poses: Float32Array}}  poses: N × B × 7
 */
export function parsePoses(buffer, bodies = []) {
  const view = new DataView(buffer);
  if (buffer.byteLength < 16) throw new Error(`the pose stream is ${buffer.byteLength} bytes, shorter than its header`);
  const magic = String.fromCharCode(view.getUint8(0), view.getUint8(1), view.getUint8(2), view.getUint8(3));
  if (magic !== MAGIC) throw new Error(`the pose stream starts with "${magic}", not "${MAGIC}"`);
  const version = view.getUint32(4, true);
  if (version !== 1) throw new Error(`pose stream version ${version} is not supported (1 is)`);
  const b = view.getUint32(8, true);
  const n = view.getUint32(12, true);
  const stride = 1 + 7 * b;
  const need = 16 + 4 * stride * n;
  if (buffer.byteLength < need) throw new Error(`the pose stream is truncated: ${buffer.byteLength} of ${need} bytes`);
  if (bodies.length && bodies.length !== b) throw new Error(`the pose stream has ${b} bodies, the result lists ${bodies.length}`);
  const times = new Float64Array(n);
  const poses = new Float32Array(n * b * 7);
  let at = 16;
  for (let i = 0; i < n; i++) {
    times[i] = view.getFloat32(at, true);
    at += 4;
    const o = i * b * 7;
    for (let k = 0; k < b * 7; k++, at += 4) poses[o + k] = view.getFloat32(at, true);
  }
  return { bodies: bodies.length ? bodies : Array.from({ length: b }, (_, i) => `body ${i + 1}`), times, poses };
}

/**
 * Where `t` falls in ascending `times`: {i, a} with t ≈ times[i] + a·(times[i+1] − times[i]),
 * a in [0, 1]; clamped at the ends. Repeated instants (events) take the later sample.
 */
export function bracket(times, t) {
  const n = times.length;
  if (n === 0) return { i: -1, a: 0 };
  if (n === 1 || !(t > times[0])) return { i: 0, a: 0 };
  if (t >= times[n - 1]) return { i: n - 1, a: 0 };
  let lo = 0;
  let hi = n - 1; // times[lo] <= t < times[hi]
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (times[mid] <= t) lo = mid;
    else hi = mid;
  }
  const span = times[hi] - times[lo];
  return { i: lo, a: span > 0 ? (t - times[lo]) / span : 0 };
}

/**
 * Every body's pose at time `t`: Float64Array B × 7 (position, then unit quaternion x, y, z, w).
 * @param {{times: Float64Array, poses: Float32Array, bodies: string[]}} stream
 */
export function posesAt(stream, t, out = new Float64Array(stream.bodies.length * 7)) {
  const b = stream.bodies.length;
  const { i, a } = bracket(stream.times, t);
  if (i < 0) return out;
  const p = stream.poses;
  const o0 = i * b * 7;
  const o1 = a > 0 ? (i + 1) * b * 7 : o0;
  for (let k = 0; k < b; k++) {
    const s = o0 + k * 7;
    const e = o1 + k * 7;
    const d = k * 7;
    for (let c = 0; c < 3; c++) out[d + c] = p[s + c] + a * (p[e + c] - p[s + c]);
    slerp(p, s + 3, p, e + 3, a, out, d + 3);
  }
  return out;
}

/**
 * Spherical interpolation of unit quaternions (x, y, z, w) a[ao..] → b[bo..] by `t`, the short
 * way round, written to out[oo..] normalised (the stream's f32 quaternions are not exactly unit).
 */
export function slerp(a, ao, b, bo, t, out, oo = 0) {
  let ax = a[ao], ay = a[ao + 1], az = a[ao + 2], aw = a[ao + 3];
  let bx = b[bo], by = b[bo + 1], bz = b[bo + 2], bw = b[bo + 3];
  let dot = ax * bx + ay * by + az * bz + aw * bw;
  if (dot < 0) {
    bx = -bx; by = -by; bz = -bz; bw = -bw;
    dot = -dot;
  }
  let s0 = 1 - t;
  let s1 = t;
  if (dot < 0.9995) {
    const theta = Math.acos(Math.min(1, dot));
    const sin = Math.sin(theta);
    s0 = Math.sin((1 - t) * theta) / sin;
    s1 = Math.sin(t * theta) / sin;
  }
  let x = s0 * ax + s1 * bx;
  let y = s0 * ay + s1 * by;
  let z = s0 * az + s1 * bz;
  let w = s0 * aw + s1 * bw;
  const len = Math.hypot(x, y, z, w) || 1;
  out[oo] = x / len;
  out[oo + 1] = y / len;
  out[oo + 2] = z / len;
  out[oo + 3] = w / len;
  return out;
}

/** A signal's value at time `t`, linear between its samples (null outside its span or with no data). */
export function valueAt(series, t) {
  const { t: ts, y } = series;
  if (!ts?.length || t < ts[0] - 1e-12 || t > ts[ts.length - 1] + 1e-12) return null;
  const { i, a } = bracket(ts, t);
  const y0 = y[i];
  if (a === 0 || i + 1 >= ts.length) return y0;
  return y0 + a * (y[i + 1] - y0);
}

function csvField(s) {
  const text = String(s);
  return /[",\n\r]/.test(text) ? `"${text.replace(/"/g, '""')}"` : text;
}

const num = (x) => (x === null || x === undefined || Number.isNaN(x) ? '' : String(x));

/**
 * CSV of signals [{name, unit, t, y}]: one time column when they share their instants,
 * otherwise the union of instants with each signal's value where it has a sample there (never
 * interpolated). Names are quoted when they hold commas (R.T[1,1]).
 */
export function signalsCsv(signals) {
  const head = (s) => csvField(s.unit && s.unit !== '1' ? `${s.name} [${s.unit}]` : s.name);
  const lines = [['time [s]', ...signals.map(head)].join(',')];
  if (!signals.length) return lines[0] + '\n';
  const same = signals.every((s) => s.t.length === signals[0].t.length && s.t.every((x, i) => x === signals[0].t[i]));
  if (same) {
    const t = signals[0].t;
    for (let i = 0; i < t.length; i++) lines.push([num(t[i]), ...signals.map((s) => num(s.y[i]))].join(','));
    return lines.join('\n') + '\n';
  }
  // Merge: walk every signal's instants in time order; repeated instants (events) stay apart.
  const at = signals.map(() => 0);
  for (;;) {
    let t = Infinity;
    signals.forEach((s, k) => {
      if (at[k] < s.t.length) t = Math.min(t, s.t[at[k]]);
    });
    if (t === Infinity) break;
    const row = [num(t)];
    signals.forEach((s, k) => {
      if (at[k] < s.t.length && s.t[at[k]] === t) {
        row.push(num(s.y[at[k]]));
        at[k] += 1;
      } else row.push('');
    });
    lines.push(row.join(','));
  }
  return lines.join('\n') + '\n';
}

/** A file name for the CSV of result `name` (its extension replaced). */
export function csvName(name) {
  const base = String(name || 'result').replace(/\.mat$/i, '').replace(/[^\w.+-]+/g, '_') || 'result';
  return `${base}-signals.csv`;
}

/**
 * The joint coordinates of the model (revolute and prismatic elements of tree joints, by their
 * Modelica names) that a result does not hold: why a result with some joint angles animates
 * fewer bodies than it has.
 * @param {object} report  the conversion report
 * @param {string[]} found the result's joints_found
 */
export function missingJoints(report, found) {
  const have = new Set(found || []);
  const out = [];
  for (const j of report?.joints || []) {
    if (!j.in_tree) continue;
    for (const e of j.elements || []) {
      if (e.kind !== 'revolute' && e.kind !== 'prismatic') continue;
      const name = e.modelica_name || j.modelica_name;
      if (!have.has(name) && !have.has(j.modelica_name)) out.push(name);
    }
  }
  return out;
}
