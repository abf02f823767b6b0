// Scene (issue 29): the model's environment. The scene layer (sceneLayer) loads the stored scene
// and its uploaded meshes once per model view and draws them in the 3D view, which every tab
// shares (model view, motion player, results, live view; attached objects move with their
// body). The Scene tab edits it: add a primitive or import a mesh (uploaded, then an object
// showing it), select an object (its row or a click in 3D), place it with the gizmo (move or
// rotate, both ways in sync with the typed numbers) or by typed numbers (position in metres,
// angles in degrees about x, y, z), snap it onto the surface below it or onto a picked point,
// duplicate, hide or show, delete, undo and redo (buttons, Ctrl+Z, Ctrl+Shift+Z, Ctrl+Y), and
// set its kind (static; moving by a constant velocity or a table of poses; free with its mass
// and inertia), save the whole scene (PUT …/scene); the API's 422 field errors are shown on their
// object (a kind's fields at their control), and
// after saving the interferences of the scene's objects at the CAD pose are listed.

import { STLLoader } from 'three/addons/loaders/STLLoader.js';
import { api, enc } from '../api.js';
import { h, fill, errorBox, num } from '../ui.js';
import {
  PRIMITIVES,
  MESH_FILE_UNITS,
  MESH_FILE_TYPES,
  newObject,
  withPose,
  anglesFromRotation,
  errorsByObject,
  describe,
  duplicateObject,
  meshNameFromFile,
  meshObject,
  sceneInterferences,
  shapeFields,
  withShape,
  OBJECT_KINDS,
  kindForm,
  withKind,
  kindControl,
} from './scene-data.js';
import { placeFieldErrors } from '../field-errors.js';
import { History, historyKey } from './scene-history.js';
import { witnessLine } from './collision-data.js';

const IDENTITY = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];

/**
 * The model's scene in its 3D view: `load()` reads the stored scene and draws it; `draw(objects)`
 * draws an edited one (meshes are fetched once each, GET …/scene/meshes/{name}, and drawn when
 * they arrive); `forget(mesh)` drops a replaced mesh's geometry.
 * @param {string} modelId
 * @param {object} viewer  the model view's Viewer (or its stand-in without WebGL)
 */
export function sceneLayer(modelId, viewer) {
  const base = `/api/models/${enc(modelId)}/scene`;
  const geometries = new Map(); // mesh name → geometry (file units)
  const pending = new Map(); // mesh name → Promise
  let generation = 0;
  let stored = [];
  const loader = new STLLoader();

  function fetchMesh(name) {
    if (!pending.has(name)) {
      pending.set(
        name,
        api(`${base}/meshes/${enc(name)}`, { accept: 'model/stl' })
          .then((bytes) => geometries.set(name, loader.parse(bytes)))
          .catch(() => pending.delete(name)), // drawn as a wire box; tried again at the next draw
      );
    }
    return pending.get(name);
  }

  const layer = {
    /** The scene as last loaded or saved. */
    stored: () => stored,
    async load() {
      stored = (await api(base)).objects;
      layer.draw(stored);
      return stored;
    },
    saved(objects) {
      stored = objects;
      layer.draw(objects);
    },
    draw(objects) {
      const gen = ++generation;
      viewer.setSceneObjects?.(objects, geometries);
      const missing = [...new Set(objects.filter((o) => o.shape.kind === 'mesh' && !geometries.has(o.shape.mesh)).map((o) => o.shape.mesh))];
      if (!missing.length) return Promise.resolve();
      return Promise.all(missing.map(fetchMesh)).then(() => {
        if (gen === generation) viewer.setSceneObjects?.(objects, geometries);
      });
    },
    forget(mesh) {
      geometries.delete(mesh);
      pending.delete(mesh);
    },
  };
  return layer;
}

/** `#rrggbb` of an sRGB colour with components in 0..1, and back (rounded to 1/255). */
const hexOf = (c) => `#${c.map((x) => Math.round(Math.min(1, Math.max(0, x)) * 255).toString(16).padStart(2, '0')).join('')}`;
const rgbOf = (hex) => [1, 3, 5].map((i) => Math.round((parseInt(hex.slice(i, i + 2), 16) / 255) * 1e4) / 1e4);

