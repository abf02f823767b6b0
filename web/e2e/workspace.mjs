// The model workspace at the scale of a real model (issue 30), on the iCub left hand (11 joints
// with long CAD names): at 1440×900 and at 390×844 every tab is opened (a drive editor open, a
// motion with its keyframe table and player) and the bounding boxes of every visible control
// and table must lie inside their panel and the window, or inside a box that scrolls by itself
// (class "scroll"), which must itself fit; the 3D view and Play must be on screen together.
// The unit choice reaches the keyframe table and the plots; a typed slider value is exact.
import assert from 'node:assert/strict';
import { join } from 'node:path';

/** Controls and tables that lie outside their panel or the window (at most 10 described). */
function outOfReach() {
  const visible = (el) => {
    if (el.closest('[hidden]')) return false;
    const r = el.getBoundingClientRect();
    if (r.width === 0 && r.height === 0) return false;
    return getComputedStyle(el).visibility !== 'hidden';
  };
  const bad = [];
  let checked = 0;
  const vw = document.documentElement.clientWidth;
  const panels = [...document.querySelectorAll('.workspace > .view3d, .workspace > .dock, .workspace > .side')].filter(visible);
  for (const panel of panels) {
    const p = panel.getBoundingClientRect();
    for (const el of panel.querySelectorAll('button, input, select, textarea, table, [role=tab], .uplot')) {
      if (!visible(el) || el.classList.contains('visually-hidden')) continue;
      if (el.closest('.diagram-view')) continue; // the diagram pans and zooms inside its own box
      // Inside a box that scrolls on its own: that box must fit instead.
      const scroller = el.closest('.scroll');
      const target = scroller && panel.contains(scroller) ? scroller : el;
      const r = target.getBoundingClientRect();
      checked++;
      if (r.left < p.left - 1 || r.right > p.right + 1 || r.left < -1 || r.right > vw + 1) {
        const what = el.getAttribute('aria-label') || el.id || el.textContent.trim().slice(0, 40) || el.tagName;
        bad.push(`${panel.className.split(' ')[0]}: ${el.tagName.toLowerCase()} "${what}" at ${Math.round(r.left)}…${Math.round(r.right)} (panel ${Math.round(p.left)}…${Math.round(p.right)}, window ${vw})`);
      }
    }
  }
  const pageOverflow = document.documentElement.scrollWidth - vw;
  // What sticks out of the window when the page is wider than it (outside boxes that scroll).
  const wide = pageOverflow > 1
    ? [...document.querySelectorAll('body *')].filter((e) => !e.parentElement.closest('.scroll') && e.getBoundingClientRect().right > vw + 1).slice(0, 6).map((e) => `${e.tagName.toLowerCase()}.${e.className} → ${Math.round(e.getBoundingClientRect().right)}`)
    : [];
  return { checked, bad: bad.slice(0, 10), count: bad.length, pageOverflow, wide };
}

/** Whether the 3D view and the Play button are both fully in the window, and Play is not covered. */
function viewAndPlay() {
  const inWindow = (r) => r.top >= -1 && r.left >= -1 && r.bottom <= window.innerHeight + 1 && r.right <= window.innerWidth + 1 && r.width > 0 && r.height > 0;
  const stage = document.querySelector('.stage').getBoundingClientRect();
  const play = document.querySelector('#motion-play');
  const r = play.getBoundingClientRect();
  const top = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
  // The 3D view needs a usable size, not a sliver: at least 40 % of the window's width (wide) or 30 % of its height.
  const usable = stage.width >= Math.min(0.4 * window.innerWidth, 300) && stage.height >= 0.3 * window.innerHeight - 40;
  return { stage: inWindow(stage) && usable, play: inWindow(r) && top === play, stageBox: [stage.left, stage.top, stage.width, stage.height].map(Math.round), playBox: [r.left, r.top].map(Math.round) };
}

/**
 * In a narrow window (stacked layout): the 3D view, the dock and the side panel one above the
 * other at the window's width; every visible table that is wider than its panel sits in a box
 * that scrolls sideways by itself (overflow-x auto or scroll, no wider than the panel), so the
 * table scrolls, not the page.
 */
