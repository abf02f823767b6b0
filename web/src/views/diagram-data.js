// The Modelica diagram's pure parts: which icon a component gets from its class (drawn from
// primitives in the spirit of the MSL icons, no copied graphics), and how its name is labelled:
// in screen pixels whatever the zoom, hidden when the component is too small on screen to carry
// it, without the prefix most names share, and abbreviated or hidden where it would cover
// another name (fitLabels); the full name is the component's tooltip.

import { abbreviate } from '../layout-data.js';

/** The icon kind of a Modelica class name (MSL or one we generate). */
export function componentKind(className) {
  const c = String(className ?? '');
  const last = c.split('.').pop();
  if (/^World$/.test(last)) return 'world';
  if (/Fixed$/.test(last) && !/Translation|Rotation/.test(last)) return 'fixed';
  if (/^Fixed(Translation|Rotation)$|^FixedShape/.test(last)) return 'translation';
  if (/(Force|Torque)$/.test(last)) return 'force';
  if (/^Body|BodyShape|BodyBox|BodyCylinder|^Mass$/.test(last)) return 'body';
  if (/Revolute|Spherical|Universal|Cylindrical|Planar|FreeMotion/.test(last)) return 'revolute';
  if (/Prismatic/.test(last)) return 'prismatic';
  // Generated classes are known by their package (ARM.Motors.DCPermanentMagnet, ARM.Gears…).
  if (/Sensor/.test(last)) return 'sensor';
  if (/(^|\.)Drives?\.|^Drive|Drive$/.test(c)) return 'drive';
  if (/Motors?\.|Motor|DCPM|Servo/i.test(c)) return 'motor';
  if (/Gears?\.|Gear|Screw/i.test(c)) return 'gear';
  if (/Controllers?\.|Controller|Cascade|PID$|PI$/.test(c)) return 'controller';
  if (/Contact|Force|Torque|Collision/.test(c)) return 'force';
  return 'other';
}

export const LABEL_PX = 11; // label height on screen, CSS pixels
export const MIN_BOX_PX = 18; // below this on-screen width a component carries no label

/**
 * A label for a component `boxWidth` user units wide at `scale` screen pixels per user unit:
 * the font size in user units that makes LABEL_PX on screen, or hidden when the component is
 * narrower than MIN_BOX_PX on screen (its name would cover its neighbours).
 */
export function labelPlan(scale, boxWidth) {
  if (!(scale > 0) || boxWidth * scale < MIN_BOX_PX) return { visible: false, fontSize: 0 };
  return { visible: true, fontSize: LABEL_PX / scale };
}

/** The text of the SVG component's <title>: "Class name" → {className, name}. */
export function parseTitle(title) {
  const t = String(title ?? '').trim();
  const i = t.lastIndexOf(' ');
  return i < 0 ? { className: t, name: '' } : { className: t.slice(0, i), name: t.slice(i + 1) };
}

/**
 * The parameter rows of a Mechatronics drive component (drive_<joint>): the joint, the library
 * instances of its motor, gear and controller (by name), the gear ratio (the drive's own override
 * or the gear's value) and any other overridden values.
 * @param {string} joint
 * @param {object|undefined} drive  one of GET /api/models/{id}/drives' drives
 * @param {Map<string, {name: string, values?: object}>} instById  the library's instances
 * @returns {[string, string][]}
 */
export function driveParamRows(joint, drive, instById) {
  if (!drive) return [['Joint', joint], ['Drive', 'none stored for this joint']];
  const name = (id) => (id ? instById.get(id)?.name || id : '—');
  const rows = [['Joint', joint], ['Motor', name(drive.motor_instance)], ['Gear', name(drive.gear_instance)]];
  const ratio = drive.overrides?.gear?.ratio ?? instById.get(drive.gear_instance)?.values?.ratio;
  if (ratio !== undefined && ratio !== null) rows.push(['Ratio', String(ratio)]);
  rows.push(['Controller', name(drive.controller_instance)]);
  for (const [slot, values] of Object.entries(drive.overrides || {})) {
    for (const [k, v] of Object.entries(values || {})) if (!(slot === 'gear' && k === 'ratio')) rows.push([`${slot}.${k}`, String(v)]);
  }
  if (drive.status && drive.status !== 'active') rows.push(['Status', drive.status]);
  return rows;
}

