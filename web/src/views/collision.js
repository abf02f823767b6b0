// Collision (issue 14): the version's collision shapes per body, the pairs that interfere at the
// CAD pose (selecting one tints both bodies in 3D and draws the line between its witness
// points), and the model's allowed-collision matrix, editable pair by pair ("may touch").

import { api, enc } from '../api.js';
import { h, fill, errorBox, num } from '../ui.js';
import { abbreviate } from '../layout-data.js';
import { shapeRows, matrixRows, pairEdit, resetAllEdit, witnessLine, interferenceText, pairKey, mm } from './collision-data.js';

/** A long CAD name cut to fit its cell, the full name on hover. */
const nameCell = (n) => h('span', { class: 'name', title: n }, abbreviate(n, 26));

/**
 * @param {HTMLElement} panel
 * @param {{modelId: string, versionNumber: number, viewer: object, say: Function, resetPose: Function}} ctx
 * @returns {{shown(on: boolean): void, dispose(): void}}
 */
export function renderCollision(panel, ctx) {
  const { modelId, versionNumber, viewer } = ctx;
  const base = `/api/models/${enc(modelId)}`;
  let data = null; // GET …/versions/{v}/collision
  let matrix = null; // GET …/collision-matrix
  let chosen = null; // the interference shown in 3D (its pair key)
  let disposed = false;

  const shapesBox = h('div', { class: 'collision-shapes' });
  const interBox = h('div', { class: 'collision-interferences', 'aria-live': 'polite' });
  const matrixBox = h('div', { class: 'collision-matrix' });
  fill(
    panel,
    h('h2', {}, 'Interferences at the CAD pose'),
    interBox,
    h('h2', {}, 'Allowed-collision matrix'),
    h('p', { class: 'muted' }, 'Pairs that may touch are not checked. Bodies joined by a joint may touch by default; check such a pair to see where it intersects.'),
    matrixBox,
    h('h2', {}, 'Collision shapes'),
    shapesBox,
  );

  async function load() {
    fill(interBox, h('p', { role: 'status' }, 'Checking the CAD pose…'));
    try {
      [data, matrix] = await Promise.all([api(`${base}/versions/${versionNumber}/collision`), api(`${base}/collision-matrix`)]);
    } catch (e) {
      fill(interBox, errorBox(e, 'Collisions are not available for this version'));
      fill(matrixBox);
      fill(shapesBox);
      return;
    }
    if (disposed) return;
    renderShapes();
    renderInterferences();
    renderMatrix();
  }

  /** After a matrix change: the interferences depend on it. */
  async function reloadInterferences() {
    try {
      data = await api(`${base}/versions/${versionNumber}/collision`);
    } catch (e) {
      fill(interBox, errorBox(e, 'The interferences could not be checked'));
      return;
    }
    if (disposed) return;
    renderInterferences();
  }

  // ---------------------------------------------------------------- shapes
  function renderShapes() {
    const rows = shapeRows(data.bodies).map((r) =>
      h(
        'tr',
        { dataset: { body: r.body }, class: r.hasShape ? '' : 'no-shape' },
        h('th', { scope: 'row' }, nameCell(r.body)),
        h('td', {}, r.kind),
        h('td', { class: 'num' }, String(r.parts)),
        h('td', { class: 'num' }, String(r.vertices)),
        h('td', { class: 'num' }, r.fitErrorMm === null ? '—' : num(r.fitErrorMm)),
        h('td', { class: 'num' }, r.volumeRatio === null ? '—' : num(r.volumeRatio)),
        h('td', { class: 'warnings' }, r.warnings.length ? h('ul', {}, r.warnings.map((w) => h('li', { class: 'warn' }, w))) : h('span', { class: 'muted' }, 'none')),
      ),
    );
    fill(
      shapesBox,
      h(
        'div',
        { class: 'scroll' },
        h(
          'table',
          { class: 'collision-shapes-table', 'aria-label': 'Collision shapes per body' },
          h('thead', {}, h('tr', {}, ['Body', 'Kind', 'Parts', 'Vertices', 'Fit error [mm]', 'Volume ratio', 'Warnings'].map((c) => h('th', { scope: 'col' }, c)))),
          h('tbody', {}, rows),
        ),
      ),
    );
  }

  // ---------------------------------------------------------------- interferences
  function renderInterferences() {
    const list = data.interferences || [];
    if (chosen && !list.some((i) => pairKey(i.a, i.b) === chosen)) {
      chosen = null;
      viewer.setContacts?.([], []);
    }
    if (!list.length) {
      fill(interBox, h('p', { class: 'muted no-interference' }, 'None: no checked pair intersects at the CAD pose.'));
      return;
    }
    const items = list.map((i) => {
      const key = pairKey(i.a, i.b);
      const on = key === chosen;
      return h(
        'li',
        { dataset: { a: i.a, b: i.b }, class: on ? 'selected' : '' },
        h(
          'button',
          { type: 'button', class: 'pick', 'aria-pressed': String(on), onclick: () => show(i), 'aria-label': `Show the interference of ${i.a} and ${i.b} in 3D` },
          `${i.a} — ${i.b}`,
        ),
        h('span', { class: 'depth' }, ` depth ${num(mm(i.depth))} mm`),
        h('small', { class: 'muted' }, ` witness points ${i.point_a.map((x) => num(mm(x))).join(', ')} and ${i.point_b.map((x) => num(mm(x))).join(', ')} mm (world)`),
      );
    });
    fill(
      interBox,
      h('p', { class: 'warning' }, `${list.length} checked ${list.length === 1 ? 'pair intersects' : 'pairs intersect'} at the CAD pose.`),
      h('ul', { class: 'picklist interferences', 'aria-label': 'Interferences at the CAD pose' }, items),
      chosen ? h('button', { type: 'button', onclick: clear }, 'Clear the 3D marks') : null,
    );
  }

  function show(i) {
    // The witness points are at the CAD pose: the model goes there first.
    ctx.resetPose?.();
    chosen = pairKey(i.a, i.b);
    viewer.setContacts?.([i.a, i.b], [witnessLine(i)]);
    ctx.say(interferenceText(i), 'info');
    renderInterferences();
  }

  function clear() {
    chosen = null;
    viewer.setContacts?.([], []);
    renderInterferences();
  }

  // ---------------------------------------------------------------- matrix
  function renderMatrix() {
    const rows = matrixRows(matrix).map((r) => {
      const id = `may-touch-${r.a}-${r.b}`.replace(/[^\w-]/g, '_');
      const box = h('input', { type: 'checkbox', id, checked: r.allowed, 'aria-label': `${r.a} and ${r.b} may touch` });
      box.addEventListener('change', () => save(pairEdit(matrix, r.a, r.b, box.checked), box));
      return h(
        'tr',
        { dataset: { a: r.a, b: r.b }, class: `${r.custom ? 'custom' : ''} ${r.allowed ? 'allowed' : 'checked'}` },
        h('th', { scope: 'row' }, nameCell(r.a)),
        h('th', { scope: 'row' }, nameCell(r.b)),
        h('td', { class: 'may-touch' }, box),
        h('td', { class: 'state' }, r.custom ? h('span', { class: 'badge' }, 'custom') : h('span', { class: 'muted' }, 'default'), ' ', h('small', { class: 'muted' }, r.why)),
        h(
          'td',
          {},
          r.custom
            ? h('button', { type: 'button', onclick: (e) => save(pairEdit(matrix, r.a, r.b, null), e.currentTarget), 'aria-label': `Reset ${r.a} and ${r.b} to the default` }, 'Default')
            : null,
        ),
      );
    });
    const custom = matrixRows(matrix).filter((r) => r.custom).length;
    fill(
      matrixBox,
      rows.length
        ? h(
            'div',
            { class: 'scroll' },
            h(
              'table',
              { class: 'collision-matrix-table', 'aria-label': 'Allowed-collision matrix' },
              h('thead', {}, h('tr', {}, ['Body', 'Body', 'May touch', 'Why', ''].map((c) => h('th', { scope: 'col' }, c)))),
              h('tbody', {}, rows),
            ),
          )
        : h('p', { class: 'muted' }, 'Fewer than two bodies have a collision shape: no pairs.'),
      h(
        'div',
        { class: 'row' },
        h('span', { class: 'muted' }, `${matrixRows(matrix).filter((r) => !r.allowed).length} of ${rows.length} pairs checked; ${custom} custom.`),
        custom ? h('button', { type: 'button', class: 'danger', onclick: (e) => save(resetAllEdit(matrix), e.currentTarget) }, 'Reset all to the defaults') : null,
      ),
      matrix.orphans?.length
        ? h('p', { class: 'muted orphans' }, `Edits naming bodies this version lacks (kept): ${matrix.orphans.map((o) => `${o.a} — ${o.b}: ${o.allowed ? 'may touch' : 'checked'}`).join('; ')}.`)
        : null,
      h('div', { class: 'matrix-out', 'aria-live': 'polite' }),
    );
  }

  async function save(body, control) {
    if (control) control.disabled = true;
    try {
      matrix = await api(`${base}/collision-matrix`, { method: 'PUT', body });
      if (disposed) return;
      const p = body.pairs[0];
      ctx.say(body.pairs.length === 1 ? `${p.a} and ${p.b}: ${p.allowed === null ? 'back to the default' : p.allowed ? 'may touch' : 'checked'}` : 'The matrix is the default again', 'ok');
      renderMatrix();
      fill(matrixBox.querySelector('.matrix-out'), h('p', { class: 'ok saved' }, 'Saved.'));
      await reloadInterferences();
    } catch (e) {
      renderMatrix();
      fill(matrixBox.querySelector('.matrix-out'), errorBox(e, 'The matrix was not saved'));
    }
  }

  load();
  return {
    /** The scene changed (saved in the Scene tab): its objects' interferences are checked again. */
    reload() {
      if (data && !disposed) reloadInterferences();
    },
    shown(on) {
      // The 3D marks belong to this tab.
      if (!on && chosen) clear();
    },
    dispose() {
      disposed = true;
    },
  };
}
