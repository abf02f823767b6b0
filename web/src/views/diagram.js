// The "Modelica diagram" tab: the version's Mechanics (or Mechatronics) diagram as Dymola and
// OMEdit draw it, from the package's own Placement and Line annotations (the service renders it
// as SVG). The picture stands under the 3D view with zoom buttons; clicking a body or joint in it
// selects that body or joint everywhere.

import { api } from '../api.js';
import { h, fill, errorBox } from '../ui.js';

/**
 * @param {HTMLElement} panel  the tab panel
 * @param {{ version: any, report: any, select: Function, stage: HTMLElement }} ctx
 */
export function renderDiagram(panel, { version, report, select, stage }) {
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
  };
  async function load() {
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
      // Fit the width of the stage first.
      const w = Number(view.querySelector('svg').dataset.width) || 1;
      zoom = Math.min(1, Math.max(0.05, (view.clientWidth || 800) / w));
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
    h(
      'p',
      { class: 'muted' },
      'The diagram Dymola and OMEdit show for this package: the kinematic tree from the world (left) to the deepest bodies (right), each body with the frames fixed on it, joints between them; dashed red lines close loops. Mechatronics adds each drive above its joint.',
    ),
    h('p', {}, h('label', {}, 'Model ', choice), ' ', h('button', { type: 'button', onclick: () => zoomBy(1.25) }, 'Zoom in'), ' ', h('button', { type: 'button', onclick: () => zoomBy(0.8) }, 'Zoom out'), ' ', open),
  );
  fill(stage, status, view);
  load();
}
