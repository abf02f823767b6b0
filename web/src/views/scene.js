// Scene (issue 29): the model's environment. Lists the scene objects, adds a primitive, edits an
// object's pose by typed numbers (position in metres, angles in degrees about x, y, z), deletes,
// and saves the whole scene (PUT …/scene); the API's 422 field errors are shown on their object.
// Not yet here: the 3D drawing, the gizmo, mesh import, undo/redo.

import { api, enc } from '../api.js';
import { h, fill, errorBox } from '../ui.js';
import { PRIMITIVES, newObject, withPose, anglesFromRotation, errorsByObject, describe } from './scene-data.js';

/**
 * @param {HTMLElement} panel
 * @param {{modelId: string, bodies: string[], say: Function}} ctx
 * @returns {{dispose(): void}}
 */
export function renderScene(panel, ctx) {
  const url = `/api/models/${enc(ctx.modelId)}/scene`;
  let objects = [];
  let errors = new Map();
  let dirty = false;
  let disposed = false;
  const list = h('div', { class: 'scene-objects', 'aria-live': 'polite' });
  const kind = h('select', { 'aria-label': 'Primitive' }, ...Object.keys(PRIMITIVES).map((k) => h('option', { value: k }, k)));
  const add = h('button', { type: 'button' }, 'Add');
  const save = h('button', { type: 'button', class: 'primary' }, 'Save scene');
  const status = h('p', { class: 'muted', role: 'status' });
  fill(
    panel,
    h('h2', {}, 'Scene objects'),
    h('p', { class: 'muted' }, 'The machine\'s environment: objects take part in the collision checks and in the package (regenerate it after saving).'),
    h('div', { class: 'scene-add' }, kind, add),
    list,
    h('div', {}, save, status),
  );

  function changed() {
    dirty = true;
    status.textContent = 'Unsaved changes';
    render();
  }

  function row(o, k) {
    const angles = anglesFromRotation(o.rotation || [[1, 0, 0], [0, 1, 0], [0, 0, 1]]).map((a) => String(Math.round(a * 1e6) / 1e6));
    const inputs = (vals, label) => vals.map((v, i) => h('input', { type: 'text', inputmode: 'decimal', size: 7, value: String(v), 'aria-label': `${o.name} ${label} ${'xyz'[i]}` }));
    const pos = inputs(o.position, 'position');
    const rot = inputs(angles, 'angle about');
    const apply = h('button', { type: 'button' }, 'Apply pose');
    const del = h('button', { type: 'button', class: 'danger' }, 'Delete');
    const problems = errors.get(k) || [];
    const note = h('span', { class: 'error', role: 'alert' }, ...problems.map((p) => h('div', {}, p)));
    apply.addEventListener('click', () => {
      const r = withPose(o, pos.map((i) => i.value), rot.map((i) => i.value));
      if (r.error) {
        fill(note, r.error);
        return;
      }
      objects[k] = r.object;
      changed();
    });
    del.addEventListener('click', () => {
      objects.splice(k, 1);
      errors = new Map();
      changed();
    });
    return h('tr', { 'data-object': o.name },
      h('td', {}, h('code', {}, o.name)),
      h('td', {}, describe(o)),
      h('td', {}, 'x, y, z (m) ', ...pos),
      h('td', {}, 'about x, y, z (°) ', ...rot),
      h('td', {}, apply, ' ', del, note));
  }

  function render() {
    if (disposed) return;
    const general = errors.get(-1) || [];
    if (!objects.length) {
      fill(list, h('p', { class: 'muted' }, 'No scene objects yet: add a primitive.'), ...general.map((g) => h('p', { class: 'error' }, g)));
      return;
    }
    fill(list,
      ...general.map((g) => h('p', { class: 'error', role: 'alert' }, g)),
      h('table', {}, h('thead', {}, h('tr', {}, h('th', {}, 'Name'), h('th', {}, 'Shape'), h('th', {}, 'Position'), h('th', {}, 'Rotation'), h('th', {}))),
        h('tbody', {}, ...objects.map(row))));
  }

  add.addEventListener('click', () => {
    objects.push(newObject(kind.value, [...objects.map((o) => o.name), ...(ctx.bodies || [])]));
    changed();
  });
  save.addEventListener('click', async () => {
    save.disabled = true;
    try {
      const stored = await api(url, { method: 'PUT', body: { objects } });
      objects = stored.objects;
      errors = new Map();
      dirty = false;
      status.textContent = 'Saved';
      ctx.say?.('Scene saved');
    } catch (e) {
      errors = errorsByObject(e.errors);
      if (!errors.size) fill(status, errorBox(e, 'The scene could not be saved'));
      else status.textContent = 'Not saved: see the errors';
    } finally {
      save.disabled = false;
      render();
    }
  });

  (async () => {
    fill(list, h('p', { role: 'status' }, 'Loading the scene…'));
    try {
      objects = (await api(url)).objects;
    } catch (e) {
      fill(list, errorBox(e, 'The scene could not be loaded'));
      return;
    }
    if (!dirty) render();
  })();

  return { dispose() { disposed = true; } };
}
