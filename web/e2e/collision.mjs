// Collisions (issue 14), end to end (part of ui.mjs, on the model view of the uploaded arm):
// the Collision tab's shape table against the API; no interference at the CAD pose with the
// default matrix; a joined pair (BASE–LINK_UPPER, which intersect at the joint) set to
// "checked" in the matrix: the interference appears with its depth, selecting it tints both
// bodies and draws the line between its witness points (read back from the three.js scene and
// compared with the API's points, each lying on its own body's mesh box); back to the default,
// the interference is gone. Then a motion made through the API that swings the fore link into
// the base: "Check collisions" shows the first contact and a marker on the timeline at its
// time (and dashed lines on the plots), a click on the pair moves the player to the time of
// the minimum distance and draws the closest-point line there.

import assert from 'node:assert/strict';
import { waitForModel } from './lib.mjs';

const H = { 'X-Requested-With': 'cad2mo' };

/** A JSON request made by the page (same origin, the UI's header). */
function call(page, method, path, body) {
  return page.evaluate(
    async ({ method, path, body, headers }) => {
      const r = await fetch(path, { method, headers: body ? { ...headers, 'Content-Type': 'application/json' } : headers, body: body ? JSON.stringify(body) : undefined });
      const text = await r.text();
      if (!r.ok) throw new Error(`${method} ${path}: ${r.status} ${text}`);
      return text ? JSON.parse(text) : null;
    },
    { method, path, body, headers: H },
  );
}

/** What the 3D view shows of the collision marks: lines from the scene, tinted bodies, mesh boxes. */
function scene(page) {
  return page.evaluate(async () => {
    const v = window.cad2moViewer;
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    const tinted = [];
    const boxes = {};
    for (const [name, b] of v.bodies) {
      if (!b.hasMesh) continue;
      const e = b.materials[0].emissive;
      if (e.r + e.g + e.b > 0) tinted.push(name);
      b.group.updateMatrixWorld(true);
      const min = [Infinity, Infinity, Infinity];
      const max = [-Infinity, -Infinity, -Infinity];
      b.group.traverse((o) => {
        if (!o.isMesh) return;
        const pos = o.geometry.getAttribute('position');
        const m = o.matrixWorld.elements;
        for (let i = 0; i < pos.count; i++) {
          const x = pos.getX(i), y = pos.getY(i), z = pos.getZ(i);
          const w = [m[0] * x + m[4] * y + m[8] * z + m[12], m[1] * x + m[5] * y + m[9] * z + m[13], m[2] * x + m[6] * y + m[10] * z + m[14]];
          for (let k = 0; k < 3; k++) {
            min[k] = Math.min(min[k], w[k]);
            max[k] = Math.max(max[k], w[k]);
          }
        }
      });
      boxes[name] = { min, max };
    }
    return { lines: v.contactLines(), tinted: tinted.sort(), boxes };
  });
}

/** Largest coordinate difference between two points. */
const gap = (p, q) => Math.max(...p.map((x, i) => Math.abs(x - q[i])));

/** How far a point lies outside a box (0 inside). */
const outside = (p, box) => Math.max(0, ...p.map((x, i) => Math.max(box.min[i] - x, x - box.max[i])));

/** The line drawn is the API's witness segment; each end lies on its own body's mesh box. */
function checkLine(seen, pair, tol, where) {
  assert.equal(seen.lines.length, 1, `${where}: one closest-point line: ${JSON.stringify(seen.lines)}`);
  const [l] = seen.lines;
  // three.js holds vertex positions as float32: 1e-7 relative, far below a micrometre here.
  assert.ok(gap(l.from, pair.point_a) < 1e-6 && gap(l.to, pair.point_b) < 1e-6, `${where}: the line joins the API's witness points ${JSON.stringify(pair.point_a)} → ${JSON.stringify(pair.point_b)}: ${JSON.stringify(l)}`);
  assert.deepEqual(seen.tinted, [pair.a, pair.b].sort(), `${where}: both bodies of the pair are highlighted`);
  const da = outside(pair.point_a, seen.boxes[pair.a]);
  const db = outside(pair.point_b, seen.boxes[pair.b]);
  assert.ok(da <= tol && db <= tol, `${where}: the witness points lie on the drawn meshes (${da} m, ${db} m outside their boxes)`);
}