/**
 * The prefix most component names share (CAD exports start every name with the model's,
 * "SIM_L_HAND_"), ending at a separator: shared by at least `share` of the names and leaving a
 * few characters of each; '' when there is none worth removing (under 4 characters).
 */
export function namePrefix(names, share = 0.6) {
  const list = [...names].map(String);
  if (list.length < 2) return '';
  // Candidate prefixes: every separator-ended start of every name, counted.
  const count = new Map();
  for (const n of list) {
    for (let i = 0; i < n.length - 3; i++) {
      if (n[i] === '_' || n[i] === '.') {
        const p = n.slice(0, i + 1);
        count.set(p, (count.get(p) || 0) + 1);
      }
    }
  }
  let best = '';
  for (const [p, c] of count) if (c >= share * list.length && p.length > best.length) best = p;
  return best.length >= 4 ? best : '';
}

/**
 * A component's name shown in at most `max` characters: the shared `prefix` dropped (an
 * ellipsis says so), then abbreviated in the middle (layout-data.js abbreviate).
 */
export function shortName(name, prefix, max) {
  const n = String(name);
  if (prefix && n.startsWith(prefix) && n.length > prefix.length) return `…${abbreviate(n.slice(prefix.length), Math.max(5, max - 1))}`;
  return abbreviate(n, max);
}

/**
 * Which names to show, and in how many characters, so that no two overlap. `labels` come in
 * priority order, each {cx, y0, y1, width, chars}: its text's box now (centred on cx) and
 * characters. A name that would cover one placed before it is cut down (its width taken in
 * proportion to its characters) to as few as `minChars`, else hidden; with `shrink: false` it is
 * hidden at once (a check of measured boxes). `pad` is the gap kept between two names.
 * @returns {number[]} per label the characters to show (0: hidden)
 */
export function fitLabels(labels, { minChars = 5, pad = 0, shrink = true } = {}) {
  const out = new Array(labels.length).fill(0);
  const heights = labels.map((l) => l.y1 - l.y0).filter((x) => x > 0);
  const cell = Math.max(1e-9, 4 * (heights.length ? Math.max(...heights) : 1));
  const grid = new Map(); // cell → placed boxes touching it
  const cells = (b, visit) => {
    for (let i = Math.floor(b.x0 / cell); i <= Math.floor(b.x1 / cell); i++) {
      for (let j = Math.floor(b.y0 / cell); j <= Math.floor(b.y1 / cell); j++) if (visit(`${i},${j}`) === false) return false;
    }
    return true;
  };
  const free = (b) =>
    cells(b, (k) => {
      for (const o of grid.get(k) || []) if (b.x0 < o.x1 + pad && o.x0 < b.x1 + pad && b.y0 < o.y1 + pad && o.y0 < b.y1 + pad) return false;
      return true;
    });
  labels.forEach((l, i) => {
    if (!(l.chars > 0) || !(l.width >= 0)) return;
    const per = l.width / l.chars;
    let c = l.chars;
    for (;;) {
      const b = { x0: l.cx - (per * c) / 2, x1: l.cx + (per * c) / 2, y0: l.y0, y1: l.y1 };
      if (free(b)) {
        out[i] = c;
        cells(b, (k) => {
          if (!grid.has(k)) grid.set(k, []);
          grid.get(k).push(b);
        });
        return;
      }
      if (!shrink || c <= minChars) return;
      c = Math.max(minChars, Math.min(c - 1, Math.floor(c * 0.8)));
    }
  });
  return out;
}
