// The Results tab, end to end (part of ui.mjs, on the model view of the uploaded arm). No
// simulator runs here, so the test writes the result files itself (e2e/matv4.mjs) from a known
// motion of the arm: its two revolute joints turning at constant speeds, every body's
// frame_a.r_0 / frame_a.R.T computed by the viewer's own forward kinematics (float32, as Dymola
// writes; constant signals in data_1). A second file holds only the joint angles (float64), so
// the service's forward kinematics places the bodies. Checked: the summary, the CAD meshes'
// world poses in the 3D view after scrubbing (at a sample and between samples), play at a speed,
// loop, charts of searched variables with the value at the cursor, a click on a chart seeking
// the 3D time, the CSV export, refusals shown at the upload, deleting a result.

import { poseDistance } from './lib.mjs';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { bodyDeltas, frameMatrix, coordinates } from '../src/viewer/kinematics.js';
import { writeMat } from './matv4.mjs';

const N = 101; // instants, 0 … 2 s
const time = Array.from({ length: N }, (_, i) => i / 50);
const f32 = Math.fround;

/** Joint values of the known motion at time t: joint k turns at speed SPEEDS[k] from its start. */
const RATES = [1.5, -0.7];
function jointValues(coords, t) {
  const q = new Map();
  coords.forEach((c, k) => q.set(c.key, c.q0 + (RATES[k] ?? 0) * t));
  return q;
}

/** Every body's CS1 world matrix (three.js Matrix4) for joint values q. */
function worldPoses(report, q) {
  const deltas = bodyDeltas(report, q);
  return new Map(report.bodies.map((b) => [b.modelica_name, deltas.get(b.modelica_name).clone().multiply(frameMatrix(b.cs1))]));
}

/** Rotation entry (row i, column j) of a column-major 4×4. */
const rot = (e, i, j) => e[j * 4 + i];

/** The result file with poses: r_0 and R.T (world → body: R.T[i,j] = M[j,i]) of every body. */
function framesFile(report, coords) {
  const series = [];
  const poses = time.map((t) => worldPoses(report, jointValues(coords, t)));
  for (const b of report.bodies) {
    const name = b.modelica_name;
    for (let i = 0; i < 3; i++) {
      series.push({ name: `${name}.frame_a.r_0[${i + 1}]`, description: 'Position vector from world frame to the connector frame origin, resolved in world frame [m]', values: poses.map((p) => p.get(name).elements[12 + i]) });
    }
    for (let i = 0; i < 3; i++) {
      for (let j = 0; j < 3; j++) {
        series.push({ name: `${name}.frame_a.R.T[${i + 1}, ${j + 1}]`, description: 'Transformation matrix from world frame to local frame', values: poses.map((p) => rot(p.get(name).elements, j, i)) });
      }
    }
  }
  coords.forEach((c, k) => {
    series.push({ name: `${c.element}.phi`, description: 'Relative rotation angle from frame_a to frame_b [rad]', values: time.map((t) => c.q0 + (RATES[k] ?? 0) * t) });
    series.push({ name: `${c.element}.w`, description: 'First derivative of angle phi (relative angular velocity) [rad/s]', values: time.map(() => RATES[k] ?? 0) });
  });
  const constants = report.bodies.map((b) => ({ name: `${b.modelica_name}.m`, description: 'Mass of rigid body [kg]', value: b.mass }));
  return writeMat({ time, series, constants, precision: 'f32' });
}

/** The result file with the joint angles only (OpenModelica's float64). */
function jointsFile(coords) {
  const series = coords.map((c, k) => ({ name: `${c.element}.phi`, description: 'Relative rotation angle from frame_a to frame_b [rad]', values: time.map((t) => c.q0 + (RATES[k] ?? 0) * t) }));
  return writeMat({ time, series, precision: 'f64' });
}

/** The 3D view's CS1 world matrices (column-major) of the named bodies, now. */
const viewerPoses = (page) =>
  page.evaluate(() => {
    const out = {};
    for (const [name, b] of window.cad2moViewer.bodies) out[name] = Array.from(b.group.matrix.elements);
    return out;
  });