function stackedAndScrolling() {
  const box = (sel) => document.querySelector(sel)?.getBoundingClientRect();
  const vw = document.documentElement.clientWidth;
  const view = box('.workspace > .view3d');
  const side = box('.workspace > .side');
  const stacked = !!view && !!side && side.top >= view.bottom - 1 && Math.abs(side.left - view.left) <= 2 && side.width >= 0.9 * vw - 40 && view.width >= 0.9 * vw - 40;
  const bad = [];
  let wide = 0;
  for (const panel of document.querySelectorAll('.workspace > .side, .workspace > .dock')) {
    if (panel.closest('[hidden]')) continue;
    const p = panel.getBoundingClientRect();
    for (const t of panel.querySelectorAll('table')) {
      if (t.closest('[hidden]') || t.closest('.diagram-view')) continue;
      const r = t.getBoundingClientRect();
      if (r.width === 0 || r.width <= p.width + 1) continue;
      wide++;
      let scroller = t.parentElement;
      while (scroller && scroller !== panel && !/(auto|scroll)/.test(getComputedStyle(scroller).overflowX)) scroller = scroller.parentElement;
      const ok = scroller && scroller !== panel && scroller.getBoundingClientRect().width <= p.width + 1 && scroller.scrollWidth > scroller.clientWidth;
      if (!ok) bad.push(`${t.className || t.getAttribute('aria-label') || 'table'} ${Math.round(r.width)}px in a ${Math.round(p.width)}px panel`);
    }
  }
  return { stacked, view: view && [view.left, view.top, view.width, view.height].map(Math.round), side: side && [side.left, side.top, side.width].map(Math.round), wide, bad };
}

const TABS = ['Structure', 'Report', 'Drives', 'Motion', 'Results', 'Live', 'Collision', 'Scene', 'Modelica diagram'];

/**
 * Opens every tab of the model on the page at `width`×`height`, checks reach on each, and the
 * 3D view with Play. The first call (wide) creates the motion; later ones reuse it.
 */
export async function checkWorkspace(page, { name, shots, width, height, step = () => {} }) {
  await page.setViewportSize({ width, height });
  await page.waitForTimeout(150);
  const out = { width, height, tabs: {} };
  for (const tab of TABS) {
    step(`workspace ${width}: ${tab}`);
    await page.getByRole('tab', { name: tab, exact: true }).click();
    const panel = page.locator('[role=tabpanel]:not([hidden])');
    if (tab === 'Drives') {
      await panel.locator('table.drives').waitFor();
      const add = panel.getByRole('button', { name: /^(Add|Edit) the drive of / }).first();
      await add.click();
      await panel.locator('form.drive-editor').waitFor();
      // A new drive has nothing chosen (a joint must not look assigned).
      if ((await add.textContent()) === 'Add drive') assert.equal(await panel.locator('#drive-motor').inputValue(), '', `${name}: the motor is not pre-selected`);
    } else if (tab === 'Motion') {
      if (!(await page.locator('#motion-play').count())) {
        await panel.getByLabel('New motion name').fill('reach');
        await panel.getByRole('button', { name: 'New motion', exact: true }).click();
        await page.locator('#motion-play').waitFor({ timeout: 60_000 });
      }
      await panel.locator('table.keyframe-table').waitFor();
      await page.locator('.plot[data-plot="q"] .uplot').waitFor();
    } else if (tab === 'Results') {
      await panel.locator('.results-list-box, .dropzone').first().waitFor();
    } else if (tab === 'Collision') {
      await panel.locator('table.collision-shapes-table, .error, p').first().waitFor();
    } else if (tab === 'Modelica diagram') {
      await page.locator('.diagram-view svg, .diagram-stage .error').first().waitFor();
    }
    await page.waitForTimeout(100);
    const reach = await page.evaluate(outOfReach);
    await page.screenshot({ path: join(shots, `ws-${name}-${width}-${tab.split(' ')[0].toLowerCase()}.png`) });
    assert.equal(reach.count, 0, `${name} at ${width}×${height}, ${tab}: ${reach.count} of ${reach.checked} controls out of their panel or the window: ${reach.bad.join('; ')}`);
    assert.ok(reach.pageOverflow <= 1, `${name} at ${width}×${height}, ${tab}: the page is ${reach.pageOverflow}px wider than the window: ${reach.wide.join('; ')}`);
    out.tabs[tab] = reach.checked;
    if (width < 700) {
      // Stacked: tables wider than the window scroll inside themselves.
      const st = await page.evaluate(stackedAndScrolling);
      assert.ok(st.stacked, `${name} at ${width}×${height}, ${tab}: the panels are not stacked: ${JSON.stringify(st)}`);
      assert.deepEqual(st.bad, [], `${name} at ${width}×${height}, ${tab}: tables wider than their panel that do not scroll by themselves`);
      out.wideTables = (out.wideTables || 0) + st.wide;
      // The tables themselves, for review (a screenshot of the window shows a part of them).
      if (tab === 'Drives' || tab === 'Motion') {
        const sel = tab === 'Drives' ? 'table.drives' : 'table.keyframe-table';
        await panel.locator(sel).screenshot({ path: join(shots, `ws-${name}-${width}-${tab.toLowerCase()}-table.png`) });
      }
    }
    // Abbreviated joint names stay tellable apart: no two rows read alike.
    if (tab === 'Drives' || tab === 'Motion') {
      const shown = await panel.locator(tab === 'Drives' ? 'table.drives tbody th button' : 'table.keyframe-table tbody th .name').allTextContents();
      assert.equal(new Set(shown).size, shown.length, `${name}, ${tab}: rows that read alike: ${shown.join(' | ')}`);
    }
    // In a wide window the drives and keyframe tables fit without scrolling sideways.
    if (width >= 1200 && (tab === 'Drives' || tab === 'Motion')) {
      const sel = tab === 'Drives' ? 'table.drives' : 'table.keyframe-table';
      const fit = await panel.locator(sel).evaluate((t) => {
        const box = t.closest('.scroll') || t.parentElement;
        return { table: Math.round(t.getBoundingClientRect().width), box: box.clientWidth };
      });
      assert.ok(fit.table <= fit.box + 1, `${name} at ${width}: ${sel} is ${fit.table}px wide in a ${fit.box}px panel`);
    }
    if (tab === 'Motion') {
      // The 3D view and Play together: the player heads the dock (wide) or follows the view (stacked).
      await page.locator('.view3d').evaluate((el) => el.scrollIntoView({ block: 'start' }));
      const vp = await page.evaluate(viewAndPlay);
      assert.ok(vp.stage && vp.play, `${name} at ${width}×${height}: the 3D view and Play are not on screen together: ${JSON.stringify(vp)}`);
      out.viewAndPlay = vp;
    }
  }
  return out;
}

