// The "Modelica diagram" tab: the version's Mechanics (or Mechatronics) diagram as Dymola and
// OMEdit draw it, from the package's own Placement and Line annotations (the service renders it
// as SVG). The picture fills the bottom dock across the whole window (the 3D view and the tabs
// stay above it), with zoom buttons; every component gets an icon drawn from primitives by its
// class kind, names are labelled in screen pixels (hidden when the component is too small on
// screen, abbreviated or hidden where they would cover another name), and clicking a component shows its parameters (and selects a body or joint everywhere).

import { api, enc } from '../api.js';
import { h, fill, errorBox, num } from '../ui.js';
import { componentKind, labelPlan, parseTitle, driveParamRows, namePrefix, shortName, fitLabels } from './diagram-data.js';
import { getUnits, toDisplay, symbolOf } from '../units.js';

const SVG = 'http://www.w3.org/2000/svg';
/** Whose names come first where names would collide: bodies and joints, then drives, then the rest. */
const LABEL_RANK = { body: 0, revolute: 1, prismatic: 1, drive: 2, motor: 3, gear: 3, controller: 3, world: 4, fixed: 4, force: 5, sensor: 5, translation: 6, other: 7 };
const el = (tag, attrs) => {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  return e;
};

/** Primitives of a kind's icon inside the box (x, y, w, h), in the MSL icons' spirit. */
function icon(kind, x, y, w, hh) {
  const cx = x + w / 2;
  const cy = y + hh / 2;
  const r = Math.min(w, hh) / 2;
  const line = { stroke: '#303030', 'stroke-width': Math.max(0.4, r * 0.08), fill: 'none' };
  const g = el('g', { class: `icon icon-${kind}`, 'pointer-events': 'none' });
  const add = (tag, attrs) => g.append(el(tag, attrs));
  switch (kind) {
    case 'body': // a rod from frame_a to a sphere (Body)
      add('rect', { x: x + w * 0.08, y: cy - hh * 0.1, width: w * 0.5, height: hh * 0.2, fill: '#9ab8d8', stroke: '#303030', 'stroke-width': line['stroke-width'] });
      add('circle', { cx: x + w * 0.72, cy, r: r * 0.4, fill: '#3070c0', stroke: '#303030', 'stroke-width': line['stroke-width'] });
      break;
    case 'revolute': // two blocks and the hinge between them
      add('rect', { x: x + w * 0.08, y: cy - hh * 0.3, width: w * 0.34, height: hh * 0.6, ...line, fill: '#d0d0d0' });
      add('rect', { x: x + w * 0.58, y: cy - hh * 0.3, width: w * 0.34, height: hh * 0.6, ...line, fill: '#ffffff' });
      add('circle', { cx, cy, r: r * 0.2, fill: '#303030' });
      break;
    case 'prismatic': // a slider in its guide
      add('rect', { x: x + w * 0.05, y: cy - hh * 0.12, width: w * 0.9, height: hh * 0.24, ...line, fill: '#e8e8e8' });
      add('rect', { x: x + w * 0.4, y: cy - hh * 0.3, width: w * 0.3, height: hh * 0.6, ...line, fill: '#9ab8d8' });
      break;
    case 'world':
    case 'fixed': // the ground: a bar with hatching
      add('line', { x1: x + w * 0.15, y1: cy, x2: x + w * 0.85, y2: cy, ...line });
      for (let i = 0; i < 5; i++) add('line', { x1: x + w * (0.2 + 0.14 * i), y1: cy, x2: x + w * (0.13 + 0.14 * i), y2: cy + hh * 0.25, ...line });
      if (kind === 'world') {
        add('line', { x1: x + w * 0.25, y1: cy - hh * 0.05, x2: x + w * 0.25, y2: cy - hh * 0.38, ...line });
        add('line', { x1: x + w * 0.25, y1: cy - hh * 0.05, x2: x + w * 0.55, y2: cy - hh * 0.05, ...line });
      }
      break;
    case 'translation': // a fixed rod between two frames
      add('line', { x1: x + w * 0.1, y1: cy, x2: x + w * 0.9, y2: cy, ...line, 'stroke-width': Math.max(0.8, hh * 0.12) });
      break;
    case 'motor': // a circle with M
      add('circle', { cx, cy, r: r * 0.6, ...line, fill: '#f4f4f4' });
      g.append(Object.assign(el('text', { x: cx, y: cy + r * 0.22, 'font-size': r * 0.7, 'text-anchor': 'middle', fill: '#303030' }), { textContent: 'M' }));
      break;
    case 'gear': // two meshing wheels
      add('circle', { cx: cx - r * 0.3, cy, r: r * 0.5, ...line, fill: '#e0e0e0' });
      add('circle', { cx: cx + r * 0.45, cy, r: r * 0.28, ...line, fill: '#c8c8c8' });
      break;
    case 'controller': // a block with PI
      add('rect', { x: x + w * 0.15, y: y + hh * 0.2, width: w * 0.7, height: hh * 0.6, ...line, fill: '#eef4ff' });
      g.append(Object.assign(el('text', { x: cx, y: cy + r * 0.2, 'font-size': r * 0.55, 'text-anchor': 'middle', fill: '#303030' }), { textContent: 'PI' }));
      break;
    case 'sensor': // a dial with a needle
      add('circle', { cx, cy, r: r * 0.55, ...line, fill: '#ffffff' });
      add('line', { x1: cx, y1: cy, x2: cx + r * 0.35, y2: cy - r * 0.35, ...line });
      break;
    case 'drive': // motor and gear in one box
      add('circle', { cx: x + w * 0.32, cy, r: r * 0.42, ...line, fill: '#f4f4f4' });
      add('circle', { cx: x + w * 0.7, cy, r: r * 0.3, ...line, fill: '#e0e0e0' });
      break;
    case 'force': // an arrow
      add('line', { x1: x + w * 0.15, y1: cy, x2: x + w * 0.8, y2: cy, ...line });
      add('path', { d: `M${x + w * 0.85},${cy} l${-w * 0.15},${-hh * 0.15} l0,${hh * 0.3} z`, fill: '#303030' });
      break;
    default:
      add('rect', { x: x + w * 0.2, y: y + hh * 0.2, width: w * 0.6, height: hh * 0.6, ...line });
  }
  return g;
}

