// The Live tab, end to end (part of ui.mjs, on the model view of the uploaded arm). No simulator
// runs here: the sender is the C test harness built from the package's cad2mo_live.c
// (CAD2MO_LIVE_HARNESS, compiled by tests/ui.rs), fed a known motion on stdin: every body at its
// CAD pose, the whole model turning about the vertical through its middle at 0.5 rad/s, 3 s at
// 50 Hz, paced at real time. Checked: how to start a stream (the UDP address, no token on
// loopback), the connection, the meshes moving, the world pose of every mesh against the motion
// at the simulated time the page shows, mid-stream paused in the dock player, one recorded frame
// back and forward, replayed at 0.25× (between frames), live again and after the stream's end, the
// frame counters, the end, the active runs, the service's counters (GET /api/live), and that
// leaving the tab closes the socket and hands the bodies back to the joints.

import { poseDistance } from './lib.mjs';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { Matrix4, Vector3 } from 'three';
import { frameMatrix } from '../src/viewer/kinematics.js';

const RATE = 50; // frames per simulated second
const STOP = 3; // s
const SPEED = 0.5; // rad/s about the vertical

/** The known motion: body name → its CS1 (frame_a) world matrix at time t. */
function motion(report) {
  const g = report.options?.gravity || [0, 0, -9.81];
  const up = new Vector3(-g[0], -g[1], -g[2]);
  if (up.lengthSq() === 0) up.set(0, 0, 1);
  up.normalize();
  const cad = new Map(report.bodies.map((b) => [b.modelica_name, frameMatrix(b.cs1)]));
  const centre = new Vector3();
  for (const m of cad.values()) centre.add(new Vector3().setFromMatrixPosition(m));
  centre.divideScalar(Math.max(cad.size, 1));
  return (name, t) => {
    const m0 = cad.get(name);
    assert.ok(m0, `the live view's body ${name} is in the report`);
    const turn = new Matrix4()
      .makeTranslation(centre.x, centre.y, centre.z)
      .multiply(new Matrix4().makeRotationAxis(up, SPEED * t))
      .multiply(new Matrix4().makeTranslation(-centre.x, -centre.y, -centre.z));
    return turn.multiply(m0);
  };
}

/** The harness's stdin: per line t, then per body r_0 (3) and R.T row by row (9; R.T = Mᵀ). */
function samples(bodies, at) {
  const lines = [];
  for (let i = 0; i <= STOP * RATE; i++) {
    const t = i / RATE;
    const row = [t];
    for (const name of bodies) {
      const e = at(name, t).elements; // column-major: M[i][j] = e[j * 4 + i]
      row.push(e[12], e[13], e[14]);
      for (let r = 0; r < 3; r++) for (let c = 0; c < 3; c++) row.push(e[r * 4 + c]); // R.T[r][c] = M[c][r]
    }
    lines.push(row.map((x) => String(x)).join(' '));
  }
  return lines.join('\n') + '\n';
}


/** In one task: the time the page shows, its data-time, and every mesh's world matrix. */
const observe = (page) =>
  page.evaluate(() => {
    const status = document.querySelector('.live-status');
    const poses = {};
    for (const [name, b] of window.cad2moViewer.bodies) poses[name] = Array.from(b.group.matrix.elements);
    return {
      shown: status.querySelector('[data-live="time"]').textContent,
      time: Number(status.dataset.time),
      frames: Number(status.dataset.frames),
      ended: status.dataset.ended === 'true',
      posed: window.cad2moViewer.posed ? window.cad2moViewer.posed.size : 0,
      poses,
    };
  });

/** Every streamed body's mesh is where the motion puts it at the shown time. */
function checkPoses(seen, bodies, at, what) {
  const t = Number(seen.shown);
  assert.ok(Number.isFinite(t), `${what}: the page shows a simulated time (${seen.shown})`);
  assert.ok(Math.abs(t - seen.time) < 1e-9, `${what}: the shown time ${seen.shown} is the frame's ${seen.time}`);
  let worst = 0;
  for (const name of bodies) {
    assert.ok(seen.poses[name], `${what}: ${name} is in the 3D view`);
    const d = poseDistance(seen.poses[name], at(name, t).elements);
    assert.ok(d < 1e-4, `${what}: ${name} at t=${t} is ${d} m from the streamed motion`);
    worst = Math.max(worst, d);
  }
  return { t, worst };
}

/** Runs the harness; resolves with its stdout when it exits (rejects on a failure). */
function runHarness(harness, args, input) {
  const child = spawn(harness, args, { stdio: ['pipe', 'pipe', 'pipe'] });
  let out = '';
  let err = '';
  child.stdout.on('data', (d) => (out += d));
  child.stderr.on('data', (d) => (err += d));
  const done = new Promise((resolve, reject) => {
    child.on('error', reject);
    child.on('close', (code) => (code === 0 ? resolve(out) : reject(new Error(`the live harness exited with ${code}: ${err}${out}`))));
  });
  child.stdin.end(input);
  return done;
}

