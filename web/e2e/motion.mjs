// The Motion tab, end to end (part of ui.mjs, on the model view of the uploaded arm): a motion
// made in the UI from a moved slider pose and a tool keyframe placed by dragging the IK gizmo,
// a keyframe problem shown at its keyframe, playing and scrubbing, the uPlot charts drawn, the
// sizing with a ranked alternative applied to the drive, joint limits with their defaults, and
// the regenerated package's Mechatronics.mo instantiating the motion's table (Motions sub-package).

import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { unzipSync, strFromU8 } from 'fflate';

const canvasImage = (page) => page.evaluate(() => window.cad2moViewer.renderer.domElement.toDataURL());

/** How many pixels each uPlot canvas has drawn (non-transparent, not white). */
async function plotPixels(page) {
  return page.evaluate(() =>
    [...document.querySelectorAll('.plots-box .uplot')].map((root) => {
      const c = root.querySelector('canvas');
      const img = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let drawn = 0;
      for (let i = 0; i < img.length; i += 4) if (img[i + 3] > 0 && img[i] + img[i + 1] + img[i + 2] < 740) drawn++;
      return { plot: root.parentElement.dataset.plot, w: c.width, h: c.height, drawn };
    }),
  );
}

/**
 * @param {import('playwright-core').Page} page  on the model view, version 1 of the arm
 * @param {{joint: string, step: Function, shot: Function, downloads: string, strict: boolean}} o
 *   strict: false tolerates a service that cannot size drives yet (409)
 * @returns {Promise<{motion: string, package: string, exported: boolean}>}
 */
