// The collision views' pure parts (no DOM, no three.js): units for display, the order of the
// shape table, the allowed-collision matrix as rows and as the edits a change makes, the lines
// between witness points, and a motion check's rows and timeline markers.

/** Metres → millimetres, rounded for display (no float noise). */
export function mm(m) {
  if (!Number.isFinite(m)) return null;
  return Math.round(m * 1e6) / 1e3;
}

/** A pair's key, independent of its order. */
export function pairKey(a, b) {
  return a < b ? `${a}\u0000${b}` : `${b}\u0000${a}`;
}

/**
 * The shape table's rows: bodies with a shape first (in the service's order), then those
 * without; each with its values in display units.
 */
export function shapeRows(bodies) {
  const rows = (bodies || []).map((b, i) => ({
    body: b.body,
    kind: b.kind,
    parts: b.parts,
    vertices: b.vertices,
    fitErrorMm: b.kind === 'none' ? null : mm(b.fit_error),
    volumeRatio: b.kind === 'none' || !Number.isFinite(b.volume_ratio) ? null : Math.round(b.volume_ratio * 1000) / 1000,
    triangles: b.source_triangles ?? null,
    warnings: b.warnings || [],
    hasShape: b.kind !== 'none',
    order: i,
  }));
  return rows.sort((x, y) => Number(y.hasShape) - Number(x.hasShape) || x.order - y.order);
}

/**
 * The matrix as rows for the editor: per pair whether it may touch, whether that is the default,
 * and what the state means ("allowed by default", "checked by default", "allowed (custom)", …).
 */
export function matrixRows(matrix) {
  return (matrix?.pairs || []).map((p) => ({
    a: p.a,
    b: p.b,
    key: pairKey(p.a, p.b),
    allowed: !!p.allowed,
    default: !!p.default,
    custom: !!p.custom,
    why: p.why || '',
    state: `${p.allowed ? 'may touch' : 'checked'}${p.custom ? ' (custom)' : ' (default)'}`,
  }));
}

/**
 * The PUT body that sets pair (a, b) to `allowed` (true: may touch, false: checked); a value
 * equal to the pair's default resets it (`null`), so the matrix keeps no needless edits.
 */
export function pairEdit(matrix, a, b, allowed) {
  const p = (matrix?.pairs || []).find((x) => pairKey(x.a, x.b) === pairKey(a, b));
  const value = allowed === null || allowed === undefined || (p && !!p.default === !!allowed) ? null : !!allowed;
  return { pairs: [{ a: p ? p.a : a, b: p ? p.b : b, allowed: value }] };
}

/** The PUT body that returns every custom pair (and orphaned edit) to its default. */
export function resetAllEdit(matrix) {
  const all = [...(matrix?.pairs || []), ...(matrix?.orphans || [])].filter((p) => p.custom);
  // Orphans name bodies this version lacks: the service refuses those, so only current pairs.
  const known = new Set(matrix?.bodies || []);
  return { pairs: all.filter((p) => known.has(p.a) && known.has(p.b)).map((p) => ({ a: p.a, b: p.b, allowed: null })) };
}

/** The segment between two witness points: its ends (world, m) and length (m). */
export function witnessLine(p) {
  const from = [...p.point_a];
  const to = [...p.point_b];
  return { from, to, length: Math.hypot(to[0] - from[0], to[1] - from[1], to[2] - from[2]) };
}

/** An interference's one-line description. */
export function interferenceText(i) {
  return `${i.a} and ${i.b} intersect by ${mm(i.depth)} mm`;
}

/**
 * A motion check's rows: per pair its minimum distance (mm; negative: penetration), when, first
 * contact, deepest penetration, and whether it touches. Closest first (as the service sends).
 */
export function sweepRows(result) {
  return (result?.pairs || []).map((p) => ({
    a: p.a,
    b: p.b,
    key: pairKey(p.a, p.b),
    minDistanceMm: mm(p.min_distance),
    at: p.at,
    firstContact: p.first_contact ?? null,
    maxDepthMm: mm(p.max_depth || 0),
    touches: p.first_contact !== null && p.first_contact !== undefined,
    pair: p,
  }));
}

/** The first contact's one-line summary, or that none was found. */
export function firstContactText(result) {
  const f = result?.first_contact;
  if (!f) return `No contact: every checked pair stays apart over the motion (${result?.pairs?.length ?? 0} checked pairs).`;
  return `First contact: ${f.a} and ${f.b} at ${round3(f.time)} s`;
}

/**
 * Timeline markers at the first-contact times: {a, b, time, left} with `left` in % of the
 * duration (clamped to 0..100), in time order.
 */
export function contactMarkers(result, duration) {
  const out = [];
  for (const p of result?.pairs || []) {
    if (p.first_contact === null || p.first_contact === undefined) continue;
    const left = duration > 0 ? Math.min(100, Math.max(0, (p.first_contact / duration) * 100)) : 0;
    out.push({ a: p.a, b: p.b, time: p.first_contact, left });
  }
  return out.sort((x, y) => x.time - y.time);
}

/**
 * Pairs that have touched by time t (first contact at or before t, within half a sample of the
 * check's rate): the player highlights them.
 */
export function touchedBy(result, t) {
  const half = result?.rate_hz > 0 ? 0.5 / result.rate_hz : 0;
  return (result?.pairs || []).filter((p) => p.first_contact !== null && p.first_contact !== undefined && p.first_contact <= t + half);
}

function round3(x) {
  return Math.round(x * 1000) / 1000;
}
