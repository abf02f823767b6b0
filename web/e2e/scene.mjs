// The Scene tab (issue 29), end to end (part of ui.mjs, on the model view of the uploaded arm):
// add a box (drawn in the 3D view, selected, with the gizmo), move it with the gizmo by a real
// mouse drag on the canvas (on the gizmo's x handle, found in the three.js scene and projected
// to the screen; the typed numbers follow during the drag), set a pose inside a link by typed
// numbers (the gizmo follows), undo twice and redo twice (button, Ctrl+Z, Ctrl+Shift+Z, Ctrl+Y:
// the typed numbers and the drawn box go back and forth), turn it with the gizmo's rotate ring
// (a real drag too: the typed angles follow), save, and see the interference of the box with the
// link named in the Scene tab and the Collision tab and marked in 3D. Then: duplicate, hide and
// undo, drop onto the surface below, attach to a link and follow it, import a mesh (STL in mm)
// and put it on a point picked in 3D, delete and undo, resize by numbers (0 refused, naming the
// field), make box1 moving at a velocity (a refused speed shown at its field, undo and redo),
// save, reload the page and find the values back. The scene is removed at the end (later steps
// expect none).

import assert from 'node:assert/strict';
import { rotationFromAngles } from '../src/views/scene-data.js';
import { waitForModel } from './lib.mjs';

const H = { 'X-Requested-With': 'cad2mo' };

/** The box as drawn: its frame's origin in the world (m) and whether it is visible. */
function drawn(page, name) {
  return page.evaluate((n) => {
    const e = window.cad2moViewer.sceneObjects.get(n);
    if (!e) return null;
    e.mesh.updateWorldMatrix(true, false); // its body's matrix first (the view updates it when it draws)
    const m = e.mesh.matrixWorld.elements;
    return { origin: [m[12], m[13], m[14]], visible: e.mesh.visible, gizmo: !!window.cad2moViewer.gizmo };
  }, name);
}

/**
 * Waits until object `name` is drawn away from (`away`) or back at `at` (by 1 mm, resp. 1e-9 m);
 * the drawn origin then, or null after 5 s.
 */
async function awayFrom(page, name, at, away) {
  const ok = await page
    .waitForFunction(
      ({ n, p, away }) => {
        const e = window.cad2moViewer.sceneObjects.get(n);
        e.mesh.updateWorldMatrix(true, false);
        const m = e.mesh.matrixWorld.elements;
        const d = Math.hypot(m[12] - p[0], m[13] - p[1], m[14] - p[2]);
        return (away ? d > 1e-3 : d < 1e-9) && [m[12], m[13], m[14]];
      },
      { n: name, p: at, away },
      { timeout: 5000 },
    )
    .catch(() => null);
  return ok ? ok.jsonValue() : null;
}

/** The typed position numbers of the selected object. */
async function typed(page, name) {
  const out = [];
  for (const a of 'xyz') out.push(Number(await page.getByLabel(`${name} position ${a}`, { exact: true }).inputValue()));
  return out;
}

/** An ASCII STL cube of edge `edge` (file units) centred on its origin: 12 triangles. */
function cubeStl(edge) {
  const h = edge / 2;
  const c = (i) => [i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h];
  const faces = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
  let s = 'solid cube\n';
  for (const f of faces) {
    for (const t of [[f[0], f[1], f[2]], [f[0], f[2], f[3]]]) s += `facet normal 0 0 0\nouter loop\n${t.map((k) => `vertex ${c(k).join(' ')}\n`).join('')}endloop\nendfacet\n`;
  }
  return `${s}endsolid cube\n`;
}

const near = (a, b, tol) => a.every((x, i) => Math.abs(x - b[i]) <= tol);

/**
 * @param {import('playwright-core').Page} page  on the model view of the arm (its latest version)
 * @param {{step: Function, shot: Function}} o
 */