/** Red pixels (the first-contact lines) in a uPlot chart's canvas. */
function redPixels(page, plot) {
  return page.evaluate((key) => {
    const c = document.querySelector(`.plot[data-plot="${key}"] .uplot canvas`);
    if (!c) return -1;
    const img = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < img.length; i += 4) if (img[i + 3] > 200 && img[i] > 200 && img[i + 1] < 60 && img[i + 2] < 60) n++;
    return n;
  }, plot);
}

/**
 * @param {import('playwright-core').Page} page  on the model view of the arm (its latest version)
 * @param {{step: Function, shot: Function}} o
 */
export async function collisionSteps(page, { step, shot }) {
  const [, , id, , v] = new URL(page.url()).hash.split('/');
  const version = Number(v);
  assert.ok(id && version > 0, `on a model version page: ${page.url()}`);
  const base = `/api/models/${id}`;

  // ---- The shapes per body, as the API has them.
  step('collision: shapes');
  await page.getByRole('tab', { name: 'Collision' }).click();
  const table = page.locator('table.collision-shapes-table');
  await table.waitFor();
  const data = await call(page, 'GET', `${base}/versions/${version}/collision`);
  const shaped = data.bodies.filter((b) => b.kind !== 'none');
  assert.ok(shaped.length >= 3, `the arm's three links have shapes: ${JSON.stringify(data.bodies)}`);
  assert.equal(await table.locator('tbody tr').count(), data.bodies.length, 'a row per body');
  for (const b of data.bodies) {
    const cells = await table.locator(`tr[data-body="${b.body}"] > *`).allTextContents();
    assert.equal(cells[1], b.kind, `${b.body}'s kind`);
    assert.equal(Number(cells[2]), b.parts, `${b.body}'s parts`);
    assert.equal(Number(cells[3]), b.vertices, `${b.body}'s vertices`);
    if (b.kind !== 'none') assert.ok(Math.abs(Number(cells[4]) - b.fit_error * 1000) < 1e-3, `${b.body}'s fit error in mm: ${cells[4]}`);
    for (const w of b.warnings) assert.ok(cells[6].includes(w), `${b.body}'s warning ${w}`);
  }
  // With the default matrix (joined pairs may touch) the arm has no interference.
  assert.deepEqual(data.interferences, [], 'no interference at the CAD pose with the default matrix');
  await page.locator('.no-interference').waitFor();

  // ---- The matrix: a joined pair may touch by default; checked, it intersects at the joint.
  step('collision: matrix');
  const matrix = await call(page, 'GET', `${base}/collision-matrix`);
  const pair = matrix.pairs.find((p) => [p.a, p.b].sort().join() === 'BASE,LINK_UPPER');
  assert.ok(pair && pair.allowed && pair.default && !pair.custom, `BASE–LINK_UPPER may touch by default: ${JSON.stringify(matrix)}`);
  const { a, b } = pair;
  const grid = page.locator('table.collision-matrix-table');
  assert.equal(await grid.locator('tbody tr').count(), matrix.pairs.length, 'a row per pair');
  const row = grid.locator(`tr[data-a="${a}"][data-b="${b}"]`);
  assert.match(await row.textContent(), /default.*joined by/);
  const mayTouch = row.getByLabel(`${a} and ${b} may touch`);
  assert.equal(await mayTouch.isChecked(), true);
  for (const p of matrix.pairs) assert.equal(await grid.locator(`tr[data-a="${p.a}"][data-b="${p.b}"] input[type=checkbox]`).isChecked(), p.allowed, `${p.a}–${p.b} as the API says`);
  await mayTouch.uncheck();
  await grid.locator(`tr.custom[data-a="${a}"][data-b="${b}"]`).waitFor();
  const stored = (await call(page, 'GET', `${base}/collision-matrix`)).pairs.find((p) => p.a === a && p.b === b);
  assert.deepEqual([stored.allowed, stored.custom], [false, true], `stored as checked: ${JSON.stringify(stored)}`);

  // ---- The interference appears, with its depth; selected, it is shown in 3D.
  step('collision: interference');
  const item = page.locator(`ul.interferences li[data-a="${a}"][data-b="${b}"]`);
  await item.waitFor();
  const inter = (await call(page, 'GET', `${base}/versions/${version}/collision`)).interferences.find((i) => i.a === a && i.b === b);
  assert.ok(inter && inter.depth > 0, `the API reports the interference: ${JSON.stringify(inter)}`);
  const depthMm = Number((/depth ([\d.e+-]+) mm/.exec(await item.textContent()) || [])[1]);
  assert.ok(Math.abs(depthMm - inter.depth * 1000) < 1e-3, `the depth shown (${depthMm} mm) is the API's (${inter.depth} m)`);
  // Away from the CAD pose first: selecting goes back to it (the witness points are there).
  await page.getByRole('tab', { name: 'Structure' }).click();
  const slider = page.locator('.slider input[type=range]').first();
  await slider.focus();
  for (let k = 0; k < 20; k++) await page.keyboard.press('ArrowRight');
  await page.getByRole('tab', { name: 'Collision' }).click();
  await item.getByRole('button', { name: `Show the interference of ${a} and ${b} in 3D` }).click();
  await page.locator(`ul.interferences li.selected[data-a="${a}"]`).waitFor();
  const atCad = await scene(page);
  checkLine(atCad, { ...inter }, 1e-6, 'CAD pose');
  await shot(page, '26-collision-interference');
  // The Contact points toggle hides the line and dots (kept) and shows them again.
  const contactsShown = () => page.evaluate(() => window.cad2moViewer.contactGroup.visible);
  await page.getByLabel('Contact points').uncheck();
  assert.equal(await contactsShown(), false, 'contact points hidden');
  assert.equal((await scene(page)).lines.length, 1, 'the contact line is kept while hidden');
  await page.getByLabel('Contact points').check();
  assert.equal(await contactsShown(), true, 'contact points shown again');

  // ---- Back to the default: no interference, no marks.
  await row.getByRole('button', { name: `Reset ${a} and ${b} to the default` }).click();
  await grid.locator(`tr.custom[data-a="${a}"][data-b="${b}"]`).waitFor({ state: 'detached' });
  await page.locator('.no-interference').waitFor();
  assert.equal(await grid.locator(`tr[data-a="${a}"][data-b="${b}"] input[type=checkbox]`).isChecked(), true);
  const reset = (await call(page, 'GET', `${base}/collision-matrix`)).pairs.find((p) => p.a === a && p.b === b);
  assert.deepEqual([reset.allowed, reset.custom], [true, false], `back to the default: ${JSON.stringify(reset)}`);
  assert.deepEqual((await scene(page)).lines, [], 'the line is gone with the interference');

  // ---- A motion that swings the fore link into the base (made through the API).
  step('collision: motion');
  const joints = (await call(page, 'GET', `${base}/joints`)).joints.map((j) => j.name);
  assert.ok(joints.includes('BASE_LINK') && joints.includes('LINK_LINK'), `the arm's joints: ${joints}`);
  const motion = await call(page, 'POST', `${base}/motions`, {
    name: 'swing',
    keyframes: [
      { kind: 'joints', values: {} },
      { kind: 'joints', values: { BASE_LINK: 2.8, LINK_LINK: 2.78 }, interpolation: 'ptp', duration: null, dwell: null },
    ],
  });
  const sweep = await call(page, 'GET', `${base}/motions/${motion.id}/collisions`);
  assert.ok(sweep.first_contact, `the swing makes two bodies touch: ${JSON.stringify(sweep)}`);
  // The Motion tab lists motions when it first renders: reload the page on it.
  await page.goto(`${new URL(page.url()).origin}/#/models/${id}/versions/${version}/motion`);
  await page.reload();
  await waitForModel(page);
  await page.locator('.motion-list li[data-motion="swing"] button').click();
  await page.locator('#motion-play').waitFor({ timeout: 60_000 });
  await page.locator('.plot[data-plot="q"] .uplot').waitFor();
  const duration = Number(await page.locator('#motion-scrub').getAttribute('max'));
  const redBefore = await redPixels(page, 'q');
  await page.getByRole('button', { name: 'Check collisions' }).click();
  const first = page.locator('.motion-collisions .first-contact');
  await first.waitFor();
  const fc = sweep.first_contact;
  assert.equal(await first.textContent(), `First contact: ${fc.a} and ${fc.b} at ${Math.round(fc.time * 1000) / 1000} s`);
  assert.match(await page.locator('.motion-collisions .guarantee').textContent(), /^Guarantee: .+/);
  const rows = page.locator('.motion-collisions-table tbody tr');
  assert.equal(await rows.count(), sweep.pairs.length, 'a row per checked pair');
  const hit = sweep.pairs.find((p) => p.a === fc.a && p.b === fc.b);
  const hitRow = page.locator(`.motion-collisions-table tr[data-a="${hit.a}"][data-b="${hit.b}"]`);
  const cells = await hitRow.locator('td').allTextContents();
  assert.ok(Math.abs(parseFloat(cells[0]) - hit.min_distance * 1000) < 1e-3, `min distance in mm: ${cells[0]} vs ${hit.min_distance} m`);
  assert.ok(Math.abs(parseFloat(cells[2]) - hit.first_contact) < 1e-9, `first contact: ${cells[2]}`);
  assert.ok(Math.abs(parseFloat(cells[3]) - hit.max_depth * 1000) < 1e-3, `max depth in mm: ${cells[3]}`);
  assert.equal(cells[4], 'contact');

  // ---- Markers: on the timeline at the first contact, and dashed on the plots.
  step('collision: timeline markers');
  const marks = page.locator('.timeline .contact-mark');
  assert.equal(await marks.count(), sweep.pairs.filter((p) => p.first_contact !== null).length, 'a marker per pair that touches');
  const mark = page.locator(`.timeline .contact-mark[data-a="${fc.a}"][data-b="${fc.b}"]`);
  assert.equal(Number(await mark.getAttribute('data-time')), fc.time);
  const left = await mark.evaluate((el) => parseFloat(el.style.left));
  assert.ok(Math.abs(left - (fc.time / duration) * 100) < 1e-3, `the marker sits at ${left}% of the timeline (${fc.time} of ${duration} s)`);
  const [markBox, lineBox] = [await mark.boundingBox(), await page.locator('.timeline').boundingBox()];
  const centre = markBox.x + markBox.width / 2 - lineBox.x;
  assert.ok(Math.abs(centre - (lineBox.width * fc.time) / duration) < 3, `the marker is drawn at the first contact's place: ${centre} px of ${lineBox.width}`);
  await page.waitForTimeout(100);
  const redAfter = await redPixels(page, 'q');
  assert.ok(redAfter > redBefore + 20, `the q plot marks the first contact: ${redBefore} → ${redAfter} red pixels`);
  await mark.click();
  assert.ok(Math.abs(Number(await page.locator('.player-box').getAttribute('data-time')) - fc.time) < 1e-3, 'a click on the marker moves the player there');
  await page.locator(`.motion-collisions tr.touched[data-a="${fc.a}"][data-b="${fc.b}"]`).waitFor();

  // ---- The pair: the player at its minimum distance, the closest points drawn.
  step('collision: closest points');
  await hitRow.getByRole('button').click();
  assert.equal(await page.locator('.player-box').getAttribute('data-time'), hit.at.toFixed(3), 'the player is at the time of the minimum distance');
  const atMin = await scene(page);
  // The player interpolates the 100 Hz trajectory; the check samples at 1 kHz: a few mm apart.
  checkLine(atMin, hit, 0.005, `the motion at ${hit.at} s`);
  await shot(page, '27-collision-motion');

  // ---- The marks belong to the Motion tab; the motion goes (later steps change the model).
  await page.getByRole('tab', { name: 'Structure' }).click();
  assert.deepEqual((await scene(page)).lines, [], 'no closest-point line outside the Motion tab');
  await call(page, 'DELETE', `${base}/motions/${motion.id}`);
  return { interference: { a, b, depth: inter.depth }, first_contact: fc, min_distance: hit.min_distance, at: hit.at, samples: sweep.samples };
}