/**
 * The unit choice (toolbar) reaches the keyframe table and the plots, and back; a value typed
 * next to a slider moves the joint exactly there, and Reset pose brings back the CAD pose exactly.
 */
export async function checkUnits(page) {
  await page.getByRole('tab', { name: 'Motion', exact: true }).click();
  const head = page.locator('table.keyframe-table tbody th').first();
  assert.match(await head.textContent(), /\[°\]/, 'degrees by default');
  await page.getByLabel('Angles').selectOption('rad');
  await page.locator('table.keyframe-table tbody th', { hasText: '[rad]' }).first().waitFor();
  await page.locator('.plot[data-plot="q"] .u-legend', { hasText: '[rad]' }).waitFor();
  // The legend names the joints' lines, not a column of "--" values (issue 30).
  const legend = await page.locator('.plot[data-plot="q"] .u-legend').textContent();
  assert.doesNotMatch(legend, /--/, `the legend: ${legend}`);
  // The joint filter keeps the rows whose name matches.
  const rows = await page.locator('table.keyframe-table tbody tr').count();
  const first = await page.locator('table.keyframe-table tbody tr').first().getAttribute('data-joint');
  await page.getByLabel('Filter joints').fill(first);
  assert.ok((await page.locator('table.keyframe-table tbody tr').count()) < rows || rows === 1, 'the filter narrows the rows');
  assert.equal(await page.locator('table.keyframe-table tbody tr').first().getAttribute('data-joint'), first);
  await page.getByLabel('Filter joints').fill('');
  await page.getByLabel('Angles').selectOption('deg');
  await page.locator('table.keyframe-table tbody th', { hasText: '[°]' }).first().waitFor();

  await page.getByRole('tab', { name: 'Structure', exact: true }).click();
  const entry = page.locator('input.q-entry').first();
  const key = (await entry.getAttribute('id')).slice(3);
  await entry.fill('12.5');
  await entry.press('Enter');
  const q = await page.evaluate((k) => window.cad2moViewer.q.get(k), key);
  assert.ok(Math.abs(q - (12.5 * Math.PI) / 180) < 1e-12, `the typed 12.5° moved the joint to ${q} rad`);
  assert.equal(await page.locator(`[id="q-${key}"]`).inputValue(), '12.5', 'the slider shows the typed value exactly');
  await page.getByRole('button', { name: 'Reset pose' }).click();
  const back = await page.evaluate((k) => {
    const range = document.getElementById(`q-${k}`);
    return { range: range.value, entry: document.getElementById(`qv-${k}`).value, q: window.cad2moViewer.q.get(k) };
  }, key);
  const q0 = await page.evaluate((k) => window.cad2moViewer.report.joints.flatMap((j) => j.elements.map((e, i) => [`${j.modelica_name}#${i}`, e.initial_q])).find(([kk]) => kk === k)?.[1], key);
  // The viewer forgets moved coordinates on reset: no entry is the CAD pose.
  assert.ok(back.q === undefined || back.q === q0, `Reset pose puts the joint exactly at its CAD pose: ${back.q} vs ${q0}`);
  assert.equal(Number(back.range), Number((q0 * 180 / Math.PI).toPrecision(12)) || 0, `the slider shows the CAD pose exactly: ${JSON.stringify(back)}`);
  return { key, q0 };
}

