// The Results page (top navigation), end to end (part of ui.mjs): a result of a model that was
// never converted here, written by the test as Dymola does (e2e/matv4.mjs, float32) with two
// visual shapes and one frame: a red-brown box whose origin runs along x at 1 m/s, a fixed
// upright cylinder, and a frame rising along z while it turns about z. Checked: a refusal at the
// upload, the summary, the box's world place and colour in the 3D scene after scrubbing (between
// samples), the cylinder's extent, the frame's pose, play and pause, a chart's value at the
// cursor, the CSV export, the address of an open result, deleting; and, when the fixture is
// there, MSL's RobotR3 fullRobot from Dymola drawn from its shapes (screenshot).

import assert from 'node:assert/strict';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { writeMat, shapeSeries, frameSeries, packMaterial } from './matv4.mjs';

const N = 101; // instants, 0 … 2 s
const time = Array.from({ length: N }, (_, i) => i / 50);
const f32 = Math.fround;
const BOX = 'world.box.shape';
const CYL = 'world.pillar.shape';
const FRAME = 'world.turner.frame_a';
const BOX_COLOR = [200, 100, 50];
const CYL_COLOR = [40, 90, 230];
const TURN = 0.8; // rad/s about z
const RISE = 0.25; // m/s along z

const rotZ = (a) => [
  [Math.cos(a), -Math.sin(a), 0],
  [Math.sin(a), Math.cos(a), 0],
  [0, 0, 1],
];

function shapesFile() {
  const series = [
    ...shapeSeries(BOX, { code: 101, color: BOX_COLOR, specular: 0.5, r: (t) => [t, 0, 0], rx: [1, 0, 0], ry: [0, 1, 0], size: [0.4, 0.2, 0.1] }, time),
    ...shapeSeries(CYL, { code: 103, color: CYL_COLOR, specular: 0.2, r: [0, 0.5, 0], rx: [0, 1, 0], ry: [1, 0, 0], size: [0.3, 0.1, 0.1] }, time),
    ...frameSeries(FRAME, { r: (t) => [-0.5, 0, RISE * t], M: (t) => rotZ(TURN * t) }, time),
    { name: 'world.turner.phi', description: 'Rotation angle [rad]', values: time.map((t) => TURN * t) },
  ];
  return writeMat({ time, series, precision: 'f32' });
}

/** Dymola's 99 levels per channel, back on 0..255 as the service reads them. */
const unpacked = (c) => c.map((x) => Math.round((Math.floor((99 * x) / 255) * 255) / 99));

const inspect = (page) => page.evaluate(() => window.cad2moShapes.inspect());

