// End-to-end test of the browser UI in a real headless Chromium (Debian's chromium, driven by
// playwright-core). Started by tests/ui.rs against a freshly spawned service:
//
//   CAD2MO_URL          the service, e.g. http://127.0.0.1:41234
//   CAD2MO_BUNDLE       a CAD export zip to upload
//   CAD2MO_BUNDLE_V2    the same model after a CAD change that removed the first joint
//   CAD2MO_BUNDLE_BROKEN a truncated export, refused with the file, line and element
//   CAD2MO_BUNDLE_HEAVY a bundle whose conversion takes seconds (its progress is watched)
//   CAD2MO_SCREENSHOTS  folder for a screenshot of each main screen
//   CAD2MO_DOWNLOADS    folder for the downloaded package and library
//   CAD2MO_LIVE_HARNESS the live view's C test sender (tests/live/harness.c, compiled); without
//                       it the Live tab's stream is not tested
//
// Prints one JSON line at the end ({joint, package, library}) for the Rust side to check the
// downloaded package. Any failed expectation throws: exit code 1 with the reason.

import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { launch, waitForModel, checkModelPixels, checkLabels, installPixelProbe } from './lib.mjs';
import { motionSteps } from './motion.mjs';
import { resultsSteps } from './results.mjs';
import { liveSteps } from './live.mjs';
import { collisionSteps } from './collision.mjs';
import { diagramSteps } from './diagram.mjs';
import { sceneSteps } from './scene.mjs';
import { standaloneSteps } from './standalone.mjs';

const url = process.env.CAD2MO_URL;
const bundle = process.env.CAD2MO_BUNDLE;
const bundleV2 = process.env.CAD2MO_BUNDLE_V2;
const broken = process.env.CAD2MO_BUNDLE_BROKEN;
const heavy = process.env.CAD2MO_BUNDLE_HEAVY;
const shots = process.env.CAD2MO_SCREENSHOTS;
const downloads = process.env.CAD2MO_DOWNLOADS;
for (const [k, v] of Object.entries({ url, bundle, bundleV2, broken, heavy, shots, downloads })) assert.ok(v, `missing setting ${k}`);

const step = (s) => console.error(`e2e: ${s}`);
const shot = (page, name) => page.screenshot({ path: join(shots, `${name}.png`), fullPage: true });