/** A number as a typed field shows it: rounded to a micrometre or a micro-degree. */
const shown = (x) => String(Math.round(x * 1e6) / 1e6);

/**
 * @param {HTMLElement} panel
 * @param {{modelId: string, versionNumber: number, bodies: string[], viewer: object, layer: object,
 *   select: Function, onSelect: Function, say: Function, sceneSaved?: Function}} ctx
 * @returns {{shown(on: boolean): void, dispose(): void}}
 */
export function renderScene(panel, ctx) {
  const { viewer, layer } = ctx;
  const url = `/api/models/${enc(ctx.modelId)}/scene`;
  let objects = [];
  let errors = new Map();
  let fieldErrors = []; // the last save's 422 errors, as the API gave them
  let dirty = false;
  let disposed = false;
  let visible = true; // the tab is shown
  let selected = null; // the selected object's name
  let gizmo = null;
  let dragBefore = null; // the scene before the running gizmo drag
  let placing = false; // waiting for a click on a surface
  let mode = 'translate';
  let marked = false; // this tab's interference marks are in the 3D view
  const history = new History();

  const list = h('div', { class: 'scene-objects scroll', 'aria-live': 'polite' });
  const editor = h('div', { class: 'scene-editor' });
  const kind = h('select', { 'aria-label': 'Primitive' }, ...Object.keys(PRIMITIVES).map((k) => h('option', { value: k }, k)));
  const add = h('button', { type: 'button' }, 'Add');
  const unit = h('select', { id: 'scene-mesh-unit', 'aria-label': 'Unit of the mesh file' }, ...MESH_FILE_UNITS.map((u) => h('option', { value: u, selected: u === 'mm' }, u)));
  const file = h('input', { type: 'file', id: 'scene-mesh-file', accept: MESH_FILE_TYPES.join(','), 'aria-label': 'Import a mesh (STL, OBJ, COLLADA or VRML)' });
  const undoBtn = h('button', { type: 'button', id: 'scene-undo' }, 'Undo');
  const redoBtn = h('button', { type: 'button', id: 'scene-redo' }, 'Redo');
  const save = h('button', { type: 'button', class: 'primary' }, 'Save scene');
  const status = h('p', { class: 'muted', role: 'status' });
  const interferences = h('div', { class: 'scene-interferences', 'aria-live': 'polite' });
  fill(
    panel,
    h('h2', {}, 'Scene objects'),
    h('p', { class: 'muted' }, 'The machine\'s environment: objects take part in the collision checks and in the package (regenerate it after saving). Select one to place it with the gizmo or by numbers.'),
    h('div', { class: 'scene-add' }, kind, add),
    h('div', { class: 'scene-import' }, h('label', { for: 'scene-mesh-file' }, 'Import a mesh'), h('label', { for: 'scene-mesh-unit' }, 'in'), unit, file),
    h('p', { class: 'muted', id: 'scene-mesh-hint' }, 'STL, OBJ, VRML (.wrl) or COLLADA (.dae). The unit applies to STL, OBJ and VRML; a COLLADA file states its own.'),
    h('div', { class: 'scene-history', role: 'group', 'aria-label': 'Undo and redo' }, undoBtn, ' ', redoBtn),
    list,
    editor,
    h('div', {}, save, status),
    interferences,
  );

  const taken = () => [...objects.map((o) => o.name), ...(ctx.bodies || [])];
  const indexOf = (name) => objects.findIndex((o) => o.name === name);

  /** Takes this tab's interference marks out of the 3D view. */
  function unmark() {
    if (!marked) return;
    marked = false;
    viewer.setContacts?.([], []);
  }

  /** Marks the scene edited and draws it again (list, editor, 3D, gizmo). */
  function changed() {
    unmark();
    dirty = true;
    status.textContent = 'Unsaved changes';
    layer.draw(objects);
    render();
    syncGizmo();
  }

  /** An edit that can be undone: `fn` changes `objects`. */
  function edit(label, fn) {
    const before = structuredClone(objects);
    fn();
    history.record(before, label);
    changed();
  }

  function step(which) {
    const r = which === 'undo' ? history.undo(objects) : history.redo(objects);
    if (!r) return;
    objects = r.state;
    if (selected && indexOf(selected) < 0) selectObject(null);
    errors = new Map();
    fieldErrors = [];
    changed();
    ctx.say?.(`${which === 'undo' ? 'Undone' : 'Redone'}: ${r.label}`, 'info');
  }

  function selectObject(name) {
    if (name) ctx.select?.({ kind: 'object', name }, { scroll: false });
    else if (selected) ctx.select?.(null);
  }

  // A selection anywhere (a row here, a click in 3D): an object is edited, anything else ends it.
  ctx.onSelect?.((sel) => {
    if (disposed) return;
    const name = sel?.kind === 'object' ? sel.name : null;
    if (name === selected) return;
    selected = name;
    cancelPlacing();
    render();
    syncGizmo();
  });

  function row(o, k) {
    const on = o.name === selected;
    const vis = h('input', { type: 'checkbox', checked: o.visible !== false, 'aria-label': `${o.name} visible` });
    vis.addEventListener('change', () => edit(`${vis.checked ? 'show' : 'hide'} ${o.name}`, () => (objects[k] = { ...objects[k], visible: vis.checked })));
    const problems = errors.get(k) || [];
    return h(
      'tr',
      { 'data-object': o.name, class: on ? 'selected' : '' },
      h('td', {}, h('button', { type: 'button', class: 'pick', 'aria-pressed': String(on), onclick: () => selectObject(on ? null : o.name) }, o.name)),
      h('td', {}, describe(o), ...problems.map((p) => h('div', { class: 'error', role: 'alert' }, p))),
      h('td', {}, vis),
    );
  }

  let posInputs = [];
  let rotInputs = [];

  /** The typed numbers show object `o`'s pose (after a gizmo drag, a snap, an undo). */
  function showPose(o) {
    const angles = anglesFromRotation(o.rotation || IDENTITY);
    posInputs.forEach((i, k) => (i.value = shown(o.position[k])));
    rotInputs.forEach((i, k) => (i.value = shown(angles[k])));
  }

  function renderEditor() {
    const k = indexOf(selected);
    if (k < 0) {
      fill(editor, objects.length ? h('p', { class: 'muted' }, 'Select an object to place it.') : null);
      posInputs = [];
      rotInputs = [];
      return;
    }
    const o = objects[k];
    const inputs = (label) => [0, 1, 2].map((i) => h('input', { type: 'text', inputmode: 'decimal', size: 7, 'aria-label': `${o.name} ${label} ${'xyz'[i]}` }));
    posInputs = inputs('position');
    rotInputs = inputs('angle about');
    showPose(o);
    const note = h('div', { class: 'error', role: 'alert', hidden: true });
    const apply = h('button', { type: 'button' }, 'Apply pose');
    apply.addEventListener('click', () => {
      const r = withPose(objects[k], posInputs.map((i) => i.value), rotInputs.map((i) => i.value));
      if (r.error) {
        fill(note, r.error);
        note.hidden = false;
        return;
      }
      edit(`set the pose of ${o.name}`, () => (objects[k] = r.object));
    });
    for (const i of [...posInputs, ...rotInputs]) i.addEventListener('keydown', (e) => e.key === 'Enter' && apply.click());
    // The primitive's dimensions (m): applied on their own (an undoable edit).
    const dims = shapeFields(o.shape).map((f) => h('input', { type: 'text', inputmode: 'decimal', size: 7, value: shown(f.value), 'aria-label': `${o.name} ${f.label}` }));
    const resize = h('button', { type: 'button' }, 'Apply size');
    resize.addEventListener('click', () => {
      const r = withShape(objects[k], dims.map((i) => i.value));
      if (r.error) {
        fill(note, r.error);
        note.hidden = false;
        return;
      }
      edit(`resize ${o.name}`, () => (objects[k] = r.object));
    });
    for (const i of dims) i.addEventListener('keydown', (e) => e.key === 'Enter' && resize.click());
    const sizeRow = dims.length
      ? h('div', { class: 'scene-pose' }, h('span', {}, `${shapeFields(o.shape).map((f) => f.label).join(', ')} (m)`), ...dims, resize)
      : null;
    const modeSel = h(
      'select',
      { id: 'scene-gizmo-mode', 'aria-label': 'Gizmo' },
      h('option', { value: 'translate', selected: mode === 'translate' }, 'Move'),
      h('option', { value: 'rotate', selected: mode === 'rotate' }, 'Rotate'),
    );
    modeSel.addEventListener('change', () => {
      mode = modeSel.value;
      gizmo?.setMode(mode);
    });
    const frame = o.attached_to ? `in ${o.attached_to}'s frame` : 'in the world';
    // Attached to a body (static objects): it keeps its place in the world and moves with the body.
    const attach = h(
      'select',
      { id: 'scene-attach', 'aria-label': `${o.name} attached to`, disabled: (o.kind || 'static') !== 'static' },
      h('option', { value: '' }, 'the world'),
      ...(ctx.bodies || []).map((b) => h('option', { value: b, selected: b === o.attached_to }, b)),
    );
    // Its colour (sRGB 0..1 in the API; the 3D view's default grey-blue when none).
    const colour = h('input', { type: 'color', id: 'scene-colour', 'aria-label': `${o.name} colour`, value: hexOf(o.color || [0.62, 0.66, 0.72]) });
    colour.addEventListener('change', () => edit(`colour ${o.name}`, () => (objects[k] = { ...objects[k], color: rgbOf(colour.value) })));
    attach.addEventListener('change', () => {
      const world = viewer.objectWorldPose?.(o.name);
      const to = attach.value || null;
      let pose = { position: o.position, rotation: o.rotation || IDENTITY };
      if (world) pose = viewer.localPoseIn?.(to, world) || pose;
      edit(to ? `attach ${o.name} to ${to}` : `detach ${o.name}`, () => {
        const next = { ...objects[k], position: pose.position, rotation: pose.rotation };
        if (to) next.attached_to = to;
        else delete next.attached_to;
        objects[k] = next;
      });
    });
    // Its kind (an undoable edit): static; moving by a constant velocity or a table of poses;
    // free with its mass and inertia. The last save's 422 errors show at their control.
    const kf = kindForm(o);
    const placed = placeFieldErrors(fieldErrors, (f) => kindControl(f, k)).at;
    const at = (key) => (placed.get(key) || []).map((m) => h('div', { class: 'error', role: 'alert', 'data-field': key }, m));
    const num3 = (label, values, unitHint) =>
      [0, 1, 2].map((i) => h('input', { type: 'text', inputmode: 'decimal', size: 6, value: values[i], placeholder: unitHint, 'aria-label': `${o.name} ${label} ${i + 1}` }));
    const kindSel = h(
      'select',
      { id: 'scene-kind', 'aria-label': `${o.name} kind`, disabled: o.shape.kind === 'plane' || !!o.attached_to, title: o.attached_to ? 'Attached objects are static' : null },
      ...OBJECT_KINDS.map((x) => h('option', { value: x, selected: x === kf.kind }, x)),
    );
    const motionSel = h(
      'select',
      { id: 'scene-motion', 'aria-label': `${o.name} motion` },
      h('option', { value: 'velocity', selected: kf.motion === 'velocity' }, 'constant velocity'),
      h('option', { value: 'poses', selected: kf.motion === 'poses' }, 'table of poses'),
    );
    const vel = num3('velocity', kf.velocity);
    const poses = h('textarea', { id: 'scene-poses', rows: 4, cols: 30, spellcheck: 'false', 'aria-label': `${o.name} poses` });
    poses.value = kf.poses;
    const mass = h('input', { type: 'text', inputmode: 'decimal', size: 6, value: kf.mass, 'aria-label': `${o.name} mass` });
    const inertia = num3('inertia', kf.inertia, 'auto');
    const motionRow = h('div', { class: 'scene-actions' }, h('label', { for: 'scene-motion' }, 'Motion'), motionSel, ...at('motion'));
    const velRow = h('div', { class: 'scene-pose' }, h('span', {}, 'Velocity x, y, z (m/s) '), ...vel, ...at('velocity'));
    const posesRow = h('div', { class: 'scene-pose' }, h('label', { for: 'scene-poses' }, 'Poses, a row per line: time (s) x y z (m), optionally angles about x y z (°) '), poses, ...at('poses'));
    const massRow = h('div', { class: 'scene-pose' }, h('span', {}, 'Mass (kg) '), mass, h('span', {}, ' principal inertia (kg·m², blank: solid shape) '), ...inertia, ...at('mass'), ...at('inertia'));
    const showKind = () => {
      const kd = kindSel.value;
      motionRow.hidden = kd !== 'moving';
      velRow.hidden = kd !== 'moving' || motionSel.value !== 'velocity';
      posesRow.hidden = kd !== 'moving' || motionSel.value !== 'poses';
      massRow.hidden = kd !== 'free';
    };
    kindSel.addEventListener('change', showKind);
    motionSel.addEventListener('change', showKind);
    showKind();
    const applyKind = h('button', { type: 'button', id: 'scene-apply-kind' }, 'Apply kind');
    applyKind.addEventListener('click', () => {
      const form = { kind: kindSel.value, motion: motionSel.value, velocity: vel.map((i) => i.value), poses: poses.value, mass: mass.value, inertia: inertia.map((i) => i.value) };
      const r = withKind(objects[k], form);
      if (r.error) {
        fill(note, r.error);
        note.hidden = false;
        return;
      }
      edit(`make ${o.name} ${form.kind}`, () => (objects[k] = r.object));
    });
    for (const i of [...vel, mass, ...inertia]) i.addEventListener('keydown', (e) => e.key === 'Enter' && applyKind.click());
    fill(
      editor,
      h('h3', {}, `${o.name} `, h('small', { class: 'muted' }, frame)),
      h('div', { class: 'scene-pose' }, h('span', {}, 'Position x, y, z (m) '), ...posInputs),
      h('div', { class: 'scene-pose' }, h('span', {}, 'Angles about x, y, z (°) '), ...rotInputs),
      h('div', { class: 'scene-actions' }, apply, ' ', h('label', { for: 'scene-gizmo-mode' }, 'Gizmo '), modeSel),
      sizeRow,
      h('div', { class: 'scene-actions' }, h('label', { for: 'scene-attach' }, 'Attached to'), attach, h('label', { for: 'scene-colour' }, 'Colour'), colour),
      h('div', { class: 'scene-actions scene-kind' }, h('label', { for: 'scene-kind' }, 'Kind'), kindSel, ' ', applyKind, ...at('kind')),
      motionRow,
      velRow,
      posesRow,
      massRow,
      h(
        'div',
        { class: 'scene-actions' },
        h('button', { type: 'button', onclick: () => duplicate(k) }, 'Duplicate'),
        ' ',
        h('button', { type: 'button', onclick: () => drop(k), title: 'Move it down (along gravity) until it rests on the model or another object' }, 'Drop onto surface'),
        ' ',
        h('button', { type: 'button', id: 'scene-place', 'aria-pressed': String(placing), onclick: () => place(k) }, placing ? 'Click a surface…' : 'Place on picked point'),
        ' ',
        h('button', { type: 'button', class: 'danger', onclick: () => remove(k) }, 'Delete'),
      ),
      note,
    );
  }

  function render() {
    if (disposed) return;
    undoBtn.disabled = !history.canUndo;
    redoBtn.disabled = !history.canRedo;
    undoBtn.title = history.canUndo ? `Undo: ${history.undoLabel} (Ctrl+Z)` : 'Nothing to undo';
    redoBtn.title = history.canRedo ? `Redo: ${history.redoLabel} (Ctrl+Shift+Z or Ctrl+Y)` : 'Nothing to redo';
    const general = errors.get(-1) || [];
    if (!objects.length) {
      fill(list, h('p', { class: 'muted' }, 'No scene objects yet: add a primitive or import a mesh.'), ...general.map((g) => h('p', { class: 'error' }, g)));
    } else {
      fill(
        list,
        ...general.map((g) => h('p', { class: 'error', role: 'alert' }, g)),
        h(
          'table',
          { class: 'scene-table', 'aria-label': 'Scene objects' },
          h('thead', {}, h('tr', {}, h('th', {}, 'Name'), h('th', {}, 'Shape'), h('th', {}, 'Visible'))),
          h('tbody', {}, ...objects.map(row)),
        ),
      );
    }
    renderEditor();
  }

  // ---------------------------------------------------------------- the gizmo
  function syncGizmo() {
    const world = visible && selected && objects[indexOf(selected)]?.visible !== false ? viewer.objectWorldPose?.(selected) : null;
    if (!world) {
      // (Another tab's gizmo may have replaced ours: that one stays.)
      if (gizmo && viewer.gizmo === gizmo) gizmo.dispose();
      gizmo = null;
      return;
    }
    if (gizmo && viewer.gizmo === gizmo) {
      gizmo.setPose(world);
      return;
    }
    const name = selected;
    gizmo = viewer.showGizmo(world, {
      onDrag: (m) => {
        const k = indexOf(name);
        if (k < 0) return;
        dragBefore ||= structuredClone(objects);
        const p = viewer.objectLocalPose(name, m);
        objects[k] = { ...objects[k], position: p.position, rotation: p.rotation };
        viewer.setSceneObjectPose(name, p.position, p.rotation);
        if (name === selected) showPose(objects[k]);
      },
      onEnd: () => {
        if (!dragBefore) return;
        history.record(dragBefore, `${mode === 'rotate' ? 'rotate' : 'move'} ${name} with the gizmo`);
        dragBefore = null;
        dirty = true;
        status.textContent = 'Unsaved changes';
        errors = new Map();
        fieldErrors = [];
        render();
      },
    });
    gizmo?.setMode(mode);
  }

  // ---------------------------------------------------------------- actions
  add.addEventListener('click', () => {
    const o = newObject(kind.value, taken());
    edit(`add ${o.name}`, () => objects.push(o));
    selectObject(o.name);
  });

  function duplicate(k) {
    const o = objects[k];
    const box = viewer.objectBox?.(o.name);
    const w = box && !box.isEmpty() ? (box.max.x - box.min.x) * 1.25 : 0.1;
    const copy = duplicateObject(o, taken(), [Math.min(w, 10), 0, 0]);
    edit(`duplicate ${o.name} as ${copy.name}`, () => objects.splice(k + 1, 0, copy));
    selectObject(copy.name);
  }

  function remove(k) {
    const name = objects[k].name;
    selectObject(null);
    edit(`delete ${name}`, () => objects.splice(k, 1));
    errors = new Map();
    fieldErrors = [];
  }

  function drop(k) {
    const o = objects[k];
    const d = viewer.dropDistance?.(o.name);
    if (!d) {
      ctx.say?.(`Nothing below ${o.name} to rest on`, 'info');
      return;
    }
    const up = viewer.up.toArray();
    const p = viewer.objectPoseMovedBy(o.name, up.map((x) => -x * d.distance));
    edit(`drop ${o.name} onto ${d.onto.name}`, () => (objects[k] = { ...objects[k], position: p.position, rotation: p.rotation }));
    ctx.say?.(`${o.name} rests on ${d.onto.name} (moved ${num(d.distance)} m down)`, 'info');
  }

  function cancelPlacing() {
    if (!placing) return;
    placing = false;
    viewer.cancelSurfacePick?.();
  }

  function place(k) {
    if (placing) {
      cancelPlacing();
      render();
      return;
    }
    const name = objects[k].name;
    placing = true;
    viewer.pickSurface?.(name, (hit) => {
      placing = false;
      const j = indexOf(name);
      if (disposed || j < 0) return;
      if (!hit) {
        render();
        ctx.say?.('No surface there: click on the model or another object', 'info');
        return;
      }
      // The object's underside (the middle of its box's bottom) goes to the picked point.
      const foot = viewer.objectFoot(name);
      const p = viewer.objectPoseMovedBy(name, hit.point.map((x, i) => x - foot[i]));
      edit(`place ${name} on ${hit.object.name}`, () => (objects[j] = { ...objects[j], position: p.position, rotation: p.rotation }));
      ctx.say?.(`${name} placed on ${hit.object.name}`, 'info');
    });
    render();
    ctx.say?.(`Click a surface in the 3D view to place ${name} on it`, 'info');
  }

  file.addEventListener('change', async () => {
    const f = file.files?.[0];
    if (!f) return;
    const named = meshNameFromFile(f.name);
    if (named.error) {
      fill(status, h('span', { class: 'error', role: 'alert' }, named.error));
      file.value = '';
      return;
    }
    status.textContent = `Uploading ${f.name}…`;
    try {
      const stored = await api(`${url}/meshes/${enc(named.name)}?file=${encodeURIComponent(f.name)}`, { method: 'PUT', body: await f.arrayBuffer() });
      layer.forget(stored.name);
      const o = meshObject(stored.name, named.unit || unit.value, taken());
      edit(`import ${f.name} as ${o.name}`, () => objects.push(o));
      selectObject(o.name);
      status.textContent = `Imported ${f.name} (${stored.triangles} triangles) as ${o.name}: unsaved`;
    } catch (e) {
      fill(status, errorBox(e, `${f.name} could not be imported`));
    } finally {
      file.value = '';
    }
  });

  undoBtn.addEventListener('click', () => step('undo'));
  redoBtn.addEventListener('click', () => step('redo'));
  const onKey = (e) => {
    if (!visible || disposed || panel.hidden) return;
    const t = e.target;
    const typing = t instanceof HTMLElement && (t.isContentEditable || t.tagName === 'TEXTAREA' || (t.tagName === 'INPUT' && !['checkbox', 'radio', 'button', 'file'].includes(t.type)));
    const what = historyKey(e, typing);
    if (!what) return;
    e.preventDefault();
    step(what);
  };
  document.addEventListener('keydown', onKey);

  save.addEventListener('click', async () => {
    save.disabled = true;
    try {
      const stored = await api(url, { method: 'PUT', body: { objects } });
      objects = stored.objects;
      errors = new Map();
      fieldErrors = [];
      dirty = false;
      status.textContent = 'Saved';
      layer.saved(objects);
      ctx.say?.('Scene saved');
      ctx.sceneSaved?.();
      checkInterferences();
    } catch (e) {
      errors = errorsByObject(e.errors);
      fieldErrors = e.errors || [];
      if (!errors.size) fill(status, errorBox(e, 'The scene could not be saved'));
      else status.textContent = 'Not saved: see the errors';
    } finally {
      save.disabled = false;
      render();
      syncGizmo();
    }
  });

  /** The saved scene's interferences at the CAD pose (the Collision tab lists them too). */
  async function checkInterferences() {
    fill(interferences, h('p', { role: 'status' }, 'Checking the CAD pose…'));
    let data;
    try {
      data = await api(`/api/models/${enc(ctx.modelId)}/versions/${ctx.versionNumber}/collision`);
    } catch (e) {
      fill(interferences, errorBox(e, 'The interferences could not be checked'));
      return;
    }
    if (disposed) return;
    const found = sceneInterferences(data.interferences, objects);
    // In 3D too: the touching objects and bodies tinted, a line between each pair's witness points.
    const touching = (data.interferences || []).filter((i) => found.some((f) => (f.object === i.a && f.other === i.b) || (f.object === i.b && f.other === i.a)));
    if (touching.length && visible && !dirty) {
      viewer.setContacts?.([...new Set(touching.flatMap((i) => [i.a, i.b]))], touching.map(witnessLine));
      marked = true;
    }
    fill(
      interferences,
      h('h3', {}, 'Interferences of the saved scene at the CAD pose'),
      found.length
        ? h(
            'ul',
            { class: 'picklist scene-interference-list', 'aria-label': 'Interferences of scene objects' },
            ...found.map((i) => h('li', { 'data-object': i.object, 'data-other': i.other }, `${i.object} touches ${i.other}`, h('span', { class: 'muted' }, ` depth ${num(i.depth * 1000)} mm`))),
          )
        : h('p', { class: 'muted no-interference' }, 'None: no scene object intersects the model or another object.'),
    );
  }

  (async () => {
    fill(list, h('p', { role: 'status' }, 'Loading the scene…'));
    try {
      objects = structuredClone(await (ctx.loaded || layer.load()));
    } catch (e) {
      fill(list, errorBox(e, 'The scene could not be loaded'));
      return;
    }
    if (!dirty) render();
  })();

  return {
    shown(on) {
      visible = on;
      // Objects are edited at their pose at the start (a moving one's motion starts there).
      if (on) viewer.setSceneTime?.(0);
      if (!on) {
        cancelPlacing();
        unmark();
      }
      syncGizmo();
    },
    dispose() {
      disposed = true;
      document.removeEventListener('keydown', onKey);
      cancelPlacing();
      if (gizmo && viewer.gizmo === gizmo) gizmo.dispose();
    },
  };
}