/**
 * A prismatic joint's slider (the read −0.840798 mm at the CAD pose): it shows the CAD
 * pose exactly, spans the joint's limits, and a typed length reaches the joint exactly (mm).
 */
export async function checkPrismatic(page) {
  await page.getByRole('tab', { name: 'Structure', exact: true }).click();
  const found = await page.evaluate(() => {
    for (const j of window.cad2moViewer.report.joints) {
      const i = (j.elements || []).findIndex((e) => e.kind === 'prismatic');
      if (i >= 0) return { key: `${j.modelica_name}#${i}`, q0: j.elements[i].initial_q };
    }
    return null;
  });
  assert.ok(found, 'a prismatic joint');
  const read = () =>
    page.evaluate((k) => {
      const r = document.getElementById(`q-${k}`);
      return { value: Number(r.value), min: Number(r.min), max: Number(r.max), entry: document.getElementById(`qv-${k}`).value, q: window.cad2moViewer.q.get(k) };
    }, found.key);
  const atStart = await read();
  const cad = Number((found.q0 * 1000).toPrecision(12)) || 0;
  assert.equal(atStart.value, cad, `the slider shows the CAD pose ${cad} mm exactly: ${JSON.stringify(atStart)}`);
  assert.ok(atStart.min <= cad && cad <= atStart.max && atStart.max > atStart.min, `the slider spans the limits and the CAD pose: ${JSON.stringify(atStart)}`);
  const target = Number(((atStart.min + atStart.max) / 2).toFixed(1));
  const entry = page.locator(`[id="qv-${found.key}"]`);
  await entry.fill(String(target));
  await entry.press('Enter');
  const moved = await read();
  assert.ok(Math.abs(moved.q - target / 1000) < 1e-15 && moved.value === target, `typed ${target} mm: ${JSON.stringify(moved)}`);
  await page.getByRole('button', { name: 'Reset pose' }).click();
  const back = await read();
  assert.ok(back.value === cad && (back.q === undefined || back.q === found.q0), `Reset pose: back at the CAD pose: ${JSON.stringify(back)}`);
  return { joint: found.key, cad, limits: [atStart.min, atStart.max], typed: target };
}

/**
 * Four viewports (top, front, side orthographic + perspective) each draw the model,
 * side-by-side stereo draws two different eyes, and dual output draws the left eye here and the
 * right eye in a second window: pixels that differ from the background, counted per viewport on
 * the canvas read back (grid hidden). Then the measuring tool: two clicks on the model give their
 * distance. Screenshots: ws-<name>-quad.png, ws-<name>-sbs.png, ws-<name>-dual(-right-eye).png.
 */