/** The matrix a file's r_0 / R.T (as stored, float32) give: p_world = r_0 + R.Tᵀ · p. */
function fileMatrix(report, coords, name, k) {
  const m = worldPoses(report, jointValues(coords, time[k])).get(name).elements;
  const e = new Array(16).fill(0);
  for (let i = 0; i < 3; i++) {
    for (let j = 0; j < 3; j++) e[j * 4 + i] = f32(rot(m, i, j)); // M[i,j] = R.T[j,i], both rounded as written
    e[12 + i] = f32(m[12 + i]);
  }
  e[15] = 1;
  return e;
}

async function setScrub(page, t) {
  await page.locator('#results-scrub').fill(String(t));
  await page.waitForFunction((x) => Math.abs(Number(document.querySelector('.results-player').dataset.time) - x) < 1e-9, t);
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
}

/** The chart readout's value of `name` (the value at the cursor). */
const reading = (page, chart, name) =>
  page.locator(`section.result-chart[data-chart="${chart}"] .reading[data-var="${name}"]`).getAttribute('data-value').then(Number);

async function plot(page, chart, search, name) {
  const box = page.locator(`section.result-chart[data-chart="${chart}"]`);
  await box.getByLabel(`Add a variable to chart ${chart}`).fill(search);
  await box.getByRole('button', { name: `Plot ${name} on chart ${chart}`, exact: true }).click();
  await box.locator(`.reading[data-var="${name}"]`).waitFor();
  await box.locator('.uplot').waitFor();
}

/**
 * @param {import('playwright-core').Page} page  on the model view, version 1 of the arm
 * @param {{step: Function, shot: Function, downloads: string}} o
 */