/**
 * @param {import('playwright-core').Page} page  on the model view, version 1 of the arm
 * @param {{step: Function, shot: Function, harness: string|undefined}} o
 */
export async function liveSteps(page, { step, shot, harness }) {
  if (!harness) {
    assert.notEqual(process.env.CAD2MO_REQUIRE_TOOLS, '1', 'the live view test needs its C sender (CAD2MO_LIVE_HARNESS): is a C compiler installed?');
    step('live: skipped (no CAD2MO_LIVE_HARNESS)');
    return { skipped: true };
  }
  const [, modelId, version] = /#\/models\/([^/]+)\/versions\/(\d+)/.exec(page.url());
  const report = await page.evaluate(() => window.cad2moViewer.report);
  const at = motion(report);

  step('live: the tab');
  await page.getByRole('tab', { name: 'Live' }).click();
  const status = page.getByRole('status', { name: 'Live stream' });
  await status.waitFor();
  await page.locator('.live-status[data-connection="open"]').waitFor();
  const info = await page.evaluate((u) => fetch(u).then((r) => r.json()), `/api/models/${modelId}/versions/${version}/live`);
  assert.equal(info.model, decodeURIComponent(modelId));
  assert.equal(info.version, Number(version));
  assert.equal(info.auth_required, false, 'no token on loopback');
  assert.deepEqual([...info.bodies].sort(), report.bodies.map((b) => b.modelica_name).sort(), 'the live view streams every body');
  assert.match(info.layout, /^[0-9a-f]{16}$/);
  const how = page.locator('section.live-how');
  await how.getByText('liveView = true').waitFor();
  assert.match(await how.locator('.live-udp').textContent(), new RegExp(`^${info.udp.replace(/[.[\]]/g, '\\$&')}$`));
  assert.match(await how.locator('.live-auth').textContent(), /No token needed/);
  const [host, port] = [info.udp.slice(0, info.udp.lastIndexOf(':')).replace(/^\[|\]$/g, ''), info.udp.slice(info.udp.lastIndexOf(':') + 1)];
  assert.match(await how.locator('pre.live-modifier').textContent(), new RegExp(`liveView=true, liveHost="${host}", livePort=${port}\\)`));
  assert.equal(await status.locator('[data-live="frames"]').textContent(), '0');

  step('live: stream a known motion');
  const still = await observe(page);
  const sender = runHarness(harness, [host, port, info.model, String(info.version), info.layout, '-', '1'], samples(info.bodies, at));
  let senderFailed = null;
  sender.catch((e) => (senderFailed = e));
  const listed = page.locator('.live-runs-table tr[data-run]').first().waitFor({ timeout: 8_000 }).then(() => true, () => false);
  await page.waitForFunction(() => Number(document.querySelector('.live-status').dataset.time) > 0.8, null, { timeout: 15_000 }).catch((e) => {
    throw senderFailed || e;
  });
  const moving = await observe(page);
  assert.ok(moving.frames > 0 && moving.posed === info.bodies.length, `frames arrive and pose every body: ${moving.frames} frames, ${moving.posed} posed`);
  const moved = info.bodies.filter((n) => poseDistance(moving.poses[n], still.poses[n]) > 1e-3);
  assert.ok(moved.length >= 1, 'the meshes move with the stream');

  // ---- The dock player over the recording: pause mid-stream (the frame shown holds while frames
  // keep arriving), one frame back (the recorded frame before it, where the motion puts it),
  // forward again, a replay at 0.25×, then Go live.
  step('live: pause mid-stream');
  const livePlayer = page.locator('.live-player');
  assert.equal(await livePlayer.getAttribute('data-live'), 'true', 'the player follows the stream');
  assert.equal(await page.locator('#live-play').textContent(), 'Pause');
  await page.locator('#live-play').click();
  await page.getByText(/^Paused: the 3D view shows the recorded frame at/).waitFor();
  const frozen = await observe(page);
  assert.ok(!frozen.ended && frozen.time < STOP, `paused before the end: t=${frozen.time}`);
  const mid = checkPoses(frozen, info.bodies, at, 'paused mid-stream');
  await page.waitForTimeout(300);
  const later = await observe(page);
  assert.equal(later.time, frozen.time, 'the frame shown holds while paused');
  assert.ok(later.ended || later.frames > frozen.frames, `frames keep arriving while paused: ${frozen.frames} → ${later.frames}`);
  for (const name of info.bodies) assert.deepEqual(later.poses[name], frozen.poses[name], `${name} holds still while paused`);
  assert.equal(await livePlayer.getAttribute('data-live'), 'false');

  step('live: one frame back and forward');
  await page.locator('#live-step-back').click();
  await page.waitForFunction((t) => Number(document.querySelector('.live-status').dataset.time) < t, frozen.time);
  const back = await observe(page);
  // The harness sends a frame every 1/50 s: the one before (or, if a datagram was lost, an earlier one).
  const frames = Math.round((frozen.time - back.time) * RATE);
  assert.ok(frames >= 1 && frames <= 3 && Math.abs(back.time * RATE - Math.round(back.time * RATE)) < 1e-6, `one recorded frame back: ${frozen.time} → ${back.time}`);
  checkPoses(back, info.bodies, at, 'one frame back');
  assert.ok(info.bodies.some((n) => poseDistance(back.poses[n], frozen.poses[n]) > 1e-6), 'the meshes moved back to the earlier frame');
  await shot(page, '24-live-paused');
  await page.locator('#live-step').click();
  await page.waitForFunction((t) => Number(document.querySelector('.live-status').dataset.time) > t, back.time);
  const fwd = await observe(page);
  assert.equal(fwd.time, frozen.time, 'Step » goes to the next recorded frame');
  for (const name of info.bodies) assert.ok(poseDistance(fwd.poses[name], frozen.poses[name]) < 1e-9, `${name} is back at the paused frame`);

  step('live: replay at 0.25×, then go live');
  await page.locator('#live-speed').selectOption('0.25');
  await page.locator('#live-play').click();
  const t0 = Date.now();
  await page.waitForFunction((t) => Number(document.querySelector('.live-status').dataset.time) > t + 0.02, frozen.time);
  await page.waitForTimeout(400);
  const replay = await observe(page);
  const wall = (Date.now() - t0) / 1000;
  assert.equal(await livePlayer.getAttribute('data-playing'), 'true', 'replaying');
  assert.ok(replay.time > frozen.time && replay.time - frozen.time <= 0.25 * wall + 0.05, `0.25× replay: ${frozen.time} → ${replay.time} in ${wall} s of wall time`);
  // Between two frames the time shown is rounded to 6 digits: the poses are checked at the exact one.
  assert.equal(Number(replay.shown), Number(replay.time.toPrecision(6)), 'the replayed time is shown');
  checkPoses({ ...replay, shown: String(replay.time) }, info.bodies, at, 'replayed (between recorded frames)');
  await shot(page, '24b-live-replay');
  await page.locator('#live-live').click();
  assert.equal(await livePlayer.getAttribute('data-live'), 'true', 'following again');
  await page.waitForFunction((t) => Number(document.querySelector('.live-status').dataset.time) > t + 0.3, replay.time, { timeout: 10_000 });

  step('live: the stream ends');
  const out = await sender;
  const sent = Number(/sent (\d+)/.exec(out)?.[1]);
  assert.equal(sent, STOP * RATE + 1, `the harness sent every sample: ${out}`);
  await page.locator('.live-status[data-ended="true"]').waitFor({ timeout: 10_000 });
  await page.getByText(/^Stream ended at 3 s\./).waitFor();
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const end = await observe(page);
  const last = checkPoses(end, info.bodies, at, 'after the end');
  assert.equal(last.t, STOP, 'the final frame is shown');
  assert.ok(end.frames > 0, 'frames were counted');
  // Every frame of the run was recorded for the player (3 s, well within the last 60 s).
  const recorded = Number(await status.getAttribute('data-recorded'));
  assert.equal(recorded, end.frames, `the frames were recorded: ${recorded} of ${end.frames}`);
  assert.equal(Number(await status.locator('[data-live="frames"]').textContent()), end.frames);
  // The service's numbers of the run (its stats message, about once a second).
  await page.waitForFunction(() => document.querySelector('[data-live="lost"]').textContent !== '—', null, { timeout: 5_000 });
  const lost = Number(await status.locator('[data-live="lost"]').textContent());
  const stale = Number(await status.locator('[data-live="stale"]').textContent());
  const rtf = await status.locator('[data-live="rtf"]').textContent();
  assert.ok(lost >= 0 && stale >= 0, `lost ${lost}, stale ${stale}`);
  assert.ok(Number(rtf) > 0, `the real-time factor is shown: ${rtf}`);
  assert.ok(await listed, 'the active run was listed while it streamed');
  await shot(page, '25-live-ended');

  // ---- Ambient: the service counted what it relayed.
  step('live: the service counters');
  const service = await page.evaluate(() => fetch('/api/live').then((r) => r.json()));
  assert.equal(service.enabled, true);
  assert.ok(service.counters.relayed > 0 && service.counters.received >= service.counters.relayed, `GET /api/live: ${JSON.stringify(service.counters)}`);
  assert.ok(service.counters.relayed >= end.frames, `the page got no more frames than were relayed: ${end.frames} of ${service.counters.relayed}`);

  // ---- Leaving the tab closes the socket and hands the bodies back to the joints.
  await page.getByRole('tab', { name: 'Structure' }).click();
  assert.equal(await page.evaluate(() => window.cad2moViewer.posed), null, 'the joints pose the model outside the Live tab');
  assert.equal(await page.locator('.live-status').getAttribute('data-connection'), 'closed');
  return { sent, frames: end.frames, recorded, mid: mid.t, back: back.time, replayed: replay.time, worst: Math.max(mid.worst, last.worst), relayed: service.counters.relayed };
}
