// Scene tab (issue 29), the pure part: primitives with their default sizes, poses from typed
// numbers (position in metres, rotation as angles in degrees about x, then y, then z: R = Rx·Ry·Rz,
// rows as the API takes them) and back, unique names, and the API's field errors per object.

/** Default shapes of the primitives a user can add (SI units). */
export const PRIMITIVES = {
  box: { kind: 'box', size: [0.2, 0.2, 0.2] },
  cylinder: { kind: 'cylinder', radius: 0.1, length: 0.2 },
  sphere: { kind: 'sphere', radius: 0.1 },
  capsule: { kind: 'capsule', radius: 0.05, length: 0.2 },
  plane: { kind: 'plane' },
};

/** A name for a new object of `kind` that no object or body has (`box1`, `box2`, ...). */
export function freshName(kind, taken) {
  const used = new Set(taken);
  for (let i = 1; ; i += 1) {
    const n = `${kind}${i}`;
    if (!used.has(n)) return n;
  }
}

/** A new static object of primitive `kind` at the origin. */
export function newObject(kind, taken) {
  const shape = PRIMITIVES[kind];
  if (!shape) throw new Error(`unknown primitive ${kind}`);
  return { name: freshName(kind, taken), shape: structuredClone(shape), position: [0, 0, 0], rotation: [[1, 0, 0], [0, 1, 0], [0, 0, 1]] };
}

const rad = (d) => (d * Math.PI) / 180;
const deg = (r) => (r * 180) / Math.PI;

/** Rotation rows R = Rx(a)·Ry(b)·Rz(c), angles in degrees. */
export function rotationFromAngles([a, b, c]) {
  const [ca, sa, cb, sb, cc, sc] = [Math.cos(rad(a)), Math.sin(rad(a)), Math.cos(rad(b)), Math.sin(rad(b)), Math.cos(rad(c)), Math.sin(rad(c))];
  return [
    [cb * cc, -cb * sc, sb],
    [sa * sb * cc + ca * sc, -sa * sb * sc + ca * cc, -sa * cb],
    [-ca * sb * cc + sa * sc, ca * sb * sc + sa * cc, ca * cb],
  ];
}

/** The angles (degrees) of rotation rows, as `rotationFromAngles` takes them. */
export function anglesFromRotation(r) {
  const b = Math.asin(Math.max(-1, Math.min(1, r[0][2])));
  if (1 - Math.abs(r[0][2]) < 1e-12) return [deg(Math.atan2(r[2][1], r[1][1])), deg(b), 0];
  return [deg(Math.atan2(-r[1][2], r[2][2])), deg(b), deg(Math.atan2(-r[0][1], r[0][0]))];
}

/**
 * Parses typed numbers: three finite numbers, or an error message naming the field.
 * @returns {{value?: number[], error?: string}}
 */
export function parseTriple(texts, field) {
  const value = texts.map((t) => (String(t).trim() === '' ? NaN : Number(t)));
  if (value.length !== 3 || !value.every(Number.isFinite)) return { error: `${field}: three numbers are needed` };
  return { value };
}

/** The object with a new pose from typed numbers (position m, angles °), or the error. */
export function withPose(obj, positionTexts, angleTexts) {
  const p = parseTriple(positionTexts, 'position');
  if (p.error) return { error: p.error };
  const a = parseTriple(angleTexts, 'rotation');
  if (a.error) return { error: a.error };
  return { object: { ...obj, position: p.value, rotation: rotationFromAngles(a.value) } };
}

/** The API's field errors (`objects[2].rotation`) by object index. */
export function errorsByObject(errors) {
  const out = new Map();
  for (const e of errors || []) {
    const m = /^objects\[(\d+)\]\.?(.*)$/.exec(e.field || '');
    const k = m ? Number(m[1]) : -1;
    if (!out.has(k)) out.set(k, []);
    out.get(k).push(`${m ? m[2] || 'object' : e.field}: ${e.message}`);
  }
  return out;
}