const browser = await launch();
const consoleErrors = [];
try {
  const context = await browser.newContext({ viewport: { width: 1400, height: 900 }, acceptDownloads: true });
  const page = await context.newPage();
  await installPixelProbe(page);
  // Chromium logs every 4xx response as a console error; the refusals this test provokes on
  // purpose are 422s, anything else is a real error.
  page.on('console', (m) => m.type() === 'error' && !/status of 422/.test(m.text()) && consoleErrors.push(m.text()));
  page.on('pageerror', (e) => consoleErrors.push(String(e)));
  page.setDefaultTimeout(30_000);

  // ---- Models: upload the bundle by the drop zone's file input and wait for the conversion.
  step('models screen');
  await page.goto(url);
  await page.getByRole('heading', { name: 'Models', exact: true }).waitFor();
  await page.getByText('No models yet').waitFor();
  await shot(page, '1-models-empty');
  await checkLabels(page, 'the models page');
  // The drop zone is reachable by keyboard: Tab from the name field focuses its file input.
  await page.getByLabel('Model name (optional)').focus();
  await page.keyboard.press('Tab');
  assert.equal(await page.evaluate(() => document.activeElement.type), 'file');
  assert.match(await page.locator('.dropzone').getAttribute('class'), /\bfocus\b/);
  // A broken export is refused with the file, line and element, and nothing is stored.
  await page.locator('section.upload input[type=file]').setInputFiles(broken);
  const refusal = page.locator('section.upload .error');
  await refusal.waitFor();
  assert.match(await refusal.textContent(), /BROKEN\.xml:107:26: in Body "ARM".*<position> is not closed/);
  await shot(page, '1b-upload-refused');
  assert.equal(await page.locator('tr[data-model-id]').count(), 0);
  await page.locator('section.upload input[type=file]').setInputFiles(bundle);
  await page.waitForURL(/#\/models\/[^/]+\/versions\/1$/);
  step('model view');
  const stage = page.locator('.stage');
  await waitForModel(page);

  // ---- The 3D view rendered the model: non-background pixels where the meshes project.
  step('3D pixels');
  step(`pixels ${JSON.stringify(await checkModelPixels(page))}`);
  await checkLabels(page, 'the model view');
  await shot(page, '2-model-3d');

  // ---- The view is usable by keyboard: Shift+arrows orbit, + zooms.
  const canvas = stage.locator('canvas');
  const still = await page.evaluate(() => window.cad2moViewer.renderer.domElement.toDataURL());
  await canvas.focus();
  await page.keyboard.press('Shift+ArrowLeft');
  await page.keyboard.press('+');
  await page.waitForTimeout(150);
  assert.notEqual(await page.evaluate(() => window.cad2moViewer.renderer.domElement.toDataURL()), still, 'keys move the camera');
  await page.getByRole('button', { name: 'Reset view' }).click();
  await page.waitForTimeout(150);

  // ---- Click a body in the 3D view: the pick selects it (and the list marks it).
  step('pick in 3D');
  const target = await page.evaluate(() => {
    const v = window.cad2moViewer;
    for (const [name] of v.bodies) {
      const b = v.screenBox(name);
      if (Number.isFinite(b.x0) && b.x1 - b.x0 > 8) return { name, x: (b.x0 + b.x1) / 2, y: (b.y0 + b.y1) / 2 };
    }
    return null;
  });
  assert.ok(target, 'some body is on screen');
  const canvasBox = await stage.locator('canvas').boundingBox();
  // Try the body's centre and a few points around it: shapes may be hollow at the centre.
  let picked = '';
  for (const [dx, dy] of [[0, 0], [6, 0], [-6, 0], [0, 6], [0, -6], [12, 12], [-12, -12]]) {
    await page.mouse.click(canvasBox.x + target.x + dx, canvasBox.y + target.y + dy);
    picked = await page.locator('.selection').textContent();
    if (picked.startsWith('Selected')) break;
  }
  assert.match(picked, /^Selected (body|joint) /, 'clicking the model selects a body or joint');

  // ---- Select a joint in the list; move it with its slider (by keyboard) and see the view change.
  step('joint selection and slider');
  const slider = page.locator('.slider input[type=range]').first();
  const joint = await slider.evaluate((el) => el.closest('li').dataset.joint);
  await page.locator(`button.pick[data-joint="${joint}"]`).click();
  await assert.doesNotReject(page.locator(`li[data-joint="${joint}"].selected`).waitFor());
  assert.equal(await page.locator('.selection').textContent(), `Selected joint ${joint}`);
  assert.match(await page.getByRole('table', { name: `Details of joint ${joint}` }).textContent(), /revolute about \(/);
  const before = await page.evaluate(() => window.cad2moViewer.renderer.domElement.toDataURL());
  await slider.focus();
  for (let i = 0; i < 40; i++) await page.keyboard.press('ArrowRight');
  await page.waitForTimeout(200);
  const after = await page.evaluate(() => window.cad2moViewer.renderer.domElement.toDataURL());
  assert.notEqual(before, after, 'moving the joint slider redraws the model in a new pose');
  await shot(page, '3-joint-moved');
  await page.getByRole('button', { name: 'Reset pose' }).click();

  // ---- Anaglyph mode renders (red-cyan: the picture changes).
  step('anaglyph');
  await page.getByLabel('Red-cyan anaglyph').check();
  await page.waitForTimeout(200);
  const anaglyph = await page.evaluate(() => window.cad2moViewer.renderer.domElement.toDataURL());
  assert.notEqual(anaglyph, after, 'anaglyph mode draws a different picture');
  await shot(page, '4-anaglyph');
  await page.getByLabel('Red-cyan anaglyph').uncheck();

  // ---- Report tab, reached by keyboard from the Structure tab.
  step('report');
  await page.getByRole('tab', { name: 'Structure' }).focus();
  await page.keyboard.press('ArrowRight');
  assert.equal(await page.getByRole('tab', { name: 'Report' }).getAttribute('aria-selected'), 'true');
  await page.getByRole('heading', { name: /^Warnings/ }).waitFor();
  await shot(page, '5-report');

  // ---- Drives: the selected joint's drive; an out-of-range ratio is refused, 100 is saved.
  step('drives');
  await page.getByRole('tab', { name: 'Drives' }).click();
  const editor = page.locator(`form[aria-label="Drive of ${joint}"]`);
  await editor.waitFor();
  await editor.getByLabel('Motor instance').selectOption({ label: 'maxon RE 40 148877 (24 V) (DC permanent-magnet motor)' });
  await editor.getByLabel('Gear instance').selectOption({ label: 'maxon GP 42 C 74:1 (Gear with efficiency)' });
  // A new drive starts with nothing chosen (issue 30): the controller is picked too.
  await editor.getByLabel('Controller instance').selectOption({ index: 1 });
  const ratio = editor.getByLabel('Gear ratio', { exact: false });
  // Ratio 0 is refused at its field before anything is sent (issue 30: it was sent unchecked).
  await ratio.fill('0');
  let sent = 0;
  const count = (r) => r.method() === 'PUT' && r.url().includes('/drives/') && sent++;
  page.on('request', count);
  await editor.getByRole('button', { name: 'Save drive' }).click();
  await page.waitForTimeout(200);
  const zeroMsg = await ratio.evaluate((el) => el.closest('.field')?.querySelector('.field-msg')?.textContent);
  page.off('request', count);
  assert.equal(zeroMsg, 'Gear ratio must not be 0 (the motor would be disconnected)', 'the message at the ratio field');
  assert.equal(await ratio.getAttribute('aria-invalid'), 'true');
  assert.equal(sent, 0, 'ratio 0 is not sent');
  await ratio.fill('25000');
  await editor.getByRole('button', { name: 'Save drive' }).click();
  await editor.getByText('Gear ratio = 25000 is above the maximum 10000').first().waitFor();
  assert.equal(await ratio.getAttribute('aria-invalid'), 'true');
  await shot(page, '6-drives-refused');
  // Within the limits the page knows, but refused by the generator: the live service answers
  // 422 naming the field, and its message shows at that field (issue 30), not only in a box.
  await ratio.fill('100');
  const eta = editor.getByLabel('eta');
  await eta.fill('0');
  const [driveRefusal] = await Promise.all([
    page.waitForResponse((r) => r.request().method() === 'PUT' && r.url().includes(`/drives/${encodeURIComponent(joint)}`)),
    editor.getByRole('button', { name: 'Save drive' }).click(),
  ]);
  assert.equal(driveRefusal.status(), 422, 'the service refused the drive');
  const problem = await driveRefusal.json();
  const etaError = (problem.errors || []).find((e) => /(^|\.)eta$/.test(e.field));
  assert.ok(etaError, `the 422 names the eta field: ${JSON.stringify(problem)}`);
  await editor.getByText(/eta of .* = 0\.0 must be in \(0, 1\]/).first().waitFor();
  const atField = await eta.evaluate((input) => {
    const f = input.closest('.field');
    const msg = f.querySelector('.field-msg');
    const [a, b] = [input.getBoundingClientRect(), msg.getBoundingClientRect()];
    return {
      text: msg.textContent,
      fromServer: msg.classList.contains('from-server'),
      invalid: input.getAttribute('aria-invalid'),
      describedBy: (input.getAttribute('aria-describedby') || '').split(' ').includes(msg.id),
      // Under the input, in its column, close by (its hint between them at most).
      below: b.top >= a.bottom - 1 && b.top - a.bottom <= 8 + (f.querySelector('small')?.getBoundingClientRect().height || 0) && b.left < a.right && b.right > a.left && b.height > 0,
      boxes: [a, b].map((r) => [r.left, r.top, r.right, r.bottom].map(Math.round)),
      // The whole message inside the form (a long class name wraps rather than runs out).
      inside: msg.scrollWidth <= msg.clientWidth + 1 && b.right <= input.form.getBoundingClientRect().right + 1,
      focused: document.activeElement === input,
    };
  });
  assert.equal(atField.text, etaError.message, `the service's message at the eta field: ${JSON.stringify(atField)}`);
  assert.deepEqual(
    [atField.fromServer, atField.invalid, atField.describedBy, atField.below, atField.inside, atField.focused],
    [true, 'true', true, true, true, true],
    `the 422 is shown at its field (marked invalid, described by the message, focused): ${JSON.stringify(atField)}`,
  );
  await shot(page, '6b-drives-refused-at-field');
  await eta.fill('0.72');
  await editor.getByRole('button', { name: 'Save drive' }).click();
  await page.getByText(`Saved the drive of ${joint}.`).waitFor();
  const row = page.locator(`table.drives tr[data-joint="${joint}"]`);
  assert.match(await row.textContent(), /maxon RE 40/);
  assert.match(await row.locator('td.num').textContent(), /^100$/);
  await shot(page, '7-drives-saved');
  await checkLabels(page, 'the drives tab');
  step('regenerate and download');
  // Progress from the first moment (it once stayed silent for 8 s): what the page shows under
  // the button, recorded from the click on.
  await page.evaluate(() => {
    const seen = (window.regenSeen = []);
    const t0 = performance.now();
    const note = () => {
      const p = document.querySelector('.regen-progress');
      if (p) seen.push({ ms: Math.round(performance.now() - t0), bar: !!p.querySelector('progress[aria-label="Regenerating the package"]'), text: p.textContent });
    };
    new MutationObserver(note).observe(document.body, { subtree: true, childList: true, characterData: true });
  });
  const [pkg] = await Promise.all([page.waitForEvent('download', { timeout: 60_000 }), page.getByRole('button', { name: 'Regenerate and download package' }).click()]);
  const regenSeen = await page.evaluate(() => window.regenSeen);
  assert.ok(regenSeen.length && regenSeen[0].bar && regenSeen[0].ms < 500, `a progress bar at once: ${JSON.stringify(regenSeen.slice(0, 3))}`);
  assert.ok(regenSeen.some((x) => /Re-export of v\d+: /.test(x.text)) && regenSeen.some((x) => /Downloading the package of v\d+/.test(x.text)), `the job's stage, then the download: ${JSON.stringify(regenSeen.map((x) => x.text))}`);
  await page.locator('p.ok', { hasText: /regenerated with \d+ drives and downloaded/ }).waitFor();
  const packagePath = join(downloads, pkg.suggestedFilename());
  await pkg.saveAs(packagePath);

  // ---- Motion (issue 12): editor, IK gizmo, player, plots, sizing, limits, the motion in the package.
  const motion = await motionSteps(page, { joint, step, shot, downloads, strict: true });
  await checkLabels(page, 'the motion tab');

  // ---- Results (issue 13): a simulation result animated in 3D, plotted, exported.
  const results = await resultsSteps(page, { step, shot, downloads });
  await checkLabels(page, 'the results tab');

  // ---- Live: a running simulation's poses relayed to the 3D view (the C sender, a known motion).
  const live = await liveSteps(page, { step, shot, harness: process.env.CAD2MO_LIVE_HARNESS });
  await checkLabels(page, 'the live tab');

  // ---- Collisions (issue 14): shapes, an interference made by the matrix, a motion's first contact.
  const collision = await collisionSteps(page, { step, shot });
  await checkLabels(page, 'the collision tab');

  // ---- The Modelica diagram (issue 17): Mechanics and Mechatronics as a Modelica tool draws them.
  const diagram = await diagramSteps(page, { step, shot });
  await checkLabels(page, 'the diagram tab');

  // ---- The Scene (issue 29): a box placed with the gizmo and by numbers, undo/redo, its interference.
  const scene = await sceneSteps(page, { step, shot });
  await checkLabels(page, 'the scene tab');

  // ---- The Results page: a result of any Modelica model, its Dymola visual shapes in 3D.
  const standalone = await standaloneSteps(page, { step, shot, downloads, checkLabels });

  // ---- Motor library: an invalid value is refused, a valid edit sticks; export and re-import.
  step('library');
  await page.getByRole('link', { name: 'Motor library' }).click();
  await page.getByRole('heading', { name: 'Motor library' }).waitFor();
  const ctrl = page.locator('[data-instance-name="RobotR3 axis controller"]');
  await ctrl.waitFor();
  // A catalogue value shows where it comes from (the clause of the instance's source for it).
  const fh = page.locator('[data-instance-name="Faulhaber 1331 T 006 SR"]');
  assert.match(await fh.locator('[data-param=R] .value-source').textContent(), /^source: line 2 terminal resistance 2,83/);
  await shot(page, '8-library');
  await checkLabels(page, 'the library');
  await ctrl.getByRole('button', { name: 'Edit RobotR3 axis controller' }).click();
  const form = page.locator('form.instance-form');
  await form.locator('input[name=kp]').fill('-1');
  await form.getByRole('button', { name: 'Save' }).click();
  await form.getByText(/kp = -1 .*below the minimum 0/).first().waitFor();
  await shot(page, '9-library-refused');
  await form.locator('input[name=kp]').fill('12.5');
  await form.getByRole('button', { name: 'Save' }).click();
  await form.waitFor({ state: 'detached' });
  assert.match(await ctrl.locator('[data-param=kp]').textContent(), /^12\.5/);
  const [xml] = await Promise.all([page.waitForEvent('download'), page.locator('#library-export').click()]);
  const libraryPath = join(downloads, 'motor-library.xml');
  await xml.saveAs(libraryPath);
  assert.match(readFileSync(libraryPath, 'utf8'), /12\.5/);
  // Change it again, then import the exported file: the exported value comes back.
  await ctrl.getByRole('button', { name: 'Edit RobotR3 axis controller' }).click();
  await form.locator('input[name=kp]').fill('20');
  await form.getByRole('button', { name: 'Save' }).click();
  await form.waitFor({ state: 'detached' });
  assert.match(await ctrl.locator('[data-param=kp]').textContent(), /^20/);
  await page.locator('#library-import').setInputFiles(libraryPath);
  await page.waitForFunction(() => /^12\.5/.test(document.querySelector('[data-instance-name="RobotR3 axis controller"] [data-param=kp]')?.textContent || ''));

  // Create an instance, then delete it.
  await page.getByRole('button', { name: 'New Ideal gear instance' }).click();
  const created = page.locator('form.instance-form');
  await created.locator('input[name=__name]').fill('Test gear 50:1');
  await created.locator('input[name=ratio]').fill('50');
  await created.getByRole('button', { name: 'Save' }).click();
  const newGear = page.locator('[data-instance-name="Test gear 50:1"]');
  await newGear.waitFor();
  assert.match(await newGear.locator('[data-param=ratio]').textContent(), /^50/);
  await newGear.getByRole('button', { name: 'Delete Test gear 50:1' }).click();
  await page.getByRole('dialog').getByRole('button', { name: 'Delete' }).click();
  await newGear.waitFor({ state: 'detached' });

  // ---- A new CAD version: the diff and the orphaned drive; downloads; deleting a version.
  step('new version');
  await page.getByRole('link', { name: 'Models', exact: true }).first().click();
  await page.getByRole('link', { name: 'ARM', exact: true }).click();
  await page.getByRole('heading', { name: 'Versions', exact: true }).waitFor();
  // This time by drag and drop: a real drop event carrying the file.
  const dataTransfer = await page.evaluateHandle(
    ([b64, name]) => {
      const dt = new DataTransfer();
      dt.items.add(new File([Uint8Array.from(atob(b64), (c) => c.charCodeAt(0))], name, { type: 'application/zip' }));
      return dt;
    },
    [readFileSync(bundleV2).toString('base64'), 'arm-v2.zip'],
  );
  const zone = page.locator('section.upload .dropzone');
  await zone.dispatchEvent('dragover', { dataTransfer });
  assert.match(await zone.getAttribute('class'), /\bover\b/);
  await zone.dispatchEvent('drop', { dataTransfer });
  await page.getByText('Version 2 converted.').waitFor();
  const diff = page.locator('.diff-out');
  await diff.getByText('v1 → v2').waitFor();
  assert.match(await diff.textContent(), new RegExp(`removed ${joint}`));
  assert.match(await diff.locator('li.changed').textContent(), /LINK_FORE \(LINK\).*mass: 0\.31752 → 0\.5 kg/);
  const orphans = page.locator('ul.orphaned');
  await orphans.waitFor();
  assert.match(await orphans.textContent(), new RegExp(joint));
  await shot(page, '10-model-versions');
  // The orphan can be removed (it is kept until someone does).
  await orphans.getByRole('button', { name: `Remove the orphaned drive of ${joint}` }).click();
  await page.getByRole('dialog').getByRole('button', { name: 'Remove' }).click();
  await orphans.waitFor({ state: 'detached' });
  const [v1zip] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Download the package of version 1' }).click()]);
  assert.match(v1zip.suggestedFilename(), /^ARM-v1\.zip$/);
  await page.getByRole('button', { name: 'Delete version 2' }).click();
  await page.getByRole('dialog').getByRole('button', { name: 'Delete' }).click();
  await page.locator('tr[data-version="2"]').waitFor({ state: 'detached' });
  assert.equal(await page.locator('tr[data-version]').count(), 1);

  // ---- A conversion that takes a while: the page follows the job's stages and its bar fills.
  step('job progress');
  await page.getByRole('link', { name: 'Models', exact: true }).first().click();
  await page.getByRole('heading', { name: 'All models' }).waitFor();
  await page.evaluate(() => {
    window.cad2moStates = [];
    const state = document.querySelector('section.upload .upload-state');
    const bar = document.querySelector('section.upload progress.job-progress');
    new MutationObserver(() => window.cad2moStates.push([state.textContent, bar.getAttribute('value')])).observe(state, {
      childList: true,
      characterData: true,
      subtree: true,
    });
  });
  await page.locator('section.upload input[type=file]').setInputFiles(heavy);
  await page.getByText(/ · \d+ %/).first().waitFor({ timeout: 60_000 });
  // The new model is listed at once, its conversion followed there too.
  await page.locator('tr[data-model-id]', { hasText: 'PENDULUM' }).waitFor();
  await shot(page, '15-job-progress');
  assert.equal(await page.getByLabel('Conversion', { exact: true }).evaluate((el) => el.tagName), 'PROGRESS');
  await page.waitForURL(/#\/models\/[^/]+\/versions\/1$/, { timeout: 120_000 });
  const states = await page.evaluate(() => window.cad2moStates);
  const staged = states.filter(([text]) => /: (Reading|Analysing|Writing|Zipping|Storing)[^·]* · \d+ %/.test(text));
  assert.ok(staged.length >= 2, `the job's stages were shown: ${JSON.stringify(states)}`);
  // The bar never goes back and ends full when the job is done (on a loaded machine every stage
  // seen may be the same long one, so the last fill is the done state's).
  const done = states.filter(([text]) => / converted\.$/.test(text));
  assert.equal(done.at(-1)?.[1], '1', `the bar is full when the job is done: ${JSON.stringify(states)}`);
  const values = [...staged, ...done].map(([, v]) => Number(v));
  assert.ok(values.every((v, i) => i === 0 || v >= values[i - 1]) && values.at(-1) > values[0], `the bar fills: ${JSON.stringify(states)}`);
  await waitForModel(page);
  await page.getByRole('link', { name: 'Models', exact: true }).first().click();
  await page.getByRole('button', { name: 'Delete PENDULUM' }).click();
  await page.getByRole('dialog').getByRole('button', { name: 'Delete' }).click();
  await page.locator('tr[data-model-id]', { hasText: 'PENDULUM' }).waitFor({ state: 'detached' });

  // ---- A narrow window: nothing wider than the screen, and the model still renders.
  step('narrow window');
  await page.setViewportSize({ width: 390, height: 844 });
  await page.goto(`${url}/#/models`);
  await page.getByRole('heading', { name: 'All models' }).waitFor();
  await page.waitForTimeout(300);
  await shot(page, '11-narrow-models');
  const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  assert.ok(overflow <= 1, `the models page is ${overflow}px wider than a narrow window`);
  await page.getByRole('link', { name: /^3D view of / }).first().click();
  await waitForModel(page);
  await shot(page, '12-narrow-model');
  const overflow3d = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  assert.ok(overflow3d <= 1, `the model page is ${overflow3d}px wider than a narrow window`);
  await page.getByRole('tab', { name: 'Drives' }).click();
  await page.locator('table.drives').waitFor();
  await shot(page, '13-narrow-drives');
  await page.getByRole('tab', { name: 'Motion' }).click();
  await page.locator('table.limits').waitFor();
  await shot(page, '13b-narrow-motion');
  const overflowMotion = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  assert.ok(overflowMotion <= 1, `the motion tab is ${overflowMotion}px wider than a narrow window`);
  await page.getByRole('tab', { name: 'Results' }).click();
  await page.locator('table.results').waitFor();
  await page.getByRole('button', { name: /^Open result / }).first().click();
  await page.locator('#results-play').waitFor();
  await shot(page, '13c-narrow-results');
  const overflowResults = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  assert.ok(overflowResults <= 1, `the results tab is ${overflowResults}px wider than a narrow window`);
  await page.getByRole('tab', { name: 'Live' }).click();
  await page.locator('section.live-how h3').waitFor();
  await shot(page, '13e-narrow-live');
  const overflowLive = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  assert.ok(overflowLive <= 1, `the live tab is ${overflowLive}px wider than a narrow window`);
  await page.getByRole('tab', { name: 'Collision' }).click();
  await page.locator('table.collision-shapes-table').waitFor();
  await shot(page, '13f-narrow-collision');
  const overflowCollision = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  assert.ok(overflowCollision <= 1, `the collision tab is ${overflowCollision}px wider than a narrow window`);
  await page.getByRole('link', { name: 'Results', exact: true }).click();
  await page.getByRole('heading', { name: 'Results', exact: true, level: 1 }).waitFor();
  await page.locator('.results-list-box table.results, .results-list-box p:not(:empty)').first().waitFor();
  await shot(page, '13d-narrow-results-page');
  const overflowResultsPage = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  assert.ok(overflowResultsPage <= 1, `the results page is ${overflowResultsPage}px wider than a narrow window`);
  await page.getByRole('link', { name: 'Motor library' }).click();
  await page.locator('[data-instance-name="RobotR3 axis controller"]').waitFor();
  await shot(page, '14-narrow-library');
  const overflowLib = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  assert.ok(overflowLib <= 1, `the library is ${overflowLib}px wider than a narrow window`);

  assert.deepEqual(consoleErrors, [], 'the page logged errors');
  console.log(JSON.stringify({ joint, package: packagePath, library: libraryPath, motion, results, live, collision, diagram, scene, standalone }));
} finally {
  await browser.close();
}
