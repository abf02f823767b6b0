// Pure helpers of the standalone Results page (unit-tested, no DOM): the binary stream of a
// result's Dymola visual shapes and frames, its state between steps, and where a shape's unit
// primitive goes in the world (MSL Visualizers.Advanced.Shape: origin r, length axis rx, width
// axis ry, size length × width × height).

import { bracket, slerp } from './results-data.js';

const MAGIC = 'C2MS';
export const SHAPE_FLOATS = 12; // r, rx, ry, size
export const FRAME_FLOATS = 7; // position, quaternion x, y, z, w

/**
 * Parses GET /api/results/{id}/shape-poses: "C2MS", u32 version 1, u32 shapes S, u32 frames F,
 * u32 steps N, then per step f32 time, S × 12 f32, F × 7 f32, little-endian.
 * @returns {{shapes: number, frames: number, times: Float64Array, data: Float32Array, stride: number}}
 *   data: N × stride floats (the step's time left out), stride = 12 S + 7 F
 */
export function parseShapePoses(buffer) {
  const view = new DataView(buffer);
  if (buffer.byteLength < 20) throw new Error(`the shape stream is ${buffer.byteLength} bytes, shorter than its header`);
  const magic = String.fromCharCode(view.getUint8(0), view.getUint8(1), view.getUint8(2), view.getUint8(3));
  if (magic !== MAGIC) throw new Error(`the shape stream starts with "${magic}", not "${MAGIC}"`);
  const version = view.getUint32(4, true);
  if (version !== 1) throw new Error(`shape stream version ${version} is not supported (1 is)`);
  const shapes = view.getUint32(8, true);
  const frames = view.getUint32(12, true);
  const n = view.getUint32(16, true);
  const stride = SHAPE_FLOATS * shapes + FRAME_FLOATS * frames;
  const need = 20 + 4 * (1 + stride) * n;
  if (buffer.byteLength < need) throw new Error(`the shape stream is truncated: ${buffer.byteLength} of ${need} bytes`);
  const times = new Float64Array(n);
  const data = new Float32Array(n * stride);
  let at = 20;
  for (let i = 0; i < n; i++) {
    times[i] = view.getFloat32(at, true);
    at += 4;
    const o = i * stride;
    for (let k = 0; k < stride; k++, at += 4) data[o + k] = view.getFloat32(at, true);
  }
  return { shapes, frames, times, data, stride };
}

/**
 * The stream's state at time `t`: shapes' 12 values lerped (the axes are normalised later),
 * frames' positions lerped and quaternions slerped. Float64Array of `stride` values.
 */
export function shapesAt(stream, t, out = new Float64Array(stream.stride)) {
  const { i, a } = bracket(stream.times, t);
  if (i < 0) return out;
  const d = stream.data;
  const o0 = i * stream.stride;
  const o1 = a > 0 ? (i + 1) * stream.stride : o0;
  const nShape = SHAPE_FLOATS * stream.shapes;
  for (let k = 0; k < nShape; k++) out[k] = d[o0 + k] + a * (d[o1 + k] - d[o0 + k]);
  for (let f = 0; f < stream.frames; f++) {
    const s = nShape + f * FRAME_FLOATS;
    for (let c = 0; c < 3; c++) out[s + c] = d[o0 + s + c] + a * (d[o1 + s + c] - d[o0 + s + c]);
    slerp(d, o0 + s + 3, d, o1 + s + 3, a, out, s + 3);
  }
  return out;
}

const norm = (v) => {
  const l = Math.hypot(v[0], v[1], v[2]);
  return l > 1e-12 ? [v[0] / l, v[1] / l, v[2] / l] : null;
};
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/**
 * The shape's axes: ex = rx normalised, ey = ry made perpendicular to ex and normalised,
 * ez = ex × ey. Degenerate inputs fall back to world axes (a zero rx to x; an ry along rx to the
 * world axis least along ex).
 */
