// A MAT v4 trajectory file as Dymola and OpenModelica write them (Aclass 1.1, binTrans), for the
// end-to-end tests: no simulator runs here, so the results the UI animates are written by the
// test from a known motion.
//
// Each matrix: five little-endian int32 (type = P·10 + T: P 0 f64, 1 f32, 2 int32, 5 u8; T 1
// text), rows, columns, 0 (no imaginary part), name length with its NUL; the name and NUL; the
// data column-major. Matrices: Aclass (a string per row), name and description (a string per
// column, NUL-padded), dataInfo (int32 4 × n: block, 1-based column, 0, -1), data_1 (constants
// × 2 instants) and data_2 (series × instants, time first; one instant per column).

const P = { f64: 0, f32: 1, i32: 2, u8: 5 };

function matrix(chunks, name, p, text, rows, cols, data) {
  const head = new DataView(new ArrayBuffer(20));
  [p * 10 + (text ? 1 : 0), rows, cols, 0, name.length + 1].forEach((w, i) => head.setInt32(4 * i, w, true));
  chunks.push(new Uint8Array(head.buffer), new TextEncoder().encode(`${name}\0`));
  const size = { 0: 8, 1: 4, 2: 4, 5: 1 }[p];
  const body = new DataView(new ArrayBuffer(data.length * size));
  data.forEach((x, i) => {
    if (p === 0) body.setFloat64(i * size, x, true);
    else if (p === 1) body.setFloat32(i * size, x, true);
    else if (p === 2) body.setInt32(i * size, x, true);
    else body.setUint8(i, x);
  });
  chunks.push(new Uint8Array(body.buffer));
}

/** Strings as a u8 text matrix: one per column (names) or one per row (Aclass). */
function text(chunks, name, strings, perRow) {
  const bytes = strings.map((s) => new TextEncoder().encode(s));
  const len = Math.max(1, ...bytes.map((b) => b.length));
  const n = strings.length;
  const data = new Array(len * n).fill(0);
  bytes.forEach((b, k) => b.forEach((c, j) => (data[perRow ? j * n + k : k * len + j] = c)));
  if (perRow) matrix(chunks, name, P.u8, true, n, len, data);
  else matrix(chunks, name, P.u8, true, len, n, data);
}

/**
 * @param {{time: number[], series: {name: string, description?: string, values: number[]}[],
 *   constants?: {name: string, description?: string, value: number}[], precision?: 'f32'|'f64'}} o
 *   Series whose values never change are stored as constants (in data_1), as Dymola does.
 * @returns {Uint8Array}
 */
export function writeMat({ time, series, constants = [], precision = 'f32' }) {
  const cons = [...constants];
  const varying = [];
  for (const s of series) {
    if (s.values.every((v) => v === s.values[0])) cons.push({ name: s.name, description: s.description, value: s.values[0] });
    else varying.push(s);
  }
  const vars = [{ name: 'Time', description: 'Time in [s]' }, ...varying, ...cons];
  const chunks = [];
  text(chunks, 'Aclass', ['Atrajectory', '1.1', '', 'binTrans'], true);
  text(chunks, 'name', vars.map((v) => v.name), false);
  text(chunks, 'description', vars.map((v) => v.description || ''), false);
  const info = [0, 1, 0, -1];
  varying.forEach((_, k) => info.push(2, k + 2, 0, -1));
  cons.forEach((_, k) => info.push(1, k + 1, 0, -1));
  matrix(chunks, 'dataInfo', P.i32, false, 4, vars.length, info);
  // data_1: a row per constant, its value at the first and the last instant.
  const d1 = [];
  for (const c of cons) d1.push(c.value);
  for (const c of cons) d1.push(c.value);
  matrix(chunks, 'data_1', P.f64, false, cons.length, 2, d1);
  const d2 = [];
  time.forEach((t, i) => {
    d2.push(t);
    for (const s of varying) d2.push(s.values[i]);
  });
  matrix(chunks, 'data_2', P[precision], false, varying.length + 1, time.length, d2);
  const out = new Uint8Array(chunks.reduce((n, c) => n + c.length, 0));
  let at = 0;
  for (const c of chunks) {
    out.set(c, at);
    at += c.length;
  }
  return out;
}

/**
 * Dymola's pack of a visual shape's colour and specular coefficient (its `Material` variable):
 * ((⌊99r/255⌋·100 + ⌊99g/255⌋)·100 + ⌊99b/255⌋)·10 + ⌊9·specular⌋.
 */
export function packMaterial([r, g, b], specular = 0) {
  const c = (x) => Math.floor((99 * x) / 255);
  return ((c(r) * 100 + c(g)) * 100 + c(b)) * 10 + Math.floor(9 * specular);
}

/**
 * The variables Dymola writes for a visual shape (MultiBody.Visualizers.Advanced.Shape) named
 * `p`: `p.Form` = (987000 + code)·1e20, `p.rxvisobj[1..3]`, `p.ryvisobj[1..3]`, `p.rvisobj[1..3]`,
 * `p.size[1..3]`, `p.Material`. Vectors are functions of time (or constant arrays).
 * @param {string} p
 * @param {{code: number, color: number[], specular?: number, r: Function|number[], rx: Function|number[],
 *   ry: Function|number[], size: Function|number[], file?: string}} s
 * @param {number[]} time
 * @returns {{name: string, description?: string, values: number[]}[]}  series for writeMat
 */
export function shapeSeries(p, s, time) {
  const at = (v) => (typeof v === 'function' ? time.map(v) : time.map(() => v));
  const vec = (name, v, description) => {
    const rows = at(v);
    return [0, 1, 2].map((i) => ({ name: `${p}.${name}[${i + 1}]`, description, values: rows.map((x) => x[i]) }));
  };
  return [
    { name: `${p}.Form`, description: s.file || 'Value of shapeType as Integer, for Dymola', values: time.map(() => (987000 + s.code) * 1e20) },
    ...vec('rxvisobj', s.rx, 'x-axis unit vector of shape, resolved in world frame'),
    ...vec('ryvisobj', s.ry, 'y-axis unit vector of shape, resolved in world frame'),
    ...vec('rvisobj', s.r, 'position vector from world frame to shape frame, resolved in world frame [m]'),
    ...vec('size', s.size, 'Length, width and height of shape [m]'),
    { name: `${p}.Material`, description: 'Material properties', values: time.map(() => packMaterial(s.color, s.specular)) },
  ];
}

/**
 * A frame's `f.r_0[1..3]` and `f.R.T[i, j]` (world → frame) from its position and its
 * frame → world rotation matrix M (rows), both functions of time: R.T[i, j] = M[j][i].
 */
export function frameSeries(f, { r, M }, time) {
  const pos = time.map(r);
  const rot = time.map(M);
  const out = [0, 1, 2].map((i) => ({ name: `${f}.r_0[${i + 1}]`, description: 'Position vector from world frame to the connector frame origin, resolved in world frame [m]', values: pos.map((x) => x[i]) }));
  for (let i = 0; i < 3; i++) {
    for (let j = 0; j < 3; j++) {
      out.push({ name: `${f}.R.T[${i + 1}, ${j + 1}]`, description: 'Transformation matrix from world frame to local frame', values: rot.map((m) => m[j][i]) });
    }
  }
  return out;
}
