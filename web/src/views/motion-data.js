// The motion editor's pure parts (no DOM, no three.js scene): sampling a trajectory at a time,
// units for display, the keyframes a problem document blames, throttling live IK, the drive an
// alternative from the sizing becomes, and the torque–speed data for the plane plot.

const DEG = 180 / Math.PI;

/** Display scale of a joint value: degrees for rad, millimetres for m. */
export function displayScale(unit) {
  return unit === 'rad' ? DEG : 1000;
}

export function displayUnit(unit) {
  return unit === 'rad' ? '°' : 'mm';
}

/** Joint values at time t (s) by linear interpolation of the samples, clamped to the ends. */
export function sampleAt(traj, t) {
  const ts = traj.t;
  const out = {};
  if (!ts.length) return out;
  let i;
  let f;
  if (t <= ts[0]) {
    i = 0;
    f = 0;
  } else if (t >= ts[ts.length - 1]) {
    i = ts.length - 1;
    f = 0;
  } else {
    // Binary search for the last sample at or before t.
    let lo = 0;
    let hi = ts.length - 1;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (ts[mid] <= t) lo = mid;
      else hi = mid;
    }
    i = lo;
    f = (t - ts[lo]) / (ts[hi] - ts[lo] || 1);
  }
  traj.joints.forEach((name, k) => {
    const q = traj.q[k];
    out[name] = f === 0 || i + 1 >= q.length ? q[i] : q[i] + f * (q[i + 1] - q[i]);
  });
  return out;
}

/** The index of the sample nearest to t in an ascending array. */
export function nearestIndex(ts, t) {
  if (!ts.length) return -1;
  let lo = 0;
  let hi = ts.length - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (ts[mid] <= t) lo = mid;
    else hi = mid;
  }
  return Math.abs(ts[hi] - t) < Math.abs(ts[lo] - t) ? hi : lo;
}

/**
 * The messages a problem document attaches to keyframes: Map index → [message]. Field errors
 * like `keyframes[2]` (or `keyframes[2].position`) count; without them a detail starting with
 * "keyframe 2:" does.
 */
export function keyframeProblems(problem) {
  const out = new Map();
  const add = (k, m) => {
    if (!out.has(k)) out.set(k, []);
    if (!out.get(k).includes(m)) out.get(k).push(m);
  };
  for (const e of problem?.errors || []) {
    const m = /^keyframes\[(\d+)\]/.exec(e.field || '');
    if (m) add(Number(m[1]), e.message || problem.detail || 'invalid');
  }
  if (!out.size && problem?.detail) {
    const m = /^keyframe (\d+):\s*(.*)$/s.exec(problem.detail);
    if (m) add(Number(m[1]), m[2]);
  }
  return out;
}

/**
 * Calls `fn` at most once per `ms`, always with the latest arguments, never with two calls
 * in flight (`fn` may return a promise): the last call made is always delivered.
 */
export function throttle(fn, ms, { now = () => Date.now(), later = (f, d) => setTimeout(f, d) } = {}) {
  let last = -Infinity;
  let pending = null; // latest args not yet delivered
  let busy = false;
  let timer = false;
  const run = async () => {
    timer = false;
    if (busy || !pending) return;
    const wait = last + ms - now();
    if (wait > 0) {
      timer = true;
      later(run, wait);
      return;
    }
    const args = pending;
    pending = null;
    busy = true;
    last = now();
    try {
      await fn(...args);
    } finally {
      busy = false;
      if (pending && !timer) run();
    }
  };
  const call = (...args) => {
    pending = args;
    if (!busy && !timer) run();
  };
  call.flush = () => (pending ? run() : undefined);
  return call;
}

/**
 * The PUT body of the drives API that applies a sizing alternative to an existing drive: the
 * alternative's motor and gear, the same controller (and its overrides) and reference. Ranked
 * alternatives are real catalogue combinations at the gear's own ratio, so no ratio override is
 * needed; one is set only if an alternative's ratio differs from the gear's own (`gearRatio`).
 */
export function applyAlternative(drive, alt, gearRatio) {
  const overrides = {};
  if (drive?.overrides?.controller) overrides.controller = { ...drive.overrides.controller };
  // An override only where the gear's own ratio differs (fixed-ratio gears refuse overrides).
  if (alt.ratio !== null && alt.ratio !== undefined && alt.ratio !== gearRatio) overrides.gear = { ratio: alt.ratio };
  const body = {
    motor_instance: alt.motor.id,
    gear_instance: alt.gear.id,
    controller_instance: drive.controller_instance,
    overrides,
  };
  if (drive.reference) body.reference = drive.reference;
  return body;
}