export function shapeAxes(rx, ry) {
  const ex = norm(rx) || [1, 0, 0];
  const d = dot(ry, ex);
  let ey = norm([ry[0] - d * ex[0], ry[1] - d * ex[1], ry[2] - d * ex[2]]);
  if (!ey) {
    const ax = Math.abs(ex[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
    const e = dot(ax, ex);
    ey = norm([ax[0] - e * ex[0], ax[1] - e * ex[1], ax[2] - e * ex[2]]);
  }
  return { ex, ey, ez: cross(ex, ey) };
}

/**
 * The column-major 4×4 that places the unit primitive of `kind` in the world. The unit
 * primitives run along their x axis from 0 to 1: a box 1 × 1 × 1 centred in y and z; a cylinder
 * and a cone (base at x = 0, tip at x = 1) of diameter 1; a sphere of diameter 1 centred at x =
 * 0.5. Scales: box, file and other (length, width, height); cylinder, pipecylinder and cone
 * (length, width, width); sphere (length, length, length); file-raw (a file drawn from the
 * user's file with MSL's extra = 0: its coordinates unscaled, only placed and turned).
 * @param {ArrayLike<number>} v  12 values: r, rx, ry, size
 */
export function shapeMatrix(kind, v, o = 0, out = new Array(16)) {
  const r = [v[o], v[o + 1], v[o + 2]];
  const { ex, ey, ez } = shapeAxes([v[o + 3], v[o + 4], v[o + 5]], [v[o + 6], v[o + 7], v[o + 8]]);
  const [l, w, hgt] = [v[o + 9], v[o + 10], v[o + 11]];
  let s;
  if (kind === 'sphere') s = [l, l, l];
  else if (kind === 'file-raw') s = [1, 1, 1];
  else if (kind === 'cylinder' || kind === 'pipecylinder' || kind === 'cone') s = [l, w, w];
  else s = [l, w, hgt];
  const cols = [ex, ey, ez];
  for (let c = 0; c < 3; c++) {
    for (let i = 0; i < 3; i++) out[c * 4 + i] = cols[c][i] * s[c];
    out[c * 4 + 3] = 0;
  }
  out[12] = r[0];
  out[13] = r[1];
  out[14] = r[2];
  out[15] = 1;
  return out;
}

/** The last path element of a component name, for labels ("a.b.shape" → "shape"). */
export function shortName(name) {
  const parts = String(name).split('.');
  return parts.length > 1 ? parts.slice(-2).join('.') : name;
}

/**
 * The world box everything in the stream occupies over the whole result (the shapes' origins and
 * far ends, grown by their largest size; the frames' origins), from at most `samples` steps:
 * the 3D view frames it once, so moving shapes stay in sight.
 * @returns {{min: number[], max: number[]} | null}  null for an empty stream
 */
export function streamBounds(stream, samples = 200) {
  const n = stream.times.length;
  if (!n || stream.shapes + stream.frames === 0) return null;
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  const grow = (p, pad) => {
    for (let c = 0; c < 3; c++) {
      if (!Number.isFinite(p[c])) return;
    }
    for (let c = 0; c < 3; c++) {
      min[c] = Math.min(min[c], p[c] - pad);
      max[c] = Math.max(max[c], p[c] + pad);
    }
  };
  const every = Math.max(1, Math.floor(n / samples));
  for (let i = 0; ; i = Math.min(i + every, n - 1)) {
    const o = i * stream.stride;
    const d = stream.data;
    for (let k = 0; k < stream.shapes; k++) {
      const s = o + SHAPE_FLOATS * k;
      const r = [d[s], d[s + 1], d[s + 2]];
      const { ex } = shapeAxes([d[s + 3], d[s + 4], d[s + 5]], [d[s + 6], d[s + 7], d[s + 8]]);
      const l = d[s + 9];
      const pad = Math.max(Math.abs(d[s + 10]), Math.abs(d[s + 11])) / 2;
      grow(r, pad);
      grow([r[0] + ex[0] * l, r[1] + ex[1] * l, r[2] + ex[2] * l], pad);
    }
    for (let f = 0; f < stream.frames; f++) {
      const s = o + SHAPE_FLOATS * stream.shapes + FRAME_FLOATS * f;
      grow([d[s], d[s + 1], d[s + 2]], 0);
    }
    if (i === n - 1) break;
  }
  return min[0] === Infinity ? null : { min, max };
}

/** The file name of a file shape's path (quotes and brackets of its description left out). */
export function fileLabel(path) {
  const name = String(path).replace(/["'\])\s]+$/, '').split(/[\\/]/).pop();
  return name.replace(/^["'[(\s]+/, '') || String(path);
}

/**
 * Which file shapes the user's files draw: a file matches every file shape whose path names the
 * same file, by name without extension and case (b0.dxf or B0.STL for …/RobotR3/b0.dxf).
 * @param {{kind: string, file?: string}[]} shapes  the result's shapes (GET …/shapes)
 * @param {string[]} names  the chosen files' names
 * @returns {{used: Map<string, number[]>, unused: string[], missing: string[]}}
 *   used: file name → indices of the shapes it draws; unused: files no shape names; missing:
 *   the file labels of file shapes still without a file (each once)
 */
export function matchShapeFiles(shapes, names) {
  const stem = (p) => String(p).split(/[\\/]/).pop().replace(/\.[^.]*$/, '').toLowerCase();
  const used = new Map();
  const unused = [];
  const covered = new Set();
  for (const n of names) {
    const idx = [];
    shapes.forEach((s, k) => {
      if (s.kind === 'file' && s.file && stem(fileLabel(s.file)) === stem(n)) idx.push(k);
    });
    if (idx.length) {
      used.set(n, idx);
      idx.forEach((k) => covered.add(k));
    } else unused.push(n);
  }
  const missing = [...new Set(shapes.filter((s, k) => s.kind === 'file' && s.file && !covered.has(k)).map((s) => fileLabel(s.file)))];
  return { used, unused, missing };
}