export async function checkViewports(page, { name, shots }) {
  await page.getByRole('tab', { name: 'Structure', exact: true }).click();
  const grid = page.getByLabel('Grid and world frame');
  await grid.uncheck();
  const count = () =>
    page.evaluate(async () => {
      const v = window.cad2moViewer;
      const px = await window.e2ePixels.read();
      // Per viewport: drawn pixels inside the box the model projects to through that viewport's
      // own camera (share), and outside it (stray: a stale or misplaced picture).
      return v.viewports().map((vp) => {
        const n = window.e2ePixels.count(px, { x0: vp.x + 2, y0: vp.y + 2, x1: vp.x + vp.w - 2, y1: vp.y + vp.h - 2 }, v.screenBox(undefined, vp), 2);
        return { name: vp.name, share: n.share, stray: n.stray, sig: n.sig };
      });
    });
  await page.getByLabel('Viewports').selectOption('quad');
  const quad = await count();
  await page.screenshot({ path: join(shots, `ws-${name}-quad.png`) });
  assert.deepEqual(quad.map((q) => q.name), ['top', 'front', 'side', 'perspective']);
  for (const q of quad) assert.ok(q.share > 0.1 && q.stray < 20, `the ${q.name} view draws the model where its camera sees it: ${JSON.stringify(quad)}`);
  await page.getByLabel('Viewports').selectOption('sbs');
  const sbs = await count();
  await page.screenshot({ path: join(shots, `ws-${name}-sbs.png`) });
  assert.deepEqual(sbs.map((q) => q.name), ['left', 'right']);
  for (const q of sbs) assert.ok(q.share > 0.1 && q.stray < 20, `the ${q.name} eye draws the model where it sees it: ${JSON.stringify(sbs)}`);
  assert.notEqual(sbs[0].sig, sbs[1].sig, 'the two eyes see the model from different places');
  // Dual output (polarised dual projection): the left eye here, the right eye in a second window
  // drawn from the same camera; both checked by their pixels, the right eye's read back from the
  // second window's canvas and boxed through the right eye's camera at that window's size.
  const [popup] = await Promise.all([page.waitForEvent('popup'), page.getByLabel('Viewports').selectOption('dual')]);
  await page.waitForFunction(() => Number(window.cad2moViewer.dual?.canvas.dataset.rendered) > 0);
  const [left] = await count();
  const right = await page.evaluate(async () => {
    const v = window.cad2moViewer;
    const px = await window.e2ePixels.read(v.dual.canvas);
    const { w, h } = px;
    const box = v.screenBox(undefined, { x: 0, y: 0, w, h, camera: v.eye('right', v.dual.win.innerWidth / v.dual.win.innerHeight) });
    const { share, stray } = window.e2ePixels.count(px, { x0: 2, y0: 2, x1: w - 2, y1: h - 2 }, box, 2);
    return { name: 'right', share, stray, size: [w, h], title: v.dual.win.document.title, eyes: Math.hypot(...[12, 13, 14].map((k) => v.eye('left', 1).matrixWorld.elements[k] - v.eye('right', 1).matrixWorld.elements[k])) };
  });
  await page.screenshot({ path: join(shots, `ws-${name}-dual.png`) });
  await popup.screenshot({ path: join(shots, `ws-${name}-dual-right-eye.png`) });
  assert.equal(left.name, 'left');
  for (const q of [left, right]) assert.ok(q.share > 0.1 && q.stray < 20, `dual output: the ${q.name} eye draws the model where it sees it: ${JSON.stringify({ left, right })}`);
  assert.match(right.title, /right eye/);
  assert.ok(right.eyes > 0, 'the two eyes are apart');
  // Closing the second window (the user, or its projector's session) brings the single view back.
  await popup.close();
  await page.waitForFunction(() => document.querySelector('#view-layout').value === 'single' && !window.cad2moViewer.dual);
  const dual = { left: Number(left.share.toFixed(3)), right: Number(right.share.toFixed(3)), window: right.size };
  await page.getByLabel('Viewports').selectOption('single');
  const single = await count();
  assert.equal(single.length, 1);

  // Named views: the camera looks down against "up" (top) or horizontally (front, side), the
  // whole model in the window; Fit selection frames one small body so it fills the view.
  const camera = () =>
    page.evaluate(() => {
      const v = window.cad2moViewer;
      const d = v.controls.target.clone().sub(v.camera.position).normalize();
      const c = v.renderer.domElement;
      const b = v.screenBox();
      return { down: -d.dot(v.up), inside: b.x0 >= -1 && b.y0 >= -1 && b.x1 <= c.clientWidth + 1 && b.y1 <= c.clientHeight + 1, fwd: d.toArray() };
    });
  const views = {};
  for (const view of ['top', 'front', 'side', 'iso']) {
    await page.getByLabel('Named view').selectOption(view);
    views[view] = await camera();
    assert.ok(views[view].inside, `${name}: the ${view} view shows the whole model: ${JSON.stringify(views[view])}`);
  }
  assert.ok(views.top.down > 0.999, `the top view looks down: ${JSON.stringify(views.top)}`);
  for (const v of ['front', 'side']) assert.ok(Math.abs(views[v].down) < 1e-6, `the ${v} view is horizontal: ${JSON.stringify(views[v])}`);
  assert.ok(Math.abs(views.front.fwd.reduce((s, x, i) => s + x * views.side.fwd[i], 0)) < 1e-6, 'front and side are at right angles');
  assert.ok(views.iso.down > 0.1 && views.iso.down < 0.9, 'iso looks down obliquely');
  const fit = await page.evaluate(() => {
    const v = window.cad2moViewer;
    const c = v.renderer.domElement;
    // The body drawn smallest in the whole-model view.
    const span = (n) => {
      const b = v.screenBox(n);
      return Math.max(b.x1 - b.x0, b.y1 - b.y0);
    };
    const [small] = [...v.bodies.entries()].filter(([, b]) => b.hasMesh).map(([n]) => [n, span(n)]).sort((a, b) => a[1] - b[1]);
    v.onPick({ kind: 'body', name: small[0] });
    return { name: small[0], before: small[1], view: Math.min(c.clientWidth, c.clientHeight) };
  });
  await page.getByRole('button', { name: 'Fit selection' }).click();
  fit.after = await page.evaluate((n) => {
    const b = window.cad2moViewer.screenBox(n);
    return Math.max(b.x1 - b.x0, b.y1 - b.y0);
  }, fit.name);
  assert.ok(fit.after > 0.4 * fit.view && fit.after > 2 * fit.before, `Fit selection frames ${fit.name}: ${JSON.stringify(fit)}`);
  await page.getByLabel('Named view').selectOption('iso');
  // Transparency: every body's material see-through, a different picture, and back.
  const picture = () =>
    page.evaluate(async () => {
      const v = window.cad2moViewer;
      await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
      v.render();
      return { url: v.renderer.domElement.toDataURL(), opacities: [...new Set([...v.bodies.values()].flatMap((b) => b.materials.map((m) => (m.transparent ? m.opacity : 1))))] };
    });
  const solid = await picture();
  await page.getByLabel('Transparent').check();
  const seeThrough = await picture();
  await page.screenshot({ path: join(shots, `ws-${name}-transparent.png`) });
  assert.deepEqual(seeThrough.opacities, [0.35], 'every body is see-through');
  assert.notEqual(seeThrough.url, solid.url, 'the see-through picture differs');
  await page.getByLabel('Transparent').uncheck();
  assert.deepEqual((await picture()).opacities, [1], 'solid again');

  // Collision shapes: each body's convex shape from the package, drawn over it, and hidden again.
  const plain = await page.evaluate(() => window.cad2moViewer.renderer.domElement.toDataURL());
  await page.getByRole('checkbox', { name: 'Collision shapes', exact: true }).check();
  const shapes = await page.evaluate(async () => {
    const v = window.cad2moViewer;
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    v.render();
    return { n: v.collisionShapes?.size ?? 0, visible: [...(v.collisionShapes?.values() || [])].filter((m) => m.visible).length, picture: v.renderer.domElement.toDataURL() };
  });
  assert.ok(shapes.n >= 10 && shapes.visible === shapes.n, `the hand's collision shapes are shown: ${shapes.n} (${shapes.visible} visible)`);
  assert.notEqual(shapes.picture, plain, 'the shapes are drawn');
  await page.screenshot({ path: join(shots, `ws-${name}-collision-shapes.png`) });
  await page.getByRole('checkbox', { name: 'Collision shapes', exact: true }).uncheck();
  assert.equal(await page.evaluate(() => [...window.cad2moViewer.collisionShapes.values()].filter((m) => m.visible).length), 0, 'hidden again');

  // The measuring tool: two points picked on the meshes, their distance shown.
  await page.getByRole('button', { name: 'Measure' }).click();
  const canvas = await page.locator('.stage canvas').boundingBox();
  const targets = await page.evaluate(() => {
    const v = window.cad2moViewer;
    return [...v.bodies.entries()].filter(([, b]) => b.hasMesh).map(([n]) => {
      const b = v.screenBox(n);
      return { n, x: (b.x0 + b.x1) / 2, y: (b.y0 + b.y1) / 2 };
    });
  });
  let picked = 0;
  for (const t of targets) {
    for (const [dx, dy] of [[0, 0], [4, 0], [-4, 0], [0, 4], [0, -4]]) {
      const x = t.x + dx;
      const y = t.y + dy;
      if (x < 2 || y < 2 || x > canvas.width - 2 || y > canvas.height - 2) continue;
      const before = await page.locator('.measure-out').textContent();
      await page.mouse.click(canvas.x + x, canvas.y + y);
      if ((await page.locator('.measure-out').textContent()) !== before) {
        picked++;
        break;
      }
    }
    if (picked === 2) break;
  }
  assert.equal(picked, 2, 'two points picked on the model');
  const distance = Number(await page.locator('.measure-out').getAttribute('data-distance'));
  assert.ok(distance > 0, `a distance is shown: ${await page.locator('.measure-out').textContent()}`);
  assert.match(await page.locator('.measure-out').textContent(), /^Distance [\d.e-]+ mm$/);
  await page.screenshot({ path: join(shots, `ws-${name}-measure.png`) });
  await page.getByRole('button', { name: 'Stop measuring' }).click();
  await grid.check();
  return { quad: quad.map((q) => Number(q.share.toFixed(3))), sbs: sbs.map((q) => Number(q.share.toFixed(3))), dual, distance, collisionShapes: shapes.n, views: Object.keys(views), fit };
}