/** A short description of an object's shape and kind. */
export function describe(o) {
  const s = o.shape;
  const dims = s.kind === 'box' ? s.size.join(' × ') + ' m'
    : s.kind === 'plane' ? 'z = 0 surface'
    : s.kind === 'sphere' ? `r ${s.radius} m`
    : s.kind === 'mesh' ? `${s.mesh}, ${s.unit || 'm'}`
    : `r ${s.radius} m, length ${s.length} m`;
  const kind = o.kind || 'static';
  return `${s.kind} (${dims}), ${kind}${o.attached_to ? ` on ${o.attached_to}` : ''}`;
}

/** The units a mesh file may be in, as the API names them (metres per unit in viewer.js). */
export const MESH_FILE_UNITS = ['m', 'mm', 'cm', 'in'];

/** Mesh files the service reads, by extension (STL, OBJ, COLLADA, VRML 97 / 1.0, gzip VRML). */
export const MESH_FILE_TYPES = ['.stl', '.obj', '.dae', '.wrl', '.wrz', '.vrml'];

/**
 * A copy of `o` under a name no object or body has (`box1` → `box2`, `table` → `table1`),
 * moved by `offset` (m, in its own frame's axes) so that it does not sit inside the original.
 */
export function duplicateObject(o, taken, offset = [0, 0, 0]) {
  const copy = structuredClone(o);
  copy.name = freshName(o.name.replace(/\d+$/, '') || 'object', taken);
  copy.position = o.position.map((x, i) => x + offset[i]);
  return copy;
}

/**
 * The mesh name for an uploaded file (the API wants a letter, then letters, digits or _): its
 * stem with other characters as _, a leading `m` where it would not start with a letter, at
 * most 60 characters. `null` with a message when the file's type is not one the service reads.
 */
export function meshNameFromFile(fileName) {
  const dot = fileName.lastIndexOf('.');
  const ext = dot >= 0 ? fileName.slice(dot).toLowerCase() : '';
  if (!MESH_FILE_TYPES.includes(ext)) return { error: `file: ${fileName} is not an STL, OBJ, COLLADA (.dae) or VRML (.wrl) mesh` };
  let stem = fileName.slice(0, dot).replace(/^.*[\\/]/, '').replace(/[^A-Za-z0-9_]/g, '_');
  if (!/^[A-Za-z]/.test(stem)) stem = `m${stem}`;
  // A COLLADA file states its unit, which the service applies: stored in metres.
  return ext === '.dae' ? { name: stem.slice(0, 60), unit: 'm' } : { name: stem.slice(0, 60) };
}

/** A new static object showing uploaded mesh `mesh` (file units `unit`) at the origin. */
export function meshObject(mesh, unit, taken) {
  if (!MESH_FILE_UNITS.includes(unit)) throw new Error(`unknown unit ${unit}`);
  return { name: freshName(mesh, taken), shape: { kind: 'mesh', mesh, unit }, position: [0, 0, 0], rotation: [[1, 0, 0], [0, 1, 0], [0, 0, 1]] };
}

/** The object moved by a world translation `d` (m) when its frame is the world (`parent` null). */
export function translated(o, d) {
  return { ...o, position: o.position.map((x, i) => x + d[i]) };
}

/** Interferences at the CAD pose that involve one of the scene's objects (by name). */
export function sceneInterferences(interferences, objects) {
  const names = new Set(objects.map((o) => o.name));
  return (interferences || [])
    .filter((i) => names.has(i.a) || names.has(i.b))
    .map((i) => (names.has(i.a) ? { object: i.a, other: i.b, depth: i.depth } : { object: i.b, other: i.a, depth: i.depth }));
}