export async function motionSteps(page, { joint, step, shot, downloads, strict }) {
  const name = 'pick';
  // ---- A pose away from the CAD pose: every joint slider moved by keyboard.
  step('motion: pose by the sliders');
  await page.getByRole('tab', { name: 'Structure' }).click();
  const sliders = page.locator('.slider input[type=range]');
  const n = await sliders.count();
  assert.ok(n >= 2, `the arm has two revolute joints (${n} sliders)`);
  for (let i = 0; i < n; i++) {
    await sliders.nth(i).focus();
    for (let k = 0; k < 30; k++) await page.keyboard.press(i % 2 ? 'ArrowLeft' : 'ArrowRight');
  }

  // ---- Create the motion: CAD pose → the slider pose.
  step('motion: create');
  await page.getByRole('tab', { name: 'Motion' }).click();
  await page.getByLabel('New motion name').fill(`${name} draft`);
  await page.getByRole('button', { name: 'New motion', exact: true }).click();
  await page.locator(`form[aria-label="Motion ${name} draft"]`).waitFor();
  await page.locator('#motion-play').waitFor({ timeout: 60_000 });
  // Renamed.
  await page.getByLabel('Motion name', { exact: true }).fill(name);
  await page.getByRole('button', { name: 'Save motion' }).click();
  const editor = page.locator(`form[aria-label="Motion ${name}"]`);
  await editor.waitFor();
  await page.locator(`.motion-list li[data-motion="${name}"]`).waitFor();
  assert.equal(await page.locator('.motion-list li').count(), 1);
  assert.equal(await editor.locator('li.keyframe').count(), 2);
  // The sliders' pose was captured into keyframe 1 (joint values, in degrees).
  const kf1 = editor.locator('li[data-keyframe="1"]');
  const captured = await page.locator('table.keyframe-table td[data-keyframe="1"] input').first().inputValue();
  assert.ok(Math.abs(Number(captured)) > 1, `keyframe 1 holds the moved pose: ${captured}`);
  await page.locator('#motion-play').waitFor({ timeout: 60_000 });

  // ---- The tool gizmo on the fore link: drag it, IK moves the arm live; add the pose as a keyframe.
  step('motion: IK gizmo');
  const frameSel = page.locator('#gizmo-frame');
  const options = await frameSel.locator('option').allTextContents();
  const fore = options.find((o) => /^LINK_FORE · CG/.test(o)) || options.find((o) => /^LINK_FORE/.test(o));
  assert.ok(fore, `a frame on the fore link: ${options.join(', ')}`);
  await frameSel.selectOption({ label: fore });
  await page.getByLabel('Show the gizmo in 3D').check();
  await page.waitForFunction(() => window.cad2moGizmo);
  const before = await canvasImage(page);
  const at = await page.evaluate(() => {
    const p = window.cad2moGizmo.target.position;
    return window.cad2moViewer.toScreen([p.x, p.y, p.z]);
  });
  const camera = () => page.evaluate(() => window.cad2moViewer.camera.position.toArray());
  const cameraBefore = await camera();
  const box = await page.locator('.stage canvas').boundingBox();
  const x0 = box.x + at.x;
  const y0 = box.y + at.y;
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  await page.mouse.move(x0 + 25, y0 + 20, { steps: 8 });
  await page.waitForTimeout(300);
  await page.mouse.move(x0 + 45, y0 + 35, { steps: 8 });
  await page.mouse.up();
  const ik = page.locator('.ik-out');
  await page.waitForFunction(() => Number(document.querySelector('.ik-out')?.dataset.count) >= 2);
  assert.match(await ik.textContent(), /^IK (reached|closest pose): /);
  await page.waitForTimeout(200);
  assert.notEqual(await canvasImage(page), before, 'dragging the gizmo moves the arm (IK)');
  assert.deepEqual(await camera(), cameraBefore, 'dragging the gizmo does not orbit the camera');
  await shot(page, '16-motion-gizmo');
  await editor.getByRole('button', { name: 'Add tool keyframe from the gizmo' }).click();
  const kf2 = editor.locator('li[data-keyframe="2"]');
  await kf2.waitFor();
  assert.equal(await kf2.getByLabel('Kind').inputValue(), 'tool');
  await kf2.getByLabel('Interpolation').selectOption('jerk');
  await kf2.getByLabel('Dwell [s]').fill('0.2');
  await kf2.getByLabel('Dwell [s]').press('Tab');
  await page.getByLabel('Show the gizmo in 3D').uncheck();

  // ---- A keyframe the planner refuses: the problem shows at that keyframe; then fixed.
  step('motion: keyframe problem');
  const first = page.locator('table.keyframe-table td[data-keyframe="1"] input').first();
  await first.fill('400');
  await first.press('Tab');
  await editor.getByRole('button', { name: 'Save motion' }).click();
  const problem = page.locator('li[data-keyframe="1"] .kf-problem');
  await problem.waitFor();
  assert.match(await problem.textContent(), /limit/i);
  await problem.scrollIntoViewIfNeeded();
  await shot(page, '17-motion-problem');
  await page.locator('table.keyframe-table td[data-keyframe="1"] input').first().fill(captured);
  await page.locator('table.keyframe-table td[data-keyframe="1"] input').first().press('Tab');
  await editor.getByRole('button', { name: 'Save motion' }).click();
  await page.locator('#motion-play').waitFor();
  assert.equal(await page.locator('.kf-problem').count(), 0, 'no problem left');
  const marks = await page.locator('.timeline-mark').count();
  assert.equal(marks, 3, 'the timeline shows the three keyframes');
  assert.match(await page.locator('li[data-keyframe="2"] .kf-time').textContent(), /at [\d.]+ s · IK/);

  // ---- Play at real speed, pause, scrub.
  step('motion: play');
  const player = page.locator('.player-box');
  const still = await canvasImage(page);
  const t0 = Date.now();
  await page.getByRole('button', { name: 'Play' }).click();
  await page.waitForTimeout(400);
  assert.equal(await player.getAttribute('data-playing'), 'true');
  const tPlay = Number(await player.getAttribute('data-time'));
  const wall = (Date.now() - t0) / 1000; // measured after the time was read: an upper bound
  assert.ok(tPlay > 0.1 && tPlay <= wall + 0.05, `plays at real speed: motion time ${tPlay} s after ${wall} s`);
  assert.notEqual(await canvasImage(page), still, 'playing moves the arm');
  await page.locator('#motion-play').click();
  // On a slow machine the motion may have ended just before that click (the button then said
  // Play, and the click started it again from 0): pause that playback.
  if ((await player.getAttribute('data-playing')) === 'true') await page.locator('#motion-play').click();
  assert.equal(await player.getAttribute('data-playing'), 'false', 'paused by the button');
  const paused = await player.getAttribute('data-time');
  await page.waitForTimeout(250);
  assert.equal(await player.getAttribute('data-time'), paused, 'paused');
  // Step: one sample forward and back, staying paused (at the end, forward stays there).
  const sample = Number(await page.locator('#motion-scrub').getAttribute('step'));
  const end = Number(await page.locator('#motion-scrub').getAttribute('max'));
  await page.locator('#motion-step').click();
  const stepped = Number(await player.getAttribute('data-time'));
  assert.ok(Math.abs(stepped - Math.min(Number(paused) + sample, end)) < 2e-3 && (await player.getAttribute('data-playing')) === 'false', `Step » moves one sample (${sample} s) from ${paused}: ${stepped}`);
  await page.locator('#motion-step-back').click();
  assert.ok(Math.abs(Number(await player.getAttribute('data-time')) - Math.max(stepped - sample, 0)) < 2e-3, '« Step goes back one sample');
  // The same with the keys, the focus on the Step button: → and ← step, Space plays and pauses
  // (not clicking the focused button), End and Home go to the ends.
  const back1 = Number(await player.getAttribute('data-time'));
  await page.locator('#motion-step').focus();
  await page.keyboard.press('ArrowRight');
  assert.ok(Math.abs(Number(await player.getAttribute('data-time')) - Math.min(back1 + sample, end)) < 2e-3, '→ steps forward');
  await page.keyboard.press('ArrowLeft');
  assert.ok(Math.abs(Number(await player.getAttribute('data-time')) - back1) < 2e-3, '← steps back');
  await page.keyboard.press('Space');
  assert.equal(await player.getAttribute('data-playing'), 'true', 'Space plays');
  await page.keyboard.press('Space');
  assert.equal(await player.getAttribute('data-playing'), 'false', 'Space pauses');
  await page.keyboard.press('End');
  assert.ok(Math.abs(Number(await player.getAttribute('data-time')) - end) < 2e-3, 'End goes to the end');
  await page.keyboard.press('Home');
  assert.equal(Number(await player.getAttribute('data-time')), 0, 'Home goes to the start');
  const duration = Number(await page.locator('#motion-scrub').getAttribute('max'));
  assert.ok(duration > 0, 'the motion takes time');
  await page.locator('#motion-scrub').fill(String(duration / 2));
  assert.ok(Math.abs(Number(await player.getAttribute('data-time')) - duration / 2) < 0.02, 'the scrub slider sets the time');
  // To the end, by playing.
  await page.getByRole('button', { name: 'Play' }).click();
  await page.waitForFunction(() => document.querySelector('.player-box').dataset.playing === 'false', null, { timeout: 30_000 });
  assert.ok(Math.abs(Number(await player.getAttribute('data-time')) - duration) < 1e-3, 'played to the end');

  // ---- Plots: q, qd, qdd, torque and the drive's torque–speed plane, drawn.
  step('motion: plots');
  const sized = page.locator(`.plot[data-plot="ts-${joint}"] .uplot, .ts-missing[data-joint="${joint}"], .sizing-unavailable, .sizing-box .error`).first();
  await sized.waitFor({ timeout: 60_000 });
  const sizingAvailable = !(await page.locator('.sizing-unavailable').count());
  if (!sizingAvailable) {
    assert.ok(!strict, `sizing: ${await page.locator('.sizing-unavailable').textContent()}`);
    step(`motion: NOTE ${await page.locator('.sizing-unavailable').textContent()}; the torque–speed plot and the sizing steps are skipped`);
  }
  assert.equal(await page.locator('.sizing-box .error').count(), 0, 'no sizing error');
  const pixels = await plotPixels(page);
  step(`plot pixels ${JSON.stringify(pixels)}`);
  // A drive whose gear lacks its input inertia (the drive's gear at a ratio its catalogue does
  // not rate) has no motor torque, so no torque–speed plot, and says why.
  const tsMissing = (await page.locator(`.ts-missing[data-joint="${joint}"]`).count()) > 0;
  if (tsMissing) assert.match(await page.locator(`.ts-missing[data-joint="${joint}"]`).textContent(), /missing gear\.J_in/);
  for (const key of ['q', 'qd', 'qdd', 'tau', ...(sizingAvailable && !tsMissing ? [`ts-${joint}`] : [])]) {
    const p = pixels.find((x) => x.plot === key);
    assert.ok(p, `a ${key} plot: ${JSON.stringify(pixels)}`);
    assert.ok(p.drawn > 500, `the ${key} plot has drawn: ${JSON.stringify(p)}`);
  }
  // Clicking a chart seeks: the 3D time follows.
  // (locator.click scrolls the chart out from under the dock's sticky player if needed)
  const q = page.locator('.plot[data-plot="q"] .u-over');
  await q.scrollIntoViewIfNeeded();
  const qb = await q.boundingBox();
  await q.click({ position: { x: qb.width * 0.25, y: qb.height / 2 } });
  const seeked = Number(await player.getAttribute('data-time'));
  assert.ok(Math.abs(seeked - duration * 0.25) < duration * 0.05, `a click on the plot seeks to ${seeked} of ${duration}`);
  await shot(page, '18-motion-plots');

  // ---- Sizing: the drive's checks and a ranked alternative applied.
  const appliedRatio = sizingAvailable ? await sizingSteps(page, { joint, step, shot }) : null;

  // ---- Closed-loop simulation (issue 28): the drives along the motion, the verdict, the table.
  if (sizingAvailable) {
    step('motion: simulation');
    await page.locator('.simulation-box input').first().fill('50');
    await page.getByRole('button', { name: 'Simulate' }).click();
    const answered = page.locator(`table.simulation-drives tr[data-joint="${joint}"], .simulation-out .error`).first();
    await answered.waitFor({ timeout: 120_000 });
    assert.equal(await page.locator('.simulation-out .error').count(), 0, `no simulation error: ${await page.locator('.simulation-out').textContent()}`);
    const cells = await page.locator(`table.simulation-drives tr[data-joint="${joint}"] td`).allTextContents();
    assert.match(cells[2], / \/ .* A$/, `current against its limit: ${cells}`);
    assert.match(await page.locator('.simulation-out .verdict').textContent(), /holds the path|does not hold the path/);
    // Issue 29: the simulated motion checked for contact, stated in one line.
    assert.match(await page.locator('.simulation-out .contact-line').textContent(), /contact along the simulated motion/);
    // Issue 28's plots: the tracking error of every joint, the current against its limits.
    await page.locator('.plot[data-plot="tracking"] .uplot').waitFor();
    await page.locator('.plot[data-plot="sim-i"] .uplot').waitFor();
    assert.match(await page.locator('.plot[data-plot="tracking"] .u-legend').textContent(), new RegExp(joint));
    // The simulated motion animates, with the planned one as a ghost; the two differ by the error.
    await page.getByLabel('Play the simulated motion (the planned one as a ghost)').check();
    const dur = Number(await page.locator('#motion-scrub').getAttribute('max'));
    await page.locator('#motion-scrub').fill(String(dur / 2));
    const ghost = await page.evaluate(() => {
      const v = window.cad2moViewer;
      return { groups: v.ghost?.size ?? 0, visible: [...(v.ghost?.values() || [])].filter((g) => g.parent).length };
    });
    assert.ok(ghost.groups > 0 && ghost.visible === ghost.groups, `the planned motion is drawn as a ghost: ${JSON.stringify(ghost)}`);
    await shot(page, '18c-motion-simulation');
    await page.getByLabel('Play the simulated motion (the planned one as a ghost)').uncheck();
    assert.equal(await page.evaluate(() => window.cad2moViewer.ghost ?? null), null, 'the ghost goes with the switch');
  }

  // ---- Joint limits: defaults greyed as placeholders; a custom speed, then back to defaults.
  step('motion: limits');
  const row = page.locator(`table.limits tr[data-joint="${joint}"]`);
  const speed = row.locator('input[name=speed]');
  assert.equal(await speed.inputValue(), '', 'no custom speed: empty, the default as placeholder');
  assert.match(await speed.getAttribute('placeholder'), /^171\.8/, 'default 3 rad/s shown in °/s');
  await speed.fill('90');
  await row.getByRole('button', { name: `Save the limits of ${joint}` }).click();
  await page.locator(`table.limits tr.custom[data-joint="${joint}"]`).waitFor();
  assert.equal(await page.locator(`table.limits tr[data-joint="${joint}"] input[name=speed]`).inputValue(), '90');
  await page.getByRole('button', { name: `Reset the limits of ${joint} to the defaults` }).click();
  await page.locator(`table.limits tr.custom[data-joint="${joint}"]`).waitFor({ state: 'detached' });

  // ---- The regenerated package carries the motion.
  step('motion: package');
  await page.getByRole('tab', { name: 'Drives' }).click();
  if (appliedRatio !== null) {
    // The Drives tab shows the applied drive.
    await page.locator(`table.drives tr[data-joint="${joint}"] td.num`).filter({ hasText: new RegExp(`^${appliedRatio}$`) }).waitFor();
  }
  const [pkg] = await Promise.all([page.waitForEvent('download', { timeout: 60_000 }), page.getByRole('button', { name: 'Regenerate and download package' }).click()]);
  const path = join(downloads, `motion-${pkg.suggestedFilename()}`);
  await pkg.saveAs(path);
  const files = unzipSync(new Uint8Array(readFileSync(path)), { filter: (f) => /\/(Mechatronics\.mo|Motions\/[^/]+\.mo)$/.test(f.name) });
  const text = (re) => {
    const k = Object.keys(files).find((f) => re.test(f));
    return k ? strFromU8(files[k]) : '';
  };
  const mech = text(/\/Mechatronics\.mo$/);
  assert.ok(mech.length > 0, 'the package has a Mechatronics.mo');
  // Mechatronics.mo instantiates the motion's table from the Motions sub-package; its drives follow it.
  assert.match(mech, new RegExp(`\\bMotions\\.${name} motion_${name}\\b`), `Mechatronics.mo instantiates Motions.${name}`);
  assert.match(mech, /parameter Integer motion\b/, 'Mechatronics.mo selects the motion by a parameter');
  assert.match(text(/\/Motions\/package\.mo$/), /package Motions\b/, 'the package has a Motions sub-package');
  const table = text(new RegExp(`/Motions/${name}\\.mo$`));
  assert.match(table, new RegExp(`block ${name}\\b[\\s\\S]*CombiTimeTable[\\s\\S]*end ${name};`), `Motions/${name}.mo is the motion's table`);
  const exported = true;

  // ---- Delete the motion (the later steps change the model's joints).
  step('motion: delete');
  await page.getByRole('tab', { name: 'Motion' }).click();
  await editor.getByRole('button', { name: 'Delete motion' }).click();
  await page.getByRole('dialog').getByRole('button', { name: 'Delete' }).click();
  await editor.waitFor({ state: 'detached' });
  assert.equal(await page.locator(`.motion-list li[data-motion="${name}"]`).count(), 0);
  await page.getByRole('tab', { name: 'Drives' }).click();
  return { motion: name, package: path, exported };
}

