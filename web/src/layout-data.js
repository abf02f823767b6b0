// The workspace layout's pure parts: panel sizes clamped to the window and kept in localStorage,
// and long CAD names abbreviated to fit a table cell (the full name goes into its title).

/** `v` within [lo, hi] (lo wins when the window is too small for both). */
export function clamp(v, lo, hi) {
  return Math.max(lo, Math.min(v, hi));
}

/**
 * Limits of the side panel's width and the bottom dock's height for a window of `w` × `hgt`
 * CSS pixels: the 3D view keeps at least 320 px × 200 px.
 */
export function sizeLimits(w, hgt) {
  return {
    side: { min: 280, max: Math.max(280, w - 320 - 40) },
    dock: { min: 96, max: Math.max(96, hgt - 200 - 60) },
  };
}

/** A stored size (a number in px) or the fallback, clamped to [min, max]. */
export function loadSize(storage, key, fallback, min, max) {
  let v = NaN;
  try {
    v = Number(storage?.getItem(key));
  } catch {
    /* no storage */
  }
  return Math.round(clamp(Number.isFinite(v) && v > 0 ? v : fallback, min, max));
}

/** Stores a size; a refusing storage (private mode) is ignored. */
export function saveSize(storage, key, v) {
  try {
    storage?.setItem(key, String(Math.round(v)));
  } catch {
    /* the size lasts for the page */
  }
}

/**
 * A name shortened to at most `max` characters by cutting its middle (CAD names differ at both
 * ends: "SIM_L_HAND_…_THUMB_PROXIMAL"): the first part cut at a separator where one is near.
 */
export function abbreviate(name, max = 24) {
  const s = String(name ?? '');
  if (s.length <= max || max < 5) return s;
  const keep = max - 1; // the ellipsis takes one
  const tail = Math.ceil(keep / 2);
  let head = keep - tail;
  // Prefer ending the head at a separator if one is close (within 4 characters).
  const sep = Math.max(s.lastIndexOf('_', head), s.lastIndexOf('-', head), s.lastIndexOf('.', head));
  if (sep > head - 4 && sep > 0) head = sep + 1;
  // And the tail starts at a word: a cut word ("OX_LITTLE" of "PROX_LITTLE") is dropped.
  let from = s.length - (keep - head);
  if (!/[_.\-]/.test(s[from - 1])) {
    const m = /[_.\-]/.exec(s.slice(from, from + 5));
    if (m && from + m.index + 1 < s.length - 3) from += m.index + 1;
  }
  return `${s.slice(0, head)}…${s.slice(from)}`;
}

/** Rows whose name holds every word of `query` (case-insensitive); all rows for an empty query. */
export function filterRows(rows, query, nameOf = (r) => r) {
  const words = String(query ?? '').toLowerCase().split(/\s+/).filter(Boolean);
  if (!words.length) return rows;
  return rows.filter((r) => {
    const n = String(nameOf(r)).toLowerCase();
    return words.every((w) => n.includes(w));
  });
}

/**
 * Names abbreviated to `max` characters each, but never two alike: names whose abbreviations
 * collide get longer ones (up to the full name) until every shown name is distinct.
 * @returns {Map<string, string>} name → shown text
 */
export function abbreviateAll(names, max = 24) {
  const out = new Map();
  const len = new Map();
  for (const n of names) len.set(n, max);
  for (let round = 0; round < 100; round++) {
    for (const n of names) out.set(n, abbreviate(n, len.get(n)));
    const seen = new Map();
    for (const n of names) seen.set(out.get(n), [...(seen.get(out.get(n)) || []), n]);
    const clash = [...seen.values()].filter((g) => new Set(g).size > 1).flat();
    if (!clash.length) break;
    for (const n of clash) len.set(n, Math.min(String(n).length, len.get(n) + 4));
  }
  return out;
}