async function setScrub(page, t) {
  await page.locator('#results-scrub').fill(String(t));
  await page.waitForFunction((x) => Math.abs(Number(document.querySelector('.results-player').dataset.time) - x) < 1e-9, t);
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

const near = (a, b, tol, what) => a.forEach((x, i) => assert.ok(Math.abs(x - b[i]) < tol, `${what}: ${JSON.stringify(a)} vs ${JSON.stringify(b)}`));

/**
 * @param {import('playwright-core').Page} page
 * @param {{step: Function, shot: Function, downloads: string, checkLabels: Function}} o
 */
export async function standaloneSteps(page, { step, shot, downloads, checkLabels }) {
  const shapesPath = join(downloads, 'shapes.mat');
  const noisePath = join(downloads, 'noise.mat');
  writeFileSync(shapesPath, shapesFile());
  writeFileSync(noisePath, Uint8Array.from({ length: 300 }, (_, i) => (i * 31 + 7) % 256));
  assert.equal(packMaterial([255, 0, 0], 0.7), 9900006, 'the Material packing');

  step('standalone results: the page');
  await page.getByRole('link', { name: 'Results', exact: true }).click();
  await page.getByRole('heading', { name: 'Results', exact: true, level: 1 }).waitFor();
  assert.equal(await page.getByRole('link', { name: 'Results', exact: true }).getAttribute('aria-current'), 'page');
  await page.locator('.results-list-box[data-state=listed]').waitFor();
  const before = await page.locator('table.results tr[data-result-id]').count();

  step('standalone results: a refusal at the upload');
  const input = page.locator('section.results-upload input[type=file]');
  const refusal = page.locator('section.results-upload .error');
  await input.setInputFiles(noisePath);
  await refusal.waitFor();
  assert.match(await refusal.textContent(), /noise\.mat/, 'the refusal names the file');
  await shot(page, '30-standalone-refused');
  assert.equal(await page.locator('table.results tr[data-result-id]').count(), before, 'nothing stored');

  step('standalone results: upload, summary');
  await input.setInputFiles(shapesPath);
  const summary = page.getByRole('table', { name: 'Summary of result shapes.mat' });
  await summary.waitFor();
  await page.locator('#results-play').waitFor();
  assert.equal(await refusal.count(), 0, 'the refusal is gone');
  const text = await summary.textContent();
  assert.match(text, /Instants101/, text);
  assert.match(text, /Time span0 … 2 s/, text);
  assert.match(text, /Precisionfloat32/, text);
  assert.match(text, /Shapes2 \(1 box, 1 cylinder\)/, text);
  assert.match(text, /Frames1/, text);
  assert.match(page.url(), /#\/results\/[^/]+$/, 'an open result has its address');

  step('standalone results: shapes in 3D');
  await page.waitForFunction(() => window.cad2moShapes && Number(document.querySelector('.shapes-stage')?.dataset.rendered) > 0);
  const t = 1.25; // between the samples at 1.24 and 1.26
  await setScrub(page, t);
  let scene = await inspect(page);
  assert.deepEqual(scene.shapes.map((s) => [s.name, s.kind]), [[BOX, 'box'], [CYL, 'cylinder']]);
  const box = scene.shapes[0];
  // The box runs from its origin (t, 0, 0) along x for its length, centred in y and z.
  near(box.matrix.slice(12, 15), [t, 0, 0], 1e-5, 'the box origin');
  near(box.min, [t, -0.1, -0.05], 1e-5, 'the box lower corner');
  near(box.max, [t + 0.4, 0.1, 0.05], 1e-5, 'the box upper corner');
  assert.deepEqual(box.color, unpacked(BOX_COLOR), 'the box colour from its Material');
  const hex = box.hex.match(/../g).map((x) => parseInt(x, 16));
  near(hex, unpacked(BOX_COLOR), 1.5, 'the box material colour');
  assert.deepEqual(scene.shapes[1].color, unpacked(CYL_COLOR));
  // The upright cylinder: from (0, 0.5, 0) up y for 0.3, diameter 0.1.
  const cyl = scene.shapes[1];
  near(cyl.min, [-0.05, 0.5, -0.05], 1e-3, 'the cylinder lower corner');
  near(cyl.max, [0.05, 0.8, 0.05], 1e-3, 'the cylinder upper corner');
  // The frame: rising along z, turned TURN·t about z.
  assert.equal(scene.frames[0].name, FRAME);
  near(scene.frames[0].position, [-0.5, 0, RISE * t], 1e-5, 'the frame position');
  const q = scene.frames[0].quaternion;
  const want = [0, 0, Math.sin((TURN * t) / 2), Math.cos((TURN * t) / 2)];
  const sign = Math.sign(q[3] * want[3] + q[2] * want[2]) || 1;
  near(q.map((x) => x * sign), want, 1e-4, 'the frame rotation');
  await setScrub(page, 0.5);
  scene = await inspect(page);
  near(scene.shapes[0].matrix.slice(12, 15), [0.5, 0, 0], 1e-5, 'the box origin at 0.5 s');
  await shot(page, '31-standalone-shapes');

  step('standalone results: play and pause');
  await page.locator('#results-play').click();
  const player = page.locator('.results-player');
  await page.waitForFunction(() => Number(document.querySelector('.results-player').dataset.time) > 0.6);
  await page.locator('#results-play').click();
  assert.equal(await player.getAttribute('data-playing'), 'false');
  const paused = Number(await player.getAttribute('data-time'));
  scene = await inspect(page);
  assert.ok(Math.abs(scene.shapes[0].matrix[12] - paused) < 1e-4, `the box follows the player: ${scene.shapes[0].matrix[12]} at ${paused} s`);

  step('standalone results: plots, CSV');
  const chart = page.locator('section.result-chart[data-chart="1"]');
  await chart.getByLabel('Add a variable to chart 1').fill('box.shape.rvisobj[1]');
  await chart.getByRole('button', { name: `Plot ${BOX}.rvisobj[1] on chart 1`, exact: true }).click();
  await chart.locator('.uplot').waitFor();
  await setScrub(page, 1);
  const value = Number(await chart.locator(`.reading[data-var="${BOX}.rvisobj[1]"]`).getAttribute('data-value'));
  assert.ok(Math.abs(value - 1) < 1e-6, `the plot shows the box's x at 1 s: ${value}`);
  await chart.getByLabel('Add a variable to chart 1').fill('turner.phi');
  await chart.getByRole('button', { name: 'Plot world.turner.phi on chart 1', exact: true }).click();
  await chart.locator('.reading[data-var="world.turner.phi"]').waitFor();
  const [csv] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Export CSV' }).click()]);
  assert.equal(csv.suggestedFilename(), 'shapes-signals.csv');
  const csvPath = join(downloads, csv.suggestedFilename());
  await csv.saveAs(csvPath);
  const lines = readFileSync(csvPath, 'utf8').trim().split('\n');
  assert.match(lines[0], /^time \[s\],world\.box\.shape\.rvisobj\[1\]( \[m\])?,world\.turner\.phi( \[rad\])?$/, lines[0]);
  assert.equal(lines.length, 1 + N);
  const row = lines.find((l) => l.startsWith('1,')).split(',').map(Number);
  assert.ok(Math.abs(row[1] - 1) < 1e-6 && Math.abs(row[2] - f32(TURN)) < 1e-6, `CSV row at 1 s: ${row}`);
  await shot(page, '32-standalone-plots');
  await checkLabels(page, 'the results page');

  // The address reopens the result.
  await page.reload();
  await page.getByRole('table', { name: 'Summary of result shapes.mat' }).waitFor();
  await page.waitForFunction(() => window.cad2moShapes?.shapes.length === 2);

  let robot = null;
  const fixture = process.env.CAD2MO_FULLROBOT || '/work/shared/fixtures/mat/lbl-srg+BuildingsPy/fullRobot.mat';
  if (existsSync(fixture)) {
    step('standalone results: RobotR3 fullRobot from Dymola');
    await page.locator('section.results-upload input[type=file]').setInputFiles(fixture);
    await page.getByRole('table', { name: 'Summary of result fullRobot.mat' }).waitFor({ timeout: 60_000 });
    await page.locator('#results-play').waitFor({ timeout: 60_000 });
    await page.waitForFunction(() => window.cad2moShapes && Number(document.querySelector('.shapes-stage')?.dataset.rendered) > 0);
    const stop = Number(await page.locator('#results-scrub').getAttribute('max'));
    await setScrub(page, stop / 2);
    scene = await inspect(page);
    const drawn = scene.shapes.filter((s) => s.visible && s.max.every(Number.isFinite) && s.max.some((x, i) => x - s.min[i] > 1e-6));
    assert.ok(drawn.length > 0, `RobotR3's shapes drawn: ${scene.shapes.length} shapes`);
    robot = { shapes: scene.shapes.length, drawn: drawn.length, frames: scene.frames.length };
    step(`fullRobot ${JSON.stringify(robot)}`);
    await shot(page, '33-standalone-fullrobot');
    // Its DXF shapes are boxes until their files are chosen (issue 30): a chosen b1.dxf (3D faces
    // of a 0.1 m tetrahedron written here) draws b1's shape, read in the browser; a file no shape
    // names and one without 3D faces are named.
    step('standalone results: RobotR3 shape files');
    const chooser = page.locator('.shape-files-box');
    const listed = await chooser.textContent();
    for (let i = 0; i <= 6; i++) assert.ok(listed.includes(`b${i}.dxf`), `b${i}.dxf is listed: ${listed}`);
    const faces = [[[0, 0, 0], [0.1, 0, 0], [0, 0.1, 0]], [[0, 0, 0], [0, 0.1, 0], [0, 0, 0.1]], [[0, 0, 0], [0, 0, 0.1], [0.1, 0, 0]], [[0.1, 0, 0], [0, 0, 0.1], [0, 0.1, 0]]];
    const dxf = (fs) => ['  0', 'SECTION', '  2', 'ENTITIES', ...fs.flatMap((c) => ['  0', '3DFACE', '  8', '0', ...[...c, c[2]].flatMap((p, k) => [` 1${k}`, String(p[0]), ` 2${k}`, String(p[1]), ` 3${k}`, String(p[2])])]), '  0', 'ENDSEC', '  0', 'EOF', ''].join('\r\n');
    const files = { 'b1.dxf': dxf(faces), 'B2.DXF': dxf([]).replace('ENTITIES', 'ENTITIES\r\n  0\r\nLINE'), 'notes.dxf': dxf(faces) };
    for (const [n, text] of Object.entries(files)) writeFileSync(join(downloads, n), text);
    await page.locator('#shape-files').setInputFiles(Object.keys(files).map((n) => join(downloads, n)));
    const out = page.locator('.shape-files-out');
    await out.locator('p.ok').waitFor();
    const said = await out.textContent();
    assert.match(said, /Drawn from b1\.dxf \(1 shape\)/, said);
    assert.match(said, /No shape of this result names notes\.dxf/, said);
    assert.match(said, /B2\.DXF has no 3DFACE entities/, said);
    const left = await out.locator('p.muted').last().textContent();
    assert.ok(left.startsWith('Still boxes: ') && left.includes('b0.dxf') && !left.includes('b1.dxf'), left);
    const b1 = (await inspect(page)).shapes.filter((x) => x.from === 'b1.dxf');
    assert.equal(b1.length, 1, 'one shape drawn from b1.dxf');
    assert.equal(b1[0].vertices, 12, 'the four 3D faces are drawn');
    // Placed in the shape's frame: unscaled with MSL's extra = 0, scaled by length, width, height otherwise.
    const col = Math.hypot(b1[0].matrix[0], b1[0].matrix[1], b1[0].matrix[2]);
    if (!b1[0].scaled) assert.ok(Math.abs(col - 1) < 1e-6, `b1.dxf drawn at its own size: ${col}`);
    robot.fileShape = { from: 'b1.dxf', scaled: b1[0].scaled, scale: col };
    await shot(page, '33b-standalone-fullrobot-dxf');
    await page.getByRole('button', { name: 'Delete result fullRobot.mat' }).click();
    await page.getByRole('dialog').getByRole('button', { name: 'Delete' }).click();
    await page.locator('tr[data-result-id]', { hasText: 'fullRobot.mat' }).waitFor({ state: 'detached' });
  } else {
    step(`standalone results: no ${fixture}, RobotR3 skipped`);
  }

  step('standalone results: open, delete');
  await page.locator('table.results tr[data-result-id]').filter({ hasText: 'shapes.mat' }).last().getByRole('button', { name: 'Open result shapes.mat' }).click();
  await page.getByRole('table', { name: 'Summary of result shapes.mat' }).waitFor();
  await page.waitForFunction(() => window.cad2moShapes?.shapes.length === 2);
  const count = await page.locator('table.results tr[data-result-id]').count();
  await page.locator('table.results tr[aria-current="true"]').getByRole('button', { name: 'Delete result shapes.mat' }).click();
  await page.getByRole('dialog').getByRole('button', { name: 'Delete' }).click();
  await page.getByRole('table', { name: 'Summary of result shapes.mat' }).waitFor({ state: 'detached' });
  assert.equal(await page.locator('table.results tr[data-result-id]').count(), count - 1);
  assert.equal(await page.evaluate(() => window.cad2moShapes), undefined, 'the 3D view is gone with its result');
  return { csv: csvPath, robot };
}