/** The drive's sizing: checks with verdicts, a ranked alternative applied to the drive. */
async function sizingSteps(page, { joint, step, shot }) {
  step('motion: sizing');
  const sizing = page.locator(`section.sizing[data-joint="${joint}"]`);
  await sizing.waitFor();
  assert.ok((await sizing.locator('table.checks tbody tr').count()) > 0, 'the drive has checks');
  for (const v of await sizing.locator('td.verdict').allTextContents()) assert.match(v, /^(pass|pass, below reserve|FAIL|not evaluated)$/);
  assert.ok((await sizing.locator('table.checks thead th', { hasText: 'Source of the limit' }).count()) === 1, 'the source column');
  // Without an amplifier (or without the gear input inertia the motor torque needs) the voltage
  // is not evaluated, and says what is missing.
  assert.match(await sizing.locator("tr[data-check=voltage] td.source").textContent(), /missing: (amplifier|gear\.J_in)/);
  // The settings: a 10 % reserve, a 2 s dwell and a screw life, sized again; the summary states them.
  const settings = page.getByRole('form', { name: 'Sizing settings' });
  await settings.locator('input[name=reservePercent]').fill('10');
  await settings.locator('input[name=reservePercent]').dispatchEvent('change');
  await settings.locator('input[name=dwell]').fill('2');
  await settings.locator('input[name=dwell]').dispatchEvent('change');
  // The required life of a ball or lead screw (a revolute joint's drive has no screw check).
  await settings.locator('input[name=screwLife]').fill('20000');
  await settings.locator('input[name=screwLife]').dispatchEvent('change');
  await settings.getByRole('button', { name: 'Size again' }).click();
  await page.locator('.sizing-summary', { hasText: 'Reserve 10 % · duty cycle' }).waitFor();
  assert.match(await page.locator('.sizing-summary').textContent(), /dwell 2 s/);
  assert.match(await page.locator('.sizing-summary').textContent(), /required screw life 20000 h/);
  // A refused setting: 422 naming the field, the form stays.
  await settings.locator('input[name=reservePercent]').fill('150');
  await settings.locator('input[name=reservePercent]').dispatchEvent('change');
  await page.getByRole('form', { name: 'Sizing settings' }).getByRole('button', { name: 'Size again' }).click();
  await page.getByText(/reserve/).filter({ hasText: 'must be at least 0 and below 1' }).first().waitFor();
  await page.getByRole('form', { name: 'Sizing settings' }).locator('input[name=reservePercent]').fill('20');
  await page.getByRole('form', { name: 'Sizing settings' }).locator('input[name=reservePercent]').dispatchEvent('change');
  await page.getByRole('form', { name: 'Sizing settings' }).getByRole('button', { name: 'Size again' }).click();
  await sizing.waitFor();
  for (const li of await sizing.locator('ol.alternatives li').all()) assert.match(await li.textContent(), /limited by .*(passes|fails|incomplete)|(passes|fails|incomplete).*limited by/);
  const apply = sizing.getByRole('button', { name: /^Apply / }).first();
  await apply.waitFor();
  const label = await apply.getAttribute('aria-label');
  const ratio = /· ratio ([\d.e+-]+) ·/.exec(await sizing.locator('ol.alternatives li').first().textContent())[1];
  await shot(page, '19-motion-sizing');
  await apply.click();
  await page.locator('.sizing-out .applied').waitFor();
  const applied = /^Apply (.*) with (.*) to /.exec(label);
  const after = await page.evaluate(async (j) => {
    const id = location.hash.split('/')[2];
    const r = await fetch(`/api/models/${id}/drives`, { headers: { 'X-Requested-With': 'cad2mo' } });
    return (await r.json()).drives.find((d) => d.joint === j);
  }, joint);
  const lib = await page.evaluate(async () => (await (await fetch('/api/library/instances')).json()).map((i) => [i.id, i.name]));
  const names = new Map(lib);
  assert.equal(names.get(after.motor_instance), applied[1], `the drive's motor is the alternative's: ${JSON.stringify(after)}`);
  assert.equal(names.get(after.gear_instance), applied[2], `the drive's gear is the alternative's: ${JSON.stringify(after)}`);
  return ratio;
}