/**
 * uPlot data for the torque–speed plane: x = motor speed, ascending (uPlot needs a sorted x),
 * series 1 the operating points' torque, then ±continuous and ±peak torque lines over the
 * plot's speed span; `order[i]` is the operating point shown at x index i.
 */
export function torqueSpeedData(op, envelope) {
  const n = Math.min(op.speed.length, op.torque.length);
  const order = Array.from({ length: n }, (_, i) => i).sort((a, b) => op.speed[a] - op.speed[b]);
  let xs = order.map((i) => op.speed[i]);
  let ys = order.map((i) => op.torque[i]);
  // Stretch the speed axis to show the max speed lines; the extra ends carry no point.
  const vmax = Math.max(envelope?.max_speed || 0, envelope?.no_load_speed || 0, ...xs.map(Math.abs), 1e-9);
  const span = vmax * 1.1;
  xs = [-span, ...xs, span];
  ys = [null, ...ys, null];
  const line = (v) => xs.map(() => (v === null || v === undefined ? null : v));
  return {
    order,
    data: [xs, ys, line(envelope?.continuous_torque), line(envelope?.continuous_torque == null ? null : -envelope.continuous_torque), line(envelope?.peak_torque), line(envelope?.peak_torque == null ? null : -envelope.peak_torque)],
  };
}

/** A row-major 3×3 rotation of a column-major three.js Matrix4's elements. */
export function rotationRows(e) {
  return [
    [e[0], e[4], e[8]],
    [e[1], e[5], e[9]],
    [e[2], e[6], e[10]],
  ];
}

/** A fresh name not in `taken`: base, base 2, base 3… */
export function freshName(base, taken) {
  const set = new Set(taken);
  if (!set.has(base)) return base;
  for (let i = 2; ; i++) if (!set.has(`${base} ${i}`)) return `${base} ${i}`;
}

/**
 * How many movable joint coordinates lie between the ground and each body (tree joints of the
 * report): the tool frame is likely on the deepest body.
 */
export function bodyDepths(report) {
  const bodies = new Set(report.bodies.map((b) => b.modelica_name));
  const adj = new Map();
  const link = (a, b, w) => {
    if (!adj.has(a)) adj.set(a, []);
    adj.get(a).push([b, w]);
  };
  const grounds = new Set();
  for (const j of report.joints) {
    for (const n of [j.base_body, j.follower_body]) if (!bodies.has(n)) grounds.add(n);
    if (!j.in_tree) continue;
    const w = j.elements.filter((e) => e.kind === 'revolute' || e.kind === 'prismatic').length;
    link(j.base_body, j.follower_body, w);
    link(j.follower_body, j.base_body, w);
  }
  const depth = new Map();
  const queue = [...grounds];
  for (const g of grounds) depth.set(g, 0);
  while (queue.length) {
    const u = queue.shift();
    for (const [v, w] of adj.get(u) || []) {
      if (depth.has(v)) continue;
      depth.set(v, depth.get(u) + w);
      queue.push(v);
    }
  }
  return depth;
}

/** The frame a tool most likely is: on the deepest body; a user's frame before CG before CSn. */
export function defaultToolFrame(frames, depths) {
  const rank = (f) => (/^CS\d+$/.test(f.name) ? 0 : f.name === 'CG' ? 1 : 2);
  let best = null;
  for (const f of frames) {
    const d = depths.get(f.body) ?? -1;
    if (!best || d > best.d || (d === best.d && rank(f) > best.r)) best = { f, d, r: rank(f) };
  }
  return best?.f || null;
}

/**
 * Tick labels for an axis whose ticks are `splits`: decimals enough to tell neighbouring ticks
 * apart (0.0002, 0.0004 rather than 0, 0), exponent notation for very small or large spans.
 */
export function tickLabels(splits) {
  const vs = splits.filter((v) => v !== null && Number.isFinite(v));
  let step = Infinity;
  for (let i = 1; i < vs.length; i++) {
    const d = Math.abs(vs[i] - vs[i - 1]);
    if (d > 0) step = Math.min(step, d);
  }
  const big = Math.max(0, ...vs.map(Math.abs));
  if (!Number.isFinite(step)) step = big || 1;
  const exp = step < 1e-4 || big >= 1e6;
  const decimals = Math.min(12, Math.max(0, Math.ceil(-Math.log10(step) - 1e-9)));
  return splits.map((v) => {
    if (v === null || !Number.isFinite(v)) return '';
    if (v === 0 || Math.abs(v) < step * 1e-6) return '0';
    if (exp) {
      const digits = Math.min(6, Math.max(1, Math.ceil(Math.log10(Math.abs(v) / step) + 1e-9)));
      return v.toExponential(digits - 1).replace('e+', 'e');
    }
    return v.toFixed(decimals);
  });
}