/**
 * Immersive VR (WebXR): the Enter VR button is enabled only where the browser says an
 * immersive-vr session works; headless Chromium has none, so here it is disabled with the
 * reason as its tooltip (the decision itself is unit-tested in src/viewer/xr-data.test.js).
 */
export async function checkVR(page) {
  const btn = page.locator('#enter-vr');
  await page.waitForFunction(() => document.querySelector('#enter-vr')?.dataset.xr !== 'checking', null, { timeout: 10_000 });
  const state = await btn.evaluate((b) => ({
    xr: b.dataset.xr,
    disabled: b.disabled,
    title: b.title,
    wrapTitle: b.parentElement.title,
    hasXR: 'xr' in navigator,
    supported: navigator.xr ? null : false,
  }));
  if (state.hasXR) {
    state.supported = await page.evaluate(() =>
      Promise.race([navigator.xr.isSessionSupported('immersive-vr').catch(() => false), new Promise((r) => setTimeout(() => r('no answer'), 6000))]),
    );
  }
  assert.ok(state.supported === false || state.supported === 'no answer', `this browser offers immersive VR: the test expects a headless one without: ${JSON.stringify(state)}`);
  assert.equal(state.xr, 'unsupported', JSON.stringify(state));
  assert.equal(state.disabled, true, `Enter VR is disabled without immersive VR: ${JSON.stringify(state)}`);
  assert.match(state.title, /WebXR|VR device|immersive VR|secure page/, `the reason is its tooltip: ${JSON.stringify(state)}`);
  assert.equal(state.wrapTitle, state.title, 'the reason shows over the disabled button too');
  return state;
}