export async function sceneSteps(page, { step, shot }) {
  const [, , id, , v] = new URL(page.url()).hash.split('/');
  const t0 = Date.now();

  // ---- Add a box: listed, drawn at the origin, selected with the gizmo on it.
  step('scene: add a box');
  // The model at its CAD pose (earlier steps moved it): the interferences are checked there.
  await page.getByRole('button', { name: 'Reset pose' }).click();
  await page.getByRole('tab', { name: 'Scene', exact: true }).click();
  const panel = page.locator('#panel-scene');
  await panel.getByText('No scene objects yet').waitFor();
  await panel.getByLabel('Primitive').selectOption('box');
  await panel.getByRole('button', { name: 'Add', exact: true }).click();
  await panel.locator('tr[data-object="box1"].selected').waitFor();
  let box = await drawn(page, 'box1');
  assert.ok(box && box.visible && box.gizmo && near(box.origin, [0, 0, 0], 1e-12), `box1 drawn at the origin with the gizmo: ${JSON.stringify(box)}`);

  // ---- Move it with the gizmo: a real drag on the canvas from its x handle along +x on screen.
  step('scene: gizmo drag');
  const handle = await page.evaluate(() => {
    const v = window.cad2moViewer;
    const tc = v.gizmo.controls;
    v.render();
    tc.getHelper().updateMatrixWorld(true);
    // TransformControls' invisible picker for the x arrow of its translate mode.
    const x = tc._gizmo.picker.translate.children.find((o) => o.name === 'X');
    // Its offset from the gizmo's centre is in its geometry: the middle of its box, in the world.
    x.updateWorldMatrix(true, false);
    x.geometry.computeBoundingBox();
    const p = x.geometry.boundingBox.getCenter(v.gizmo.target.position.clone()).applyMatrix4(x.matrixWorld);
    const origin = v.gizmo.target.position.toArray();
    const a = v.toScreen(origin);
    const b = v.toScreen([origin[0] + 0.05, origin[1], origin[2]]);
    const len = Math.hypot(b.x - a.x, b.y - a.y);
    return { at: v.toScreen(p.toArray()), dir: { x: (b.x - a.x) / len, y: (b.y - a.y) / len } };
  });
  const canvas = await page.locator('.stage canvas').boundingBox();
  const sx = canvas.x + handle.at.x;
  const sy = canvas.y + handle.at.y;
  await page.mouse.move(sx, sy);
  await page.mouse.move(sx + 1, sy);
  assert.equal(await page.evaluate(() => window.cad2moViewer.gizmo.controls.axis), 'X', `the pointer is on the gizmo's x handle: ${JSON.stringify(handle)}`);
  await page.mouse.down();
  await page.mouse.move(sx + handle.dir.x * 40, sy + handle.dir.y * 40, { steps: 5 });
  // While the button is still down, the typed numbers already follow.
  const midway = await typed(page, 'box1');
  assert.ok(midway[0] > 0.005, `the typed x follows the gizmo during the drag: ${midway}`);
  await page.mouse.move(sx + handle.dir.x * 80, sy + handle.dir.y * 80, { steps: 5 });
  await page.mouse.up();
  const dragged = await typed(page, 'box1');
  assert.ok(dragged[0] > 0.01 && Math.abs(dragged[1]) < 1e-9 && Math.abs(dragged[2]) < 1e-9, `the gizmo moved box1 along +x only: ${dragged}`);
  box = await drawn(page, 'box1');
  assert.ok(near(box.origin, dragged, 1e-6), `the typed numbers follow the gizmo: ${dragged} vs drawn ${box.origin}`);
  await shot(page, '34-scene-gizmo');

  // ---- Typed numbers: into the middle of a link (its mesh box at the CAD pose).
  step('scene: typed pose');
  const link = await page.evaluate(() => {
    const v = window.cad2moViewer;
    let best = null;
    for (const [name, b] of v.bodies) {
      const mesh = b.group.children.find((c) => c.isMesh && c.userData.pick?.kind === 'body');
      if (!mesh) continue;
      mesh.geometry.computeBoundingBox();
      const { min, max } = mesh.geometry.boundingBox;
      const c = [(min.x + max.x) / 2, (min.y + max.y) / 2, (min.z + max.z) / 2];
      const e = b.cad.elements;
      const w = [0, 1, 2].map((i) => e[i] * c[0] + e[4 + i] * c[1] + e[8 + i] * c[2] + e[12 + i]);
      const size = Math.hypot(max.x - min.x, max.y - min.y, max.z - min.z);
      if (!best || size > best.size) best = { name, centre: w, size };
    }
    return best;
  });
  const target = link.centre.map((x) => Math.round(x * 1e4) / 1e4);
  for (const [k, a] of [...'xyz'].entries()) await page.getByLabel(`box1 position ${a}`, { exact: true }).fill(String(target[k]));
  // Turned 30° about y (the arm's "up"): its footprint stays level.
  await page.getByLabel('box1 angle about y', { exact: true }).fill('30');
  await page.getByRole('button', { name: 'Apply pose' }).click();
  await page.waitForFunction((t) => {
    const e = window.cad2moViewer.sceneObjects.get('box1');
    return e && Math.abs(e.mesh.matrix.elements[12] - t[0]) < 1e-9 && Math.abs(e.mesh.matrix.elements[14] - t[2]) < 1e-9;
  }, target);
  assert.ok(near((await drawn(page, 'box1')).origin, target, 1e-9), 'the box is drawn at the typed position');
  // The gizmo follows the typed numbers: at the position, turned 30° about y.
  const g = await page.evaluate(() => {
    const t = window.cad2moViewer.gizmo.target;
    return { p: t.position.toArray(), q: t.quaternion.toArray() };
  });
  const half = (15 * Math.PI) / 180;
  assert.ok(near(g.p, target, 1e-9) && near(g.q, [0, Math.sin(half), 0, Math.cos(half)], 1e-9), `the gizmo at the typed pose: ${JSON.stringify(g)}`);

  // ---- Undo and redo: the numbers and the drawn box go back and forth.
  step('scene: undo and redo');
  const expectAt = async (want, what) => {
    const got = await typed(page, 'box1');
    assert.ok(near(got, want, 1e-6), `${what}: typed ${got}, expected ${want}`);
    assert.ok(near((await drawn(page, 'box1')).origin, want, 1e-6), `${what}: drawn ${(await drawn(page, 'box1')).origin}, expected ${want}`);
  };
  await page.getByRole('button', { name: 'Undo', exact: true }).click();
  await expectAt(dragged, 'undo the typed pose');
  await page.getByRole('button', { name: 'Undo', exact: true }).focus();
  await page.keyboard.press('Control+z');
  await expectAt([0, 0, 0], 'Ctrl+Z: undo the gizmo drag');
  await page.keyboard.press('Control+Shift+z');
  await expectAt(dragged, 'Ctrl+Shift+Z: redo the gizmo drag');
  await page.keyboard.press('Control+y');
  await expectAt(target, 'Ctrl+Y: redo the typed pose');
  assert.equal(await page.getByRole('button', { name: 'Redo', exact: true }).isDisabled(), true, 'nothing more to redo');

  // ---- The gizmo's rotate mode: a real drag along its y ring (the arm's "up") turns the box
  // about y only; the typed angles follow, the position stays.
  step('scene: gizmo rotate');
  await panel.getByLabel('Gizmo', { exact: true }).selectOption('rotate');
  // Points on the y ring's centre line (its picker: a torus of radius 0.5 in the handle's xz
  // plane) with the ring's tangent there, on screen; the first the gizmo takes as its y handle.
  const ringPoints = await page.evaluate(() => {
    const v = window.cad2moViewer;
    v.render();
    const y = v.gizmo.controls._gizmo.picker.rotate.children.find((o) => o.name === 'Y');
    y.updateWorldMatrix(true, false);
    y.geometry.computeBoundingBox();
    const { min, max } = y.geometry.boundingBox;
    const V = v.gizmo.target.position.constructor;
    const c = new V((min.x + max.x) / 2, (min.y + max.y) / 2, (min.z + max.z) / 2);
    const r = (max.x - min.x) / 2 - 0.1;
    const out = [];
    for (let k = 0; k < 12; k++) {
      const a = (k * Math.PI) / 6;
      const on = new V(c.x + r * Math.cos(a), c.y, c.z + r * Math.sin(a)).applyMatrix4(y.matrixWorld);
      const ahead = new V(c.x + r * Math.cos(a) - 0.2 * Math.sin(a), c.y, c.z + r * Math.sin(a) + 0.2 * Math.cos(a)).applyMatrix4(y.matrixWorld);
      const p = v.toScreen(on.toArray());
      const q = v.toScreen(ahead.toArray());
      const len = Math.hypot(q.x - p.x, q.y - p.y);
      if (len > 1e-6) out.push({ at: p, dir: { x: (q.x - p.x) / len, y: (q.y - p.y) / len } });
    }
    return out;
  });
  let ring = null;
  const view = await page.locator('.stage canvas').boundingBox(); // where the canvas is now
  for (const p of ringPoints) {
    await page.mouse.move(view.x + p.at.x, view.y + p.at.y);
    if ((await page.evaluate(() => window.cad2moViewer.gizmo.controls.axis)) === 'Y') {
      ring = p;
      break;
    }
  }
  assert.ok(ring, `the pointer finds the gizmo's y ring: ${JSON.stringify(ringPoints)}`);
  const [rx, ry] = [view.x + ring.at.x, view.y + ring.at.y];
  await page.mouse.down();
  await page.mouse.move(rx + ring.dir.x * 30, ry + ring.dir.y * 30, { steps: 5 });
  await page.mouse.move(rx + ring.dir.x * 60, ry + ring.dir.y * 60, { steps: 5 });
  await page.mouse.up();
  const turned = [];
  for (const a of 'xyz') turned.push(Number(await page.getByLabel(`box1 angle about ${a}`, { exact: true }).inputValue()));
  // About y only: y stays y (the typed angles may read e.g. 180, -85.8, 180 for a turn past 90°).
  const R = rotationFromAngles(turned);
  const about = (Math.atan2(R[0][2], R[0][0]) * 180) / Math.PI;
  assert.ok(R[1][1] > 1 - 1e-9 && Math.abs(about - 30) > 1, `the ring turned box1 about y only (to ${about}°): ${turned}°`);
  assert.ok(near(await typed(page, 'box1'), target, 1e-9), 'turning keeps the position');
  await panel.getByLabel('Gizmo', { exact: true }).selectOption('translate');

  // ---- Save: the interference of the box with the link is named (Scene and Collision tabs).
  step('scene: save and interference');
  await page.getByRole('button', { name: 'Save scene' }).click();
  await panel.getByRole('status').filter({ hasText: /^Saved$/ }).waitFor();
  const item = panel.locator(`ul.scene-interference-list li[data-object="box1"][data-other="${link.name}"]`);
  await item.waitFor();
  assert.match(await item.textContent(), new RegExp(`^box1 touches ${link.name} depth [\\d.]+ mm$`));
  const stored = await page.evaluate(async (path) => (await fetch(path)).json(), `/api/models/${id}/scene`);
  assert.ok(near(stored.objects[0].position, target, 1e-12), `stored at the typed position: ${JSON.stringify(stored)}`);
  await item.evaluate((el) => el.scrollIntoView({ block: 'center' }));
  // In 3D: the box and the link tinted, a line between their witness points.
  const tinted = await page.evaluate((n) => [window.cad2moViewer.marked.has('box1'), window.cad2moViewer.marked.has(n), window.cad2moViewer.contactLines().length], link.name);
  assert.ok(tinted[0] && tinted[1] && tinted[2] >= 1, `the interference marked in 3D: ${tinted}`);
  await shot(page, '35-scene-interference');
  await page.getByRole('tab', { name: 'Collision', exact: true }).click();
  const listed = page.locator(`ul.interferences li[data-a="box1"][data-b="${link.name}"], ul.interferences li[data-a="${link.name}"][data-b="box1"]`);
  await listed.waitFor();
  assert.match(await listed.textContent(), new RegExp(`(box1 — ${link.name}|${link.name} — box1)`));

  // ---- Duplicate, hide (and undo it), drop onto the surface below, attach to a link.
  step('scene: duplicate, visibility, drop, attach');
  await page.getByRole('tab', { name: 'Scene', exact: true }).click();
  await panel.getByRole('button', { name: 'Duplicate' }).click();
  await panel.locator('tr[data-object="box2"].selected').waitFor();
  const copy = await typed(page, 'box2');
  assert.ok(copy[0] > target[0] + 0.2 && near(copy.slice(1), target.slice(1), 1e-12), `box2 beside box1: ${copy}`);
  await panel.getByLabel('box2 visible').uncheck();
  assert.equal((await drawn(page, 'box2')).visible, false, 'box2 hidden');
  await page.keyboard.press('Control+z');
  assert.equal((await drawn(page, 'box2')).visible, true, 'Ctrl+Z shows box2 again');
  // Lifted 1 m above box1, then dropped: it comes down onto what is below it (box1 or a link) and rests there.
  const up = await page.evaluate(() => window.cad2moViewer.up.toArray());
  const high = target.map((x, i) => x + up[i]);
  for (const [k, a] of [...'xyz'].entries()) await page.getByLabel(`box2 position ${a}`, { exact: true }).fill(String(high[k]));
  await page.getByRole('button', { name: 'Apply pose' }).click();
  await panel.getByRole('button', { name: 'Drop onto surface' }).click();
  const dropped = await typed(page, 'box2');
  const rest = await page.evaluate(() => window.cad2moViewer.dropDistance('box2'));
  // It moved against "up" only (the arm's gravity is along -y), by more than the gap to box1's top.
  const fell = dropped.map((x, i) => high[i] - x);
  const along = fell[0] * up[0] + fell[1] * up[1] + fell[2] * up[2];
  assert.ok(along > 0.05 && near(fell, up.map((u) => u * along), 1e-9), `box2 came down along gravity: ${high} → ${dropped}`);
  assert.ok(rest && Math.abs(rest.distance) < 1e-6, `box2 rests on ${rest?.onto?.name}: ${JSON.stringify(rest)}`);
  // Attached to the link it rests on, it moves with it (its joint's slider) and keeps its place when attached.
  const before = (await drawn(page, 'box2')).origin;
  await panel.getByLabel('box2 attached to').selectOption(rest.onto.kind === 'body' ? rest.onto.name : link.name);
  assert.ok(near((await drawn(page, 'box2')).origin, before, 1e-9), 'attaching keeps its place in the world');
  await page.getByRole('tab', { name: 'Structure', exact: true }).click();
  const slider = page.locator('.slider input[type=range]').first();
  await slider.focus();
  for (let k = 0; k < 15; k++) await page.keyboard.press('ArrowRight');
  const moved = await awayFrom(page, 'box2', before, true);
  assert.ok(moved, 'box2 moves with its body');
  await page.getByRole('button', { name: 'Reset pose' }).click();
  assert.ok(await awayFrom(page, 'box2', before, false), 'and back with it');
  await page.getByRole('tab', { name: 'Scene', exact: true }).click();
  await shot(page, '36-scene-dropped');

  // ---- Import a mesh (a 50 mm cube, ASCII STL, in mm): uploaded, drawn from the stored STL at
  // its size in metres; then put on a point picked on the model (a click in the 3D view).
  step('scene: mesh import, place on a picked point');
  await panel.getByLabel('Unit of the mesh file').selectOption('mm');
  await page.locator('#scene-mesh-file').setInputFiles({ name: 'cube.stl', mimeType: 'model/stl', buffer: Buffer.from(cubeStl(50)) });
  await panel.locator('tr[data-object="cube1"].selected').waitFor();
  await page.waitForFunction(() => window.cad2moViewer.sceneObjects.get('cube1')?.mesh.material.wireframe === false);
  const size = await page.evaluate(() => window.cad2moViewer.objectBox('cube1').getSize(window.cad2moViewer.up.clone()).toArray());
  assert.ok(near(size, [0.05, 0.05, 0.05], 1e-6), `the cube drawn 50 mm wide: ${size}`);
  // box2 framed in the view (its row selected, Fit selection), then cube1 selected again.
  await panel.locator('tr[data-object="box2"] button.pick').click();
  await page.getByRole('button', { name: 'Fit selection' }).click();
  await panel.locator('tr[data-object="cube1"] button.pick').click();
  await panel.locator('tr[data-object="cube1"].selected').waitFor();
  // Aimed at the middle of box2's top (seen from above at an angle).
  const aim = await page.evaluate(() => {
    const v = window.cad2moViewer;
    const b = v.objectBox('box2');
    const top = b.getCenter(v.up.clone()).toArray();
    const hUp = Math.abs(b.getSize(v.up.clone()).dot(v.up)) / 2;
    return v.toScreen(top.map((x, i) => x + v.up.toArray()[i] * hUp));
  });
  await panel.getByRole('button', { name: 'Place on picked point' }).click();
  const view2 = await page.locator('.stage canvas').boundingBox();
  await page.mouse.click(view2.x + aim.x, view2.y + aim.y);
  await page.waitForFunction(() => window.cad2moViewer.surfacePicked !== undefined && !document.querySelector('#scene-place[aria-pressed=true]'));
  const placed = await page.evaluate(() => ({ foot: window.cad2moViewer.objectFoot('cube1'), picked: window.cad2moViewer.surfacePicked, rest: window.cad2moViewer.dropDistance('cube1') }));
  assert.equal(placed.picked.object.name, 'box2', `the click picked box2's top: ${JSON.stringify(placed)}`);
  assert.ok(near(placed.foot, placed.picked.point, 1e-6), `the cube's underside is at the picked point: ${JSON.stringify(placed)}`);
  assert.ok(placed.rest && Math.abs(placed.rest.distance) < 1e-6 && placed.rest.onto.name === 'box2', `the cube rests on box2: ${JSON.stringify(placed)}`);
  await shot(page, '37-scene-mesh-placed');
  // Delete, and undo it.
  await panel.getByRole('button', { name: 'Delete', exact: true }).click();
  await panel.locator('tr[data-object="cube1"]').waitFor({ state: 'detached' });
  assert.equal(await page.evaluate(() => window.cad2moViewer.sceneObjects.has('cube1')), false, 'cube1 gone from the 3D view');
  await page.getByRole('button', { name: 'Undo', exact: true }).click();
  await panel.locator('tr[data-object="cube1"]').waitFor();
  assert.equal(await page.evaluate(() => window.cad2moViewer.sceneObjects.has('cube1')), true, 'cube1 back after undo');

  // ---- A primitive's size by numbers: refused out of range (naming the field), then applied.
  await panel.locator('tr[data-object="box2"] button.pick').click();
  await page.getByLabel('box2 size x', { exact: true }).fill('0');
  await panel.getByRole('button', { name: 'Apply size' }).click();
  await panel.getByText(/^shape\.size\[0\]: "0" must be a length/).waitFor();
  await page.getByLabel('box2 size x', { exact: true }).fill('0.3');
  await panel.getByRole('button', { name: 'Apply size' }).click();
  await page.waitForFunction(() => window.cad2moViewer.sceneObjects.get('box2')?.mesh.geometry.parameters?.width === 0.3);
  assert.match(await panel.locator('tr[data-object="box2"]').textContent(), /box \(0\.3 × 0\.2 × 0\.2 m\)/);

  // ---- Kind: box1 made moving at a velocity (an undoable edit); a speed the API refuses is
  // shown at the velocity field; saved, the page reloaded, the values are back.
  step('scene: kind and motion');
  const tk = Date.now();
  await panel.locator('tr[data-object="box1"] button.pick').click();
  await panel.getByLabel('box1 kind', { exact: true }).selectOption('moving');
  const speed = async (vx) => {
    for (const [i, x] of [vx, '0', '0'].entries()) await page.getByLabel(`box1 velocity ${i + 1}`, { exact: true }).fill(x);
    await panel.getByRole('button', { name: 'Apply kind' }).click();
  };
  await speed('500');
  await panel.locator('tr[data-object="box1"]').filter({ hasText: 'moving' }).waitFor();
  await page.getByRole('button', { name: 'Undo', exact: true }).click();
  await panel.locator('tr[data-object="box1"]').filter({ hasText: 'static' }).waitFor();
  await page.getByRole('button', { name: 'Redo', exact: true }).click();
  await panel.locator('tr[data-object="box1"]').filter({ hasText: 'moving' }).waitFor();
  await page.getByRole('button', { name: 'Save scene' }).click();
  const refused = panel.locator('.scene-editor [data-field="velocity"]');
  await refused.waitFor();
  assert.match(await refused.textContent(), /at most 100 m\/s/);
  await speed('0.25');
  await page.getByRole('button', { name: 'Save scene' }).click();
  await panel.getByRole('status').filter({ hasText: /^Saved$/ }).waitFor();
  await page.reload();
  await waitForModel(page);
  await page.getByRole('tab', { name: 'Scene', exact: true }).click();
  await panel.locator('tr[data-object="box1"] button.pick').click();
  const vBack = [];
  for (const i of [1, 2, 3]) vBack.push(Number(await page.getByLabel(`box1 velocity ${i}`, { exact: true }).inputValue()));
  assert.deepEqual(vBack, [0.25, 0, 0], 'the velocity back after a reload');
  assert.equal(await panel.getByLabel('box1 kind', { exact: true }).inputValue(), 'moving');
  assert.equal(await page.getByLabel('box1 velocity 1', { exact: true }).isVisible(), true);
  assert.deepEqual([await page.getByLabel('box1 mass', { exact: true }).isVisible(), await page.getByLabel('box1 poses', { exact: true }).isVisible()], [false, false], 'only the velocity shown');
  await page.getByLabel('box1 velocity 1', { exact: true }).scrollIntoViewIfNeeded();
  await shot(page, '38-scene-kind');
  const kindSeconds = (Date.now() - tk) / 1000; // the screenshot included

  // ---- Clean up: later steps expect a model without a scene.
  await page.evaluate(async ({ path, headers }) => {
    const r = await fetch(path, { method: 'DELETE', headers });
    if (r.status !== 204) throw new Error(`DELETE ${path}: ${r.status}`);
  }, { path: `/api/models/${id}/scene`, headers: H });
  return { box: target, dragged, turned_deg: about, link: link.name, dropped_onto: rest.onto.name, version: Number(v), kind_seconds: kindSeconds, seconds: (Date.now() - t0) / 1000 };
}