/** Unit quaternion [w, x, y, z] of rotation rows (Shepperd's method). */
export function quatOf(r) {
  const tr = r[0][0] + r[1][1] + r[2][2];
  let q;
  if (tr > 0) {
    const s = Math.sqrt(tr + 1) * 2;
    q = [s / 4, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s];
  } else if (r[0][0] > r[1][1] && r[0][0] > r[2][2]) {
    const s = Math.sqrt(1 + r[0][0] - r[1][1] - r[2][2]) * 2;
    q = [(r[2][1] - r[1][2]) / s, s / 4, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s];
  } else if (r[1][1] > r[2][2]) {
    const s = Math.sqrt(1 + r[1][1] - r[0][0] - r[2][2]) * 2;
    q = [(r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, s / 4, (r[1][2] + r[2][1]) / s];
  } else {
    const s = Math.sqrt(1 + r[2][2] - r[0][0] - r[1][1]) * 2;
    q = [(r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, s / 4];
  }
  const n = Math.hypot(...q);
  return q.map((x) => x / n);
}

/** Rotation rows of a unit quaternion [w, x, y, z]. */
export function rotationOfQuat([w, x, y, z]) {
  return [
    [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
    [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
    [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
  ];
}

/** Spherical interpolation of unit quaternions (the shorter way). */
function slerp(a, b, s) {
  let d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  const bb = d < 0 ? b.map((x) => -x) : b;
  d = Math.abs(d);
  if (d > 1 - 1e-12) return a.map((x, i) => x + (bb[i] - x) * s);
  const th = Math.acos(d);
  const [ka, kb] = [Math.sin((1 - s) * th) / Math.sin(th), Math.sin(s * th) / Math.sin(th)];
  return a.map((x, i) => ka * x + kb * bb[i]);
}

/**
 * An object's pose at time `t` (s), as the collision checks take it (engine `pose_at`): static
 * and free objects at their pose; moving ones at position + velocity·t, or along their pose
 * table (linear in position, slerp in rotation between rows, held before the first row and
 * after the last).
 */
export function poseAt(o, t) {
  const rotation = o.rotation || [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
  const m = o.kind === 'moving' ? o.motion : null;
  if (m?.velocity) return { position: o.position.map((x, i) => x + m.velocity[i] * t), rotation };
  const rows = m?.poses;
  if (!rows?.length) return { position: o.position, rotation };
  const rot = (r) => r.rotation || [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
  if (t <= rows[0].time) return { position: rows[0].position, rotation: rot(rows[0]) };
  const last = rows[rows.length - 1];
  if (t >= last.time) return { position: last.position, rotation: rot(last) };
  let k = 0;
  while (rows[k + 1].time < t) k += 1;
  const [a, b] = [rows[k], rows[k + 1]];
  const s = (t - a.time) / (b.time - a.time);
  return { position: a.position.map((x, i) => x + (b.position[i] - x) * s), rotation: rotationOfQuat(slerp(quatOf(rot(a)), quatOf(rot(b)), s)) };
}

/** Sizes the API accepts (m): 0.1 mm .. 1 km, as engine/src/scene checks them. */
export const SIZE_RANGE = [1e-4, 1000];

/**
 * The editable dimensions of a primitive: [{field, label, value}] in metres (`size[0]`, `radius`,
 * `length`, ...); none for a plane or a mesh (a mesh's unit scales its file).
 */
export function shapeFields(s) {
  if (s.kind === 'box') return ['x', 'y', 'z'].map((a, i) => ({ field: `size[${i}]`, label: `size ${a}`, value: s.size[i] }));
  if (s.kind === 'sphere') return [{ field: 'radius', label: 'radius', value: s.radius }];
  if (s.kind === 'cylinder' || s.kind === 'capsule') return [{ field: 'radius', label: 'radius', value: s.radius }, { field: 'length', label: 'length', value: s.length }];
  return [];
}

/** The object with new dimensions from typed numbers (shapeFields' order), or an error naming the field. */
export function withShape(o, texts) {
  const fields = shapeFields(o.shape);
  const shape = structuredClone(o.shape);
  for (const [k, f] of fields.entries()) {
    const t = String(texts[k] ?? '').trim();
    const v = t === '' ? NaN : Number(t);
    if (!Number.isFinite(v) || v < SIZE_RANGE[0] || v > SIZE_RANGE[1]) return { error: `shape.${f.field}: "${t}" must be a length from ${SIZE_RANGE[0]} to ${SIZE_RANGE[1]} m` };
    if (f.field.startsWith('size')) shape.size[k] = v;
    else shape[f.field] = v;
  }
  return { object: { ...o, shape } };
}

const IDENTITY_ROWS = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];

/** What kind an object is, as the API names it. */
export const OBJECT_KINDS = ['static', 'moving', 'free'];

/**
 * The kind form's texts for object `o`: its kind, its motion (`velocity` m/s, or `poses`: one
 * row per line, `time x y z` and optionally the angles about x, y, z in degrees), its mass (kg)
 * and principal inertia (kg·m², blank: the solid shape's, computed by the service).
 */
export function kindForm(o) {
  const m = o.motion || {};
  const rows = (m.poses || []).map((r) => {
    const a = anglesFromRotation(r.rotation || IDENTITY_ROWS);
    const nums = [r.time, ...r.position, ...(a.some((x) => Math.abs(x) > 1e-9) ? a : [])];
    return nums.map((x) => String(Math.round(x * 1e9) / 1e9)).join(' ');
  });
  return {
    kind: o.kind || 'static',
    motion: m.poses ? 'poses' : 'velocity',
    velocity: (m.velocity || [0, 0, 0]).map(String),
    poses: rows.join('\n') || '0 0 0 0\n1 0.1 0 0',
    mass: o.mass === undefined ? '1' : String(o.mass),
    inertia: (o.inertia || ['', '', '']).map(String),
  };
}

/**
 * The object with the kind the form gives (fields of other kinds dropped), or an error naming
 * the field when a text is not a number. Ranges are the service's to check (its 422 names the
 * field, e.g. `objects[2].motion.velocity`).
 */
export function withKind(o, form) {
  const next = { ...o };
  delete next.motion;
  delete next.mass;
  delete next.inertia;
  if (form.kind === 'static') {
    delete next.kind;
    return { object: next };
  }
  if (!OBJECT_KINDS.includes(form.kind)) return { error: `kind: unknown kind ${form.kind}` };
  if (o.attached_to) return { error: 'kind: only static objects can be attached to a body: detach it first' };
  next.kind = form.kind;
  if (form.kind === 'moving') {
    if (form.motion === 'velocity') {
      const v = parseTriple(form.velocity, 'motion.velocity');
      if (v.error) return { error: v.error };
      next.motion = { velocity: v.value };
      return { object: next };
    }
    const poses = [];
    const lines = String(form.poses).split('\n').map((l) => l.trim()).filter((l) => l);
    for (const [i, line] of lines.entries()) {
      const x = line.split(/[\s,;]+/).map(Number);
      if (!(x.length === 4 || x.length === 7) || !x.every(Number.isFinite)) {
        return { error: `motion.poses[${i}]: a row is "time x y z" or "time x y z ax ay az" (s, m, °)` };
      }
      poses.push({ time: x[0], position: x.slice(1, 4), rotation: x.length === 7 ? rotationFromAngles(x.slice(4)) : IDENTITY_ROWS.map((r) => [...r]) });
    }
    next.motion = { poses };
    return { object: next };
  }
  const mass = String(form.mass).trim() === '' ? NaN : Number(form.mass);
  if (!Number.isFinite(mass)) return { error: 'mass: a number (kg) is needed' };
  next.mass = mass;
  if (form.inertia.some((t) => String(t).trim() !== '')) {
    const i = parseTriple(form.inertia, 'inertia');
    if (i.error) return { error: i.error };
    next.inertia = i.value;
  }
  return { object: next };
}

/**
 * The kind form's control showing an API field error of object `k` (`objects[k].motion.velocity`
 * → `velocity`, `….motion.poses[3].time` → `poses`, `….mass`, `….inertia`, `….kind`,
 * `….motion` → `motion`), or null for fields it has no control for.
 */
export function kindControl(field, k) {
  const m = /^objects\[(\d+)\]\.(.*)$/.exec(field);
  if (!m || Number(m[1]) !== k) return null;
  const f = m[2];
  if (f === 'motion.velocity' || f.startsWith('motion.velocity')) return 'velocity';
  if (f.startsWith('motion.poses')) return 'poses';
  if (f === 'motion') return 'motion';
  if (f === 'mass' || f === 'inertia' || f === 'kind') return f;
  return null;
}