/** Pairs of shown diagram names whose boxes on screen overlap (at most 8 named), in the diagram view `v`. */
function labelOverlaps(v) {
  const texts = [...v.querySelectorAll('svg g[data-component] > text')].filter((t) => t.getAttribute('visibility') !== 'hidden');
  const boxes = texts.map((t) => ({ name: t.textContent, r: t.getBoundingClientRect() })).filter((b) => b.r.width > 0 && b.r.height > 0);
  boxes.sort((a, b) => a.r.left - b.r.left);
  const pairs = [];
  let count = 0;
  for (let i = 0; i < boxes.length; i++) {
    const a = boxes[i].r;
    for (let j = i + 1; j < boxes.length && boxes[j].r.left < a.right - 0.5; j++) {
      const b = boxes[j].r;
      if (b.top < a.bottom - 0.5 && a.top < b.bottom - 0.5) {
        count++;
        if (pairs.length < 8) pairs.push(`${boxes[i].name} / ${boxes[j].name}`);
      }
    }
  }
  const abbreviated = texts.filter((t) => t.textContent !== t.closest('g[data-component]').dataset.component).length;
  return { shown: boxes.length, count, pairs, abbreviated };
}

/**
 * Every component name of the diagram in view is at least 9 px high on screen, or hidden, and no
 * two names shown overlap; a screenshot.
 */