/**
 * @param {HTMLElement} panel  the tab panel
 * @param {{ modelId?: string, version: any, report: any, select: Function, stage: HTMLElement }} ctx
 */
export function renderDiagram(panel, { modelId, version, report, select, stage }) {
  let which = 'Mechanics';
  let zoom = 1;
  const view = h('div', { class: 'diagram-view', tabIndex: 0, 'aria-label': 'Modelica diagram' });
  const status = h('p', { class: 'muted diagram-status' });
  const url = () => `${version.links.diagram}?model=${which}`;
  const open = h('a', { href: url(), target: '_blank', rel: 'noopener' }, 'Open full size');
  const bodies = new Set(report.bodies.map((b) => b.modelica_name));
  const joints = new Map();
  for (const j of report.joints) {
    joints.set(j.modelica_name, j.modelica_name);
    for (const e of j.elements || []) joints.set(e.modelica_name, j.modelica_name);
  }
  const applyZoom = () => {
    const svg = view.querySelector('svg');
    if (!svg) return;
    const w = Number(svg.dataset.width);
    const hgt = Number(svg.dataset.height);
    svg.setAttribute('width', String(Math.round(w * zoom)));
    svg.setAttribute('height', String(Math.round(hgt * zoom)));
    relabel(svg);
  };
  /**
   * Names at a fixed size on screen, hidden where the component is too small to carry one,
   * without the prefix most names share, and never over another name: bodies and joints first,
   * each name as long as about twice its component's width if that is free, cut down where it
   * would cover a name already placed, else hidden (fitLabels, then checked on the measured boxes).
   */
  const relabel = (svg) => {
    const vb = svg.viewBox.baseVal;
    const scale = vb && vb.width ? Number(svg.getAttribute('width')) / vb.width : 1;
    const groups = [...svg.querySelectorAll('g[data-component]')];
    const prefix = namePrefix(groups.map((g) => g.dataset.component));
    let hidden = 0;
    const shown = [];
    groups.forEach((g, order) => {
      const rect = g.querySelector(':scope > rect');
      const text = g.querySelector(':scope > text');
      if (!rect || !text) return;
      const width = Number(rect.getAttribute('width'));
      const plan = labelPlan(scale, width);
      text.setAttribute('pointer-events', 'none');
      if (!plan.visible) {
        text.setAttribute('visibility', 'hidden');
        hidden++;
        return;
      }
      text.removeAttribute('visibility');
      // As many characters as about twice the component's width holds, where that is free.
      const max = Math.max(5, Math.floor((2.2 * width * scale) / 6.5));
      text.textContent = shortName(g.dataset.component, prefix, max);
      text.setAttribute('font-size', String(plan.fontSize));
      text.setAttribute('y', String(Number(rect.getAttribute('y')) - plan.fontSize * 0.25));
      shown.push({ g, text, max, width, order, rank: LABEL_RANK[g.dataset.kind] ?? 9 });
    });
    shown.sort((a, b) => a.rank - b.rank || b.width - a.width || a.order - b.order);
    // Measured once all are written (one layout), in user units.
    const measure = (list) =>
      list.map(({ text }) => {
        const b = text.getBBox();
        return { cx: b.x + b.width / 2, y0: b.y, y1: b.y + b.height, width: b.width, chars: text.textContent.length };
      });
    const boxes = measure(shown);
    if (boxes.some((b) => b.width > 0)) {
      const pad = 6 / scale; // 6 px between names on screen (3 at least once measured)
      const keep = fitLabels(boxes, { pad, minChars: 6 });
      shown.forEach((l, i) => {
        if (!keep[i]) return;
        if (keep[i] < boxes[i].chars) l.text.textContent = shortName(l.g.dataset.component, prefix, Math.max(5, Math.round((l.max * keep[i]) / boxes[i].chars)));
      });
      // The cut names' real widths: any that still touch another are hidden.
      const placed = shown.filter((_, i) => keep[i]);
      const final = fitLabels(measure(placed), { pad: 3 / scale, shrink: false });
      for (const l of [...shown.filter((_, i) => !keep[i]), ...placed.filter((_, i) => !final[i])]) {
        l.text.setAttribute('visibility', 'hidden');
        hidden++;
      }
    }
    svg.dataset.hiddenLabels = String(hidden);
  };
  /** Icons by class kind inside each component's box. */
  const decorate = (svg) => {
    for (const g of svg.querySelectorAll('g[data-component]')) {
      const rect = g.querySelector(':scope > rect');
      const { className } = parseTitle(g.querySelector(':scope > title')?.textContent);
      const kind = componentKind(className);
      g.dataset.kind = kind;
      g.dataset.class = className;
      if (!rect) continue;
      rect.setAttribute('fill', '#ffffff');
      const [x, y, w, hh] = ['x', 'y', 'width', 'height'].map((a) => Number(rect.getAttribute(a)));
      g.insertBefore(icon(kind, x, y, w, hh), rect.nextSibling);
    }
  };
  const paramsBox = h('div', { class: 'diagram-params', 'aria-live': 'polite' });
  /** The clicked component's parameters: the class, and what the report knows of a body or joint. */
  const showParams = (g) => {
    const name = g.dataset.component;
    const rows = [['Class', g.dataset.class || '—'], ['Icon', g.dataset.kind]];
    const u = getUnits();
    const b = report.bodies.find((x) => x.modelica_name === name);
    const jn = joints.get(name);
    if (b) {
      rows.push(['m', `${num(b.mass)} kg`], ['r_CM (world)', `${b.cg_world.map((x) => num(toDisplay(x, 'm', u))).join(', ')} ${symbolOf('m', u)}`]);
      rows.push(['I (about CM)', b.inertia_cg.map((r) => r.map(num).join(' ')).join('; ') + ' kg·m²']);
    } else if (jn) {
      const j = report.joints.find((x) => x.modelica_name === jn);
      for (const e of j?.elements || []) {
        if (e.modelica_name !== name && j.modelica_name !== name) continue;
        if (e.axis_world) rows.push([`${e.modelica_name} n`, e.axis_world.map(num).join(', ')]);
        if (e.kind === 'revolute' || e.kind === 'prismatic') {
          const si = e.kind === 'revolute' ? 'rad' : 'm';
          rows.push([`${e.modelica_name} start`, `${num(toDisplay(e.initial_q, si, u))} ${symbolOf(si, u)}`]);
        }
      }
    }
    const show = (list) =>
      fill(
        paramsBox,
        h('h3', {}, `Parameters of ${name}`),
        h('table', { class: 'details-table diagram-params-table', 'aria-label': `Parameters of ${name}` }, h('tbody', {}, list.map(([k, v]) => h('tr', {}, h('th', { scope: 'row' }, k), h('td', {}, v))))),
      );
    show(rows);
    // A drive: what the Drives tab stored for its joint (motor, gear, ratio, controller).
    const drive = /^drive_(.+)$/.exec(name);
    if (drive && modelId) {
      paramsBox.dataset.loading = 'true';
      drives ||= Promise.all([api(`/api/models/${enc(modelId)}/drives`), api('/api/library/instances')]);
      drives
        .then(([d, inst]) => {
          if (paramsBox.querySelector('h3')?.textContent !== `Parameters of ${name}`) return;
          const instById = new Map(inst.map((i) => [i.id, i]));
          show([...rows, ...driveParamRows(drive[1], d.drives.find((x) => x.joint === drive[1]), instById)]);
        })
        .catch((e) => paramsBox.append(errorBox(e, 'The drive could not be loaded')))
        .finally(() => delete paramsBox.dataset.loading);
    }
  };
  let drives = null; // the drives and library instances, loaded at the first drive clicked
  async function load() {
    drives = null; // read again: they may have changed in the Drives tab
    status.textContent = `Loading the ${which} diagram…`;
    open.href = url();
    try {
      const text = await api(url(), { accept: 'image/svg+xml' });
      const doc = new DOMParser().parseFromString(text, 'image/svg+xml');
      const svg = doc.documentElement;
      if (svg.nodeName !== 'svg') throw new Error('the service sent no SVG');
      svg.dataset.width = svg.getAttribute('width');
      svg.dataset.height = svg.getAttribute('height');
      fill(view, document.importNode(svg, true));
      decorate(view.querySelector('svg'));
      // Fit the width of the stage, but no smaller than what shows names on the components
      // (about 30 px wide on screen); the rest scrolls.
      const el = view.querySelector('svg');
      const w = Number(el.dataset.width) || 1;
      const vb = el.viewBox.baseVal;
      const widths = [...el.querySelectorAll('g[data-component] > rect')].map((r) => Number(r.getAttribute('width'))).sort((a, b) => a - b);
      const median = widths[Math.floor(widths.length / 2)] || 20;
      const base = vb && vb.width ? w / vb.width : 1; // screen px per user unit at zoom 1
      const fit = (view.clientWidth || 800) / w;
      zoom = Math.min(4, Math.max(0.05, Math.max(Math.min(1, fit), 30 / (median * base))));
      applyZoom();
      const count = view.querySelectorAll('g[data-component]').length;
      const lines = view.querySelectorAll('polyline').length;
      status.textContent = `${which}: ${count} components, ${lines} connections. Scroll to move; click a body or joint to select it.`;
    } catch (e) {
      status.textContent = '';
      fill(view, errorBox(e));
    }
  }
  view.addEventListener('click', (e) => {
    const g = e.target.closest?.('g[data-component]');
    if (!g) return;
    showParams(g);
    const name = g.dataset.component;
    if (bodies.has(name)) select({ kind: 'body', name });
    else if (joints.has(name)) select({ kind: 'joint', name: joints.get(name) });
  });
  const zoomBy = (f) => {
    zoom = Math.min(8, Math.max(0.05, zoom * f));
    applyZoom();
  };
  const choice = h(
    'select',
    { 'aria-label': 'Model', onchange: (e) => { which = e.target.value; load(); } },
    h('option', { value: 'Mechanics' }, 'Mechanics'),
    h('option', { value: 'Mechatronics' }, 'Mechatronics'),
  );
  fill(
    panel,
    h('h2', {}, 'Modelica diagram'),
    // The controls first: the side panel is short while the diagram takes the dock.
    h('p', {}, h('label', {}, 'Model ', choice), ' ', h('button', { type: 'button', onclick: () => zoomBy(1.25) }, 'Zoom in'), ' ', h('button', { type: 'button', onclick: () => zoomBy(0.8) }, 'Zoom out'), ' ', open),
    h(
      'p',
      { class: 'muted' },
      'The diagram Dymola and OMEdit show for this package: the kinematic tree from the world (left) to the deepest bodies (right), each body with the frames fixed on it, joints between them; dashed red lines close loops. Mechatronics adds each drive above its joint and each contact force beside its body, wired to it alone (the collision world feeds every force by name, so no wires cross the sheet).',
    ),
  );
  fill(stage, status, view, paramsBox);
  load();
}