export async function resultsSteps(page, { step, shot, downloads }) {
  const report = await page.evaluate(() => window.cad2moViewer.report);
  const coords = coordinates(report).filter((c) => c.inTree && c.kind === 'revolute');
  assert.ok(coords.length >= 2, `the arm has two revolute joints: ${coords.map((c) => c.element)}`);
  const framesPath = join(downloads, 'arm-frames.mat');
  const jointsPath = join(downloads, 'arm-joints.mat');
  const badPath = join(downloads, 'random.mat');
  const foreignPath = join(downloads, 'other-model.mat');
  writeFileSync(framesPath, framesFile(report, coords));
  writeFileSync(jointsPath, jointsFile(coords));
  writeFileSync(badPath, Uint8Array.from({ length: 100 }, (_, i) => (i * 97 + 13) % 256));
  writeFileSync(foreignPath, writeMat({ time, series: [{ name: 'pendulum.body.frame_a.r_0[1]', values: time.map(Math.sin) }] }));

  step('results: refusals at the upload');
  await page.getByRole('tab', { name: 'Results' }).click();
  // The list has loaded (not its "Loading…" line): the count below is the stored one.
  await page.locator('.results-list-box[data-state=listed]').waitFor();
  // Results stored before this tab's steps (the closed-loop simulation's run, issue 28).
  const before = await page.locator('table.results tr[data-result-id]').count();
  const input = page.locator('section.results-upload input[type=file]');
  const refusal = page.locator('section.results-upload .error');
  await input.setInputFiles(badPath);
  await refusal.waitFor();
  assert.match(await refusal.textContent(), /random\.mat/, 'the refusal names the file');
  await shot(page, '20-results-refused');
  await input.setInputFiles(foreignPath);
  await refusal.filter({ hasText: 'other-model.mat' }).waitFor();
  assert.match(await refusal.textContent(), /none of the (model|version)'s bodies/i, await refusal.textContent());
  assert.equal(await page.locator('table.results tr[data-result-id]').count(), before, 'nothing stored');

  step('results: upload the poses');
  await input.setInputFiles(framesPath);
  const summary = page.getByRole('table', { name: 'Summary of result arm-frames.mat' });
  await summary.waitFor();
  await page.locator('#results-play').waitFor();
  assert.equal(await refusal.count(), 0, 'the refusal is gone');
  // The list fits the side panel: every Delete inside it, the names not squeezed to a letter per line.
  const fit = await page.evaluate(() => {
    const box = document.querySelector('.results-list-box').getBoundingClientRect();
    const dels = [...document.querySelectorAll('table.results td.actions button')].map((b) => b.getBoundingClientRect());
    const names = [...document.querySelectorAll('table.results th[scope=row] button.link')].map((b) => b.getBoundingClientRect().width);
    return { right: box.right, dels: dels.map((d) => d.right), narrowest: Math.min(...names) };
  });
  assert.ok(fit.dels.length >= 1 && fit.dels.every((r) => r <= fit.right + 0.5), `Delete out of the panel: ${JSON.stringify(fit)}`);
  assert.ok(fit.narrowest >= 60, `a result name squeezed to ${fit.narrowest}px`);
  const text = await summary.textContent();
  assert.match(text, /Instants101/);
  assert.match(text, /Time span0 … 2 s/);
  assert.match(text, /Precisionfloat32/);
  const moving = coords.map((c) => report.joints.find((j) => j.modelica_name === c.joint).follower_body);
  const fromFrames = await summary.locator('.from-frames li').allTextContents();
  for (const name of moving) assert.ok(fromFrames.includes(name), `${name} posed from its frame: ${fromFrames}`);
  assert.equal(await summary.locator('.from-joints li').count(), 0, 'no body from the joints when the frames are there');
  assert.match(text, /Bodies missingnone/);
  assert.match(text, /Orthonormalitylargest/);
  // The file's frames were computed by the viewer's kinematics, the service checks them with its own.
  const kin = /Kinematicsframes within ([-\d.e+]+) mm/.exec(text);
  assert.ok(kin && Number(kin[1]) < 0.01, `the frames agree with the service's kinematics: ${text}`);

  // ---- Scrub to a sample: each body is where the file's r_0 / R.T put it.
  step('results: poses in 3D');
  const k = 50; // t = 1 s
  await setScrub(page, time[k]);
  let got = await viewerPoses(page);
  for (const name of fromFrames) {
    const d = poseDistance(got[name], fileMatrix(report, coords, name, k));
    assert.ok(d < 2e-5, `${name} at t=${time[k]} is ${d} m from the file's pose`);
  }
  // Between samples: interpolated (lerp, slerp), close to the motion, not the nearest sample.
  const mid = (time[k] + time[k + 1]) / 2 + 0.004;
  await setScrub(page, mid);
  got = await viewerPoses(page);
  const exact = worldPoses(report, jointValues(coords, mid));
  for (const name of moving) {
    const d = poseDistance(got[name], exact.get(name).elements);
    const nearest = poseDistance(fileMatrix(report, coords, name, k + 1), exact.get(name).elements);
    assert.ok(d < 2e-4 && d < nearest / 5, `${name} at t=${mid} is ${d} m from the motion (the nearest sample ${nearest} m)`);
  }
  await shot(page, '21-results-pose');

  // ---- Charts: a searched variable, the value at the cursor; two on one chart; a second chart.
  step('results: plots');
  const [c1, c2] = coords.map((c) => c.element);
  await plot(page, 1, `${c1}.ph`, `${c1}.phi`);
  assert.ok(await page.getByRole('button', { name: `Plot ${c1}.phi on chart 1`, exact: true }).isDisabled(), 'a plotted variable is not offered again');
  await setScrub(page, 1);
  assert.ok(Math.abs((await reading(page, 1, `${c1}.phi`)) - f32(coords[0].q0 + RATES[0])) < 1e-5, 'the plot shows the value at the cursor');
  await setScrub(page, 0.73);
  assert.ok(Math.abs((await reading(page, 1, `${c1}.phi`)) - (coords[0].q0 + RATES[0] * 0.73)) < 1e-5, 'the value at the cursor between samples');
  await plot(page, 1, `${c1}.w`, `${c1}.w`);
  assert.ok(Math.abs((await reading(page, 1, `${c1}.w`)) - RATES[0]) < 1e-6);
  assert.equal(await page.locator('section.result-chart[data-chart="1"] .uplot .u-series').count(), 3, 'two variables on chart 1');
  await page.getByRole('button', { name: 'Add chart' }).click();
  await plot(page, 2, `${c2}.phi`, `${c2}.phi`);
  await plot(page, 2, 'frame_a.r_0[3]', `${moving[1]}.frame_a.r_0[3]`);
  await page.getByRole('button', { name: `Remove ${moving[1]}.frame_a.r_0[3] from chart 2` }).click();
  await page.locator(`section.result-chart[data-chart="2"] .chips li[data-var="${moving[1]}.frame_a.r_0[3]"]`).waitFor({ state: 'detached' });
  await shot(page, '22-results-plots');
  // A click on a chart seeks the 3D time there.
  // (locator.click scrolls the chart out from under the dock's sticky player if needed)
  const overEl = page.locator('section.result-chart[data-chart="1"] .u-over');
  await overEl.scrollIntoViewIfNeeded();
  const over = await overEl.boundingBox();
  await overEl.click({ position: { x: over.width * 0.25, y: over.height / 2 } });
  const player = page.locator('.results-player');
  const seeked = Number(await player.getAttribute('data-time'));
  assert.ok(Math.abs(seeked - 0.5) < 0.05, `a click a quarter into the chart seeks to ${seeked} s`);
  assert.ok(Math.abs((await reading(page, 1, `${c1}.phi`)) - (coords[0].q0 + RATES[0] * seeked)) < 1e-5, 'the readout follows the seek');

  // ---- CSV of the plotted signals.
  step('results: CSV');
  const [csv] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Export CSV' }).click()]);
  assert.equal(csv.suggestedFilename(), 'arm-frames-signals.csv');
  const csvPath = join(downloads, csv.suggestedFilename());
  await csv.saveAs(csvPath);
  const lines = readFileSync(csvPath, 'utf8').trim().split('\n');
  assert.equal(lines[0], `time [s],${c1}.phi [rad],${c1}.w [rad/s],${c2}.phi [rad]`);
  assert.equal(lines.length, 1 + N, 'a row per instant');
  const row = lines.find((l) => l.startsWith('1,')).split(',').map(Number);
  assert.ok(Math.abs(row[1] - f32(coords[0].q0 + RATES[0])) < 1e-6 && Math.abs(row[2] - RATES[0]) < 1e-6 && Math.abs(row[3] - f32(coords[1].q0 + RATES[1])) < 1e-6, `CSV row at 1 s: ${row}`);
  await page.getByRole('button', { name: 'Remove chart 2' }).click();
  assert.equal(await page.locator('section.result-chart').count(), 1);

  // ---- Play: at 10× to the end; at 0.1×; looping.
  step('results: play');
  const rate = () =>
    page.evaluate(async () => {
      const box = document.querySelector('.results-player');
      const a = [performance.now(), Number(box.dataset.time)];
      await new Promise((r) => setTimeout(r, 1000));
      const b = [performance.now(), Number(box.dataset.time)];
      return (b[1] - a[1]) / ((b[0] - a[0]) / 1000);
    });
  await page.locator('#results-speed').selectOption('0.1');
  await setScrub(page, 0);
  await page.locator('#results-play').click();
  const slow = await rate();
  assert.ok(slow > 0.06 && slow < 0.15, `plays at 0.1×: ${slow} s per s`);
  await page.locator('#results-play').click();
  const paused = await player.getAttribute('data-time');
  await page.waitForTimeout(200);
  assert.equal(await player.getAttribute('data-time'), paused, 'paused');
  // Step: to the next sample of the result (every 0.02 s) and back, staying paused.
  await page.locator('#results-step').click();
  const stepped = Number(await player.getAttribute('data-time'));
  const next = time.find((x) => x > Number(paused) + 1e-6);
  assert.ok(Math.abs(stepped - next) < 1e-6 && (await player.getAttribute('data-playing')) === 'false', `Step » goes from ${paused} to the next sample ${next}: ${stepped}`);
  await page.locator('#results-step-back').click();
  const back = Number(await player.getAttribute('data-time'));
  assert.ok(Math.abs(back - time.filter((x) => x < next - 1e-6).pop()) < 1e-6, `« Step goes back one sample from ${stepped}: ${back}`);
  await page.locator('#results-speed').selectOption('10');
  await page.locator('#results-play').click();
  await page.waitForFunction(() => document.querySelector('.results-player').dataset.playing === 'false', null, { timeout: 10_000 });
  assert.equal(Number(await player.getAttribute('data-time')), 2, 'played to the end at 10×');
  await page.locator('#results-loop').check();
  await page.locator('#results-speed').selectOption('2');
  await setScrub(page, 1.5);
  await page.locator('#results-play').click();
  const times = await page.evaluate(async () => {
    const box = document.querySelector('.results-player');
    const seen = [];
    const end = performance.now() + 700;
    while (performance.now() < end) {
      seen.push(Number(box.dataset.time));
      await new Promise((r) => requestAnimationFrame(r));
    }
    return seen;
  });
  assert.equal(await player.getAttribute('data-playing'), 'true', 'still playing after the end: looping');
  assert.ok(times.some((t, i) => i > 0 && t < times[i - 1] - 0.5), `wrapped to the start: ${times.join(' ')}`);
  await page.locator('#results-play').click();

  // ---- Joints only: the service's forward kinematics places the bodies.
  step('results: poses from joint angles');
  // This time by drag and drop: a real drop event carrying the file.
  const dataTransfer = await page.evaluateHandle(
    ([b64, name]) => {
      const dt = new DataTransfer();
      dt.items.add(new File([Uint8Array.from(atob(b64), (c) => c.charCodeAt(0))], name));
      return dt;
    },
    [readFileSync(jointsPath).toString('base64'), 'arm-joints.mat'],
  );
  const zone = page.locator('section.results-upload .dropzone');
  await zone.dispatchEvent('dragover', { dataTransfer });
  assert.match(await zone.getAttribute('class'), /\bover\b/);
  await zone.dispatchEvent('drop', { dataTransfer });
  const summary2 = page.getByRole('table', { name: 'Summary of result arm-joints.mat' });
  await summary2.waitFor();
  await page.locator('#results-play').waitFor();
  assert.match(await summary2.textContent(), /Precisionfloat64/);
  const fromJoints = await summary2.locator('.from-joints li').allTextContents();
  for (const name of moving) assert.ok(fromJoints.includes(name), `${name} posed from the joint angles: ${fromJoints}`);
  assert.equal(await summary2.locator('.from-frames li').count(), 0);
  await setScrub(page, 1.3);
  got = await viewerPoses(page);
  const fk = worldPoses(report, jointValues(coords, 1.3));
  for (const name of fromJoints) {
    const d = poseDistance(got[name], fk.get(name).elements);
    assert.ok(d < 1e-4, `${name} at 1.3 s is ${d} m from the forward kinematics of the file's angles`);
  }
  await shot(page, '23-results-joints');

  // ---- Leaving the tab hands the bodies back to the joints; deleting a result.
  await page.getByRole('tab', { name: 'Structure' }).click();
  assert.equal(await page.evaluate(() => window.cad2moViewer.posed), null, 'the joints pose the model outside the Results tab');
  await page.getByRole('tab', { name: 'Results' }).click();
  assert.equal(await page.locator('table.results tr[data-result-id]').count(), before + 2);
  await page.getByRole('button', { name: 'Delete result arm-joints.mat' }).click();
  await page.getByRole('dialog').getByRole('button', { name: 'Delete' }).click();
  await page.locator('table.results tr[data-result-id]').nth(before + 1).waitFor({ state: 'detached' });
  assert.equal(await page.locator('table.results tr[data-result-id]').count(), before + 1);

  // The tab has its own address: a reload comes back to it.
  assert.match(page.url(), /\/versions\/1\/results$/);
  await page.reload();
  await page.locator('table.results tr[data-result-id]').first().waitFor();
  assert.equal(await page.getByRole('tab', { name: 'Results' }).getAttribute('aria-selected'), 'true');
  await page.getByRole('button', { name: 'Open result arm-frames.mat' }).click();
  await page.locator('#results-play').waitFor();
  await page.getByRole('tab', { name: 'Drives' }).click();
  return { results: before + 1, csv: csvPath };
}