export async function checkDiagram(page, { name, shots, contacts = false }) {
  await page.getByRole('tab', { name: 'Modelica diagram', exact: true }).click();
  await page.locator('.diagram-view svg g[data-component]').first().waitFor();
  const look = await page.locator('.diagram-view').evaluate((v) => {
    const texts = [...v.querySelectorAll('svg g[data-component] > text')];
    const shown = texts.filter((t) => t.getAttribute('visibility') !== 'hidden');
    return { components: texts.length, shown: shown.length, small: shown.filter((t) => t.getBoundingClientRect().height < 9).map((t) => t.textContent).slice(0, 5), icons: v.querySelectorAll('g.icon').length };
  });
  await page.screenshot({ path: join(shots, `diagram-${name}.png`) });
  // Its own full-width view: the dock spans the workspace, under the 3D view and the side panel.
  look.width = await page.evaluate(() => {
    const w = document.querySelector('.workspace').getBoundingClientRect();
    const d = document.querySelector('.workspace > .dock').getBoundingClientRect();
    const s = document.querySelector('.workspace > .side').getBoundingClientRect();
    return { dock: Math.round(d.width), workspace: Math.round(w.width), under: d.top >= s.bottom - 1 };
  });
  assert.ok(look.width.dock >= look.width.workspace - 2 && look.width.under, `${name}: the diagram is not full width: ${JSON.stringify(look.width)}`);
  assert.deepEqual(look.small, [], `${name}: diagram names below 9 px`);
  // No name covers another: the boxes of the names shown do not overlap (a name that would
  // collide is abbreviated or hidden; the full name is the component's tooltip).
  const clash = await page.locator('.diagram-view').evaluate(labelOverlaps);
  look.labels = { shown: clash.shown, abbreviated: clash.abbreviated };
  assert.deepEqual(clash.pairs, [], `${name}: ${clash.count} pairs of diagram names overlap at the default zoom (of ${clash.shown} shown)`);
  assert.equal(look.icons, look.components, `${name}: an icon per component`);
  // Zoomed out: names are hidden once their components are small on screen, never drawn
  // unreadable; zoomed back in they return.
  const labels = () =>
    page.locator('.diagram-view').evaluate((v) => {
      const shown = [...v.querySelectorAll('svg g[data-component] > text')].filter((t) => t.getAttribute('visibility') !== 'hidden');
      return { hidden: Number(v.querySelector('svg').dataset.hiddenLabels), shown: shown.length, small: shown.filter((t) => t.getBoundingClientRect().height < 9).length };
    });
  const atDefault = await labels();
  let outs = 0;
  let far = atDefault;
  while (far.hidden <= atDefault.hidden && outs < 12) {
    await page.getByRole('button', { name: 'Zoom out', exact: true }).click();
    outs++;
    far = await labels();
    assert.equal(far.small, 0, `${name}: zoomed out ${outs}×, names below 9 px are drawn: ${JSON.stringify(far)}`);
  }
  assert.ok(far.hidden > atDefault.hidden, `${name}: zooming out hides names: ${JSON.stringify({ atDefault, far, outs })}`);
  await page.screenshot({ path: join(shots, `diagram-${name}-zoomed-out.png`) });
  for (let i = 0; i < outs; i++) await page.getByRole('button', { name: 'Zoom in', exact: true }).click();
  assert.equal((await labels()).hidden, atDefault.hidden, `${name}: zoomed back in, the names return`);
  look.zoomOuts = outs;
  if (contacts) look.contacts = await checkContactWires(page, { name, shots });
  return look;
}

/**
 * The Mechatronics diagram of a model with collision shapes: a contact force beside each body
 * with one short wire to it, never a bundle across the sheet (issue 30). Each contact wire (its
 * polyline's connect title names a collisionForce_) is at most 4 median component widths long
 * and spans less than a tenth of the drawing either way; no wire leaves the collision world.
 */
async function checkContactWires(page, { name, shots }) {
  await page.getByLabel('Model', { exact: true }).selectOption('Mechatronics');
  await page.locator('.diagram-status', { hasText: /^Mechatronics:/ }).waitFor();
  const wires = await page.locator('.diagram-view svg').evaluate((svg) => {
    const vb = svg.viewBox.baseVal;
    const widths = [...svg.querySelectorAll('g[data-component] > rect')].map((r) => Number(r.getAttribute('width'))).sort((a, b) => a - b);
    const median = widths[Math.floor(widths.length / 2)];
    const lines = [...svg.querySelectorAll('polyline')].map((p) => ({
      title: p.querySelector('title')?.textContent || '',
      pts: p.getAttribute('points').trim().split(/\s+/).map((xy) => xy.split(',').map(Number)),
    }));
    const contact = lines.filter((l) => /^connect\(collisionForce_/.test(l.title));
    const measured = contact.map((l) => {
      const xs = l.pts.map((p) => p[0]);
      const ys = l.pts.map((p) => p[1]);
      let length = 0;
      for (let i = 1; i < l.pts.length; i++) length += Math.abs(l.pts[i][0] - l.pts[i - 1][0]) + Math.abs(l.pts[i][1] - l.pts[i - 1][1]);
      return { title: l.title, length, spanX: Math.max(...xs) - Math.min(...xs), spanY: Math.max(...ys) - Math.min(...ys) };
    });
    return {
      sheet: [vb.width, vb.height],
      median,
      forces: svg.querySelectorAll('g[data-component^="collisionForce_"]').length,
      fromWorld: lines.filter((l) => /collisionWorld/.test(l.title)).length,
      measured,
    };
  });
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: join(shots, `diagram-${name}-mechatronics.png`) });
  assert.ok(wires.forces >= 2 && wires.measured.length === wires.forces, `${name}: a wire per contact force: ${JSON.stringify(wires)}`);
  assert.equal(wires.fromWorld, 0, `${name}: no wires from the collision world`);
  const long = wires.measured.filter((w) => w.length > 4 * wires.median || w.spanX >= 0.1 * wires.sheet[0] || w.spanY >= 0.1 * wires.sheet[1]);
  assert.deepEqual(long, [], `${name}: contact wires that are long or cross the sheet (median component width ${wires.median}, sheet ${wires.sheet})`);
  return { forces: wires.forces, longest: Math.max(...wires.measured.map((w) => w.length)), median: wires.median, sheet: wires.sheet };
}
