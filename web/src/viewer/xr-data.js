// WebXR immersive view: the pure parts. Whether this browser offers an immersive VR session
// (the "Enter VR" button is enabled only then, else disabled with the reason as its tooltip),
// and where the model stands in the headset's space (true size, upright, on the floor in front
// of the user). No three.js here: plain arrays, tested with node --test.

/** How long a browser may take to answer isSessionSupported before we say it did not. */
export const SUPPORT_TIMEOUT_MS = 5000;

/**
 * Whether an immersive VR session can be requested: `{supported: true, reason: ''}` or
 * `{supported: false, reason}` with a sentence for the button's tooltip.
 * @param {{xr?: {isSessionSupported?: (mode: string) => Promise<boolean>}} | undefined} nav  navigator
 * @param {boolean} secure  window.isSecureContext (WebXR exists only on HTTPS pages and localhost)
 * @param {number} [timeoutMs]
 */
export async function immersiveSupport(nav, secure, timeoutMs = SUPPORT_TIMEOUT_MS) {
  if (!secure) return { supported: false, reason: 'VR needs a secure page: open the service over HTTPS (or on localhost) to use WebXR' };
  const xr = nav?.xr;
  if (!xr || typeof xr.isSessionSupported !== 'function') {
    return { supported: false, reason: 'This browser has no WebXR (navigator.xr): open the page in a WebXR browser with a VR headset to view the model in VR' };
  }
  let timer;
  const late = new Promise((resolve) => {
    timer = setTimeout(() => resolve('timeout'), timeoutMs);
  });
  try {
    const answer = await Promise.race([Promise.resolve().then(() => xr.isSessionSupported('immersive-vr')), late]);
    if (answer === 'timeout') return { supported: false, reason: `The browser did not say within ${timeoutMs / 1000} s whether immersive VR works` };
    if (answer === true) return { supported: true, reason: '' };
    return { supported: false, reason: 'This browser has WebXR but no immersive VR device: connect a headset (or start its runtime) and reload' };
  } catch (e) {
    return { supported: false, reason: `WebXR refused to say whether immersive VR works: ${e?.message || e}` };
  } finally {
    clearTimeout(timer);
  }
}

const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const unit = (a) => {
  const n = Math.hypot(...a);
  return n > 0 ? a.map((x) => x / n) : [0, 0, 1];
};

/** The unit quaternion [x, y, z, w] turning unit vector `a` onto unit vector `b`. */
export function quaternionBetween(a, b) {
  const d = dot(a, b);
  if (d < -1 + 1e-12) {
    // Opposite: half a turn about any axis at right angles to a.
    const axis = unit(Math.abs(a[0]) < 0.9 ? cross(a, [1, 0, 0]) : cross(a, [0, 1, 0]));
    return [...axis, 0];
  }
  const c = cross(a, b);
  const q = [c[0], c[1], c[2], 1 + d];
  const n = Math.hypot(...q);
  return q.map((x) => x / n);
}

/** Rotates vector v by unit quaternion q. */
export function rotate(q, v) {
  const [x, y, z, w] = q;
  const u = [x, y, z];
  const t = cross(u, v).map((c) => 2 * c);
  const ut = cross(u, t);
  return [v[0] + w * t[0] + ut[0], v[1] + w * t[1] + ut[1], v[2] + w * t[2] + ut[2]];
}

/**
 * Where the model stands in the headset's space (WebXR: metres, +y up, the user at the origin
 * looking along -z, y = 0 the floor of a 'local-floor' space): turned so the model's `up` (the
 * report's gravity reversed) is +y, at its true size, its lowest point on the floor and its
 * centre `distance` metres plus its own radius in front of the user. `box` is the model's
 * bounding box in its world, {min: [x, y, z], max: [x, y, z]}. Returns {quaternion, position}
 * for the scene's root (applied as p' = q·p + position).
 */
export function xrPlacement(up, box, distance = 1.0) {
  const q = quaternionBetween(unit(up), [0, 1, 0]);
  const corners = [];
  for (const x of [box.min[0], box.max[0]]) for (const y of [box.min[1], box.max[1]]) for (const z of [box.min[2], box.max[2]]) corners.push(rotate(q, [x, y, z]));
  const lo = [0, 1, 2].map((i) => Math.min(...corners.map((c) => c[i])));
  const hi = [0, 1, 2].map((i) => Math.max(...corners.map((c) => c[i])));
  const centre = [0, 1, 2].map((i) => (lo[i] + hi[i]) / 2);
  const radius = Math.hypot(hi[0] - lo[0], hi[2] - lo[2]) / 2;
  return { quaternion: q, position: [-centre[0], -lo[1], -centre[2] - distance - radius] };
}
