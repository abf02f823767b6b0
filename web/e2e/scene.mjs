// The Scene tab (issue 29), end to end (part of ui.mjs, on the model view of the uploaded arm):
// add a box (drawn in the 3D view, selected, with the gizmo), move it with the gizmo by a real
// mouse drag on the canvas (on the gizmo's x handle, found in the three.js scene and projected
// to the screen), set a position inside a link by typed numbers, undo twice and redo twice
// (button, Ctrl+Z, Ctrl+Shift+Z, Ctrl+Y: the typed numbers and the drawn box go back and
// forth), save, and see the interference of the box with the link named in the Scene tab and
// the Collision tab. The scene is removed at the end (later steps expect none).

import assert from 'node:assert/strict';

const H = { 'X-Requested-With': 'cad2mo' };

/** The box as drawn: its frame's origin in the world (m) and whether it is visible. */
function drawn(page, name) {
  return page.evaluate((n) => {
    const e = window.cad2moViewer.sceneObjects.get(n);
    if (!e) return null;
    e.mesh.updateMatrixWorld(true);
    const m = e.mesh.matrixWorld.elements;
    return { origin: [m[12], m[13], m[14]], visible: e.mesh.visible, gizmo: !!window.cad2moViewer.gizmo };
  }, name);
}

/** The typed position numbers of the selected object. */
async function typed(page, name) {
  const out = [];
  for (const a of 'xyz') out.push(Number(await page.getByLabel(`${name} position ${a}`, { exact: true }).inputValue()));
  return out;
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
    const p = x.getWorldPosition(v.gizmo.target.position.clone());
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
  await page.mouse.down();
  await page.mouse.move(sx + handle.dir.x * 40, sy + handle.dir.y * 40, { steps: 5 });
  await page.mouse.move(sx + handle.dir.x * 80, sy + handle.dir.y * 80, { steps: 5 });
  await page.mouse.up();
  const dragged = await typed(page, 'box1');
  assert.ok(dragged[0] > 0.01 && Math.abs(dragged[1]) < 1e-9 && Math.abs(dragged[2]) < 1e-9, `the gizmo moved box1 along +x only: ${dragged}`);
  box = await drawn(page, 'box1');
  assert.ok(near(box.origin, dragged, 1e-6), `the typed numbers follow the gizmo: ${dragged} vs drawn ${box.origin}`);
  await shot(page, '30-scene-gizmo');

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
  await page.getByRole('button', { name: 'Apply pose' }).click();
  await page.waitForFunction((t) => {
    const e = window.cad2moViewer.sceneObjects.get('box1');
    return e && Math.abs(e.mesh.matrix.elements[12] - t[0]) < 1e-9 && Math.abs(e.mesh.matrix.elements[14] - t[2]) < 1e-9;
  }, target);
  assert.ok(near((await drawn(page, 'box1')).origin, target, 1e-9), 'the box is drawn at the typed position');

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

  // ---- Save: the interference of the box with the link is named (Scene and Collision tabs).
  step('scene: save and interference');
  await page.getByRole('button', { name: 'Save scene' }).click();
  await panel.getByRole('status').filter({ hasText: /^Saved$/ }).waitFor();
  const item = panel.locator(`ul.scene-interference-list li[data-object="box1"][data-other="${link.name}"]`);
  await item.waitFor();
  assert.match(await item.textContent(), new RegExp(`^box1 touches ${link.name} depth [\\d.]+ mm$`));
  const stored = await page.evaluate(async (path) => (await fetch(path)).json(), `/api/models/${id}/scene`);
  assert.ok(near(stored.objects[0].position, target, 1e-12), `stored at the typed position: ${JSON.stringify(stored)}`);
  await shot(page, '31-scene-interference');
  await page.getByRole('tab', { name: 'Collision', exact: true }).click();
  const listed = page.locator('ul.interferences li').filter({ hasText: 'box1' });
  await listed.waitFor();
  assert.match(await listed.textContent(), new RegExp(`(box1 — ${link.name}|${link.name} — box1)`));

  // ---- Clean up: later steps expect a model without a scene.
  await page.evaluate(async ({ path, headers }) => {
    const r = await fetch(path, { method: 'DELETE', headers });
    if (r.status !== 204) throw new Error(`DELETE ${path}: ${r.status}`);
  }, { path: `/api/models/${id}/scene`, headers: H });
  return { box: target, dragged, link: link.name, version: Number(v), seconds: (Date.now() - t0) / 1000 };
}
