// The user's display units (degrees or radians for angles, millimetres or metres for lengths),
// kept in localStorage and used by every joint value the UI shows or reads: sliders, keyframes,
// drive references and plots. Values travel to and from the API in SI (rad, m) only.

const KEY = 'cad2mo.units';
export const DEFAULT_UNITS = Object.freeze({ angle: 'deg', length: 'mm' });
const ANGLE = { deg: { factor: 180 / Math.PI, symbol: '°' }, rad: { factor: 1, symbol: 'rad' } };
const LENGTH = { mm: { factor: 1000, symbol: 'mm' }, m: { factor: 1, symbol: 'm' } };

/** A valid units choice from anything (unknown or missing parts fall back to the defaults). */
export function normalizeUnits(u) {
  return {
    angle: u && Object.hasOwn(ANGLE, u.angle) ? u.angle : DEFAULT_UNITS.angle,
    length: u && Object.hasOwn(LENGTH, u.length) ? u.length : DEFAULT_UNITS.length,
  };
}

/** Whether an SI unit of a joint coordinate is an angle ('rad', or a revolute joint's kind). */
const isAngle = (siUnit) => siUnit === 'rad' || siUnit === 'revolute';

/** Display value per SI value, for a coordinate in `siUnit` ('rad' or 'm', or 'revolute'/'prismatic'). */
export function factorOf(siUnit, units = DEFAULT_UNITS) {
  const u = normalizeUnits(units);
  return isAngle(siUnit) ? ANGLE[u.angle].factor : LENGTH[u.length].factor;
}

/** The unit's symbol as shown: '°', 'rad', 'mm' or 'm'. */
export function symbolOf(siUnit, units = DEFAULT_UNITS) {
  const u = normalizeUnits(units);
  return isAngle(siUnit) ? ANGLE[u.angle].symbol : LENGTH[u.length].symbol;
}

/** SI value -> display value; scaled values are rounded to 12 significant digits (no float noise such as 29.999999999999996). */
export function toDisplay(si, siUnit, units) {
  if (si === null || si === undefined || !Number.isFinite(si)) return si;
  const f = factorOf(siUnit, units);
  if (f === 1) return si;
  const x = si * f;
  return x === 0 ? 0 : Number(x.toPrecision(12));
}

/** Display value -> SI value. */
export function fromDisplay(shown, siUnit, units) {
  if (shown === null || shown === undefined || !Number.isFinite(shown)) return shown;
  return shown / factorOf(siUnit, units);
}

/** A derived unit for plots: 'rad/s' -> '°/s' in degrees, 'm/s²' -> 'mm/s²' in millimetres. */
export function plotUnit(siUnit, suffix, units) {
  return `${symbolOf(siUnit, units)}${suffix}`;
}

/** Parses a typed number ("1,5" as well as "1.5"); null for empty, NaN for garbage. */
export function parseNumber(text) {
  const t = String(text ?? '').trim().replace(',', '.');
  if (t === '') return null;
  return /^[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?$/i.test(t) ? Number(t) : NaN;
}

const listeners = new Set();
let current = null;

/** The stored choice (defaults when none, or without storage). */
export function getUnits(storage = globalThis.localStorage) {
  if (!current) {
    try {
      current = normalizeUnits(JSON.parse(storage?.getItem(KEY) || 'null'));
    } catch {
      current = { ...DEFAULT_UNITS };
    }
  }
  return current;
}

/** Stores a new choice and tells every listener. */
export function setUnits(u, storage = globalThis.localStorage) {
  current = normalizeUnits({ ...getUnits(storage), ...u });
  try {
    storage?.setItem(KEY, JSON.stringify(current));
  } catch {
    /* private mode: the choice lasts for the page */
  }
  for (const f of listeners) f(current);
  return current;
}

/** Calls f(units) on every change; returns the function that stops it. */
export function onUnits(f) {
  listeners.add(f);
  return () => listeners.delete(f);
}
