import test from 'node:test';
import assert from 'node:assert/strict';
import { liveUrl, liveProtocols, newFrame, decodeFrame, copyFrame, parseMessage, RateMeter, LiveRuns, backoff, splitHostPort, startModifier, FINAL, FrameRecorder, RECORD_SECONDS, RECORD_BYTES } from './live-data.js';
import { posesAt } from './results-data.js';

/** A relayed frame as the contract lays it out. */
function frame({ run = 7, seq = 0, time = 0, flags = 0, poses = [] }) {
  const n = poses.length / 7;
  const buf = new ArrayBuffer(24 + 28 * n);
  const v = new DataView(buf);
  v.setUint32(0, run, true);
  v.setUint32(4, seq, true);
  v.setFloat64(8, time, true);
  v.setUint32(16, n, true);
  v.setUint32(20, flags, true);
  poses.forEach((x, i) => v.setFloat32(24 + 4 * i, x, true));
  return buf;
}

test('liveUrl and liveProtocols follow the page and the token', () => {
  assert.equal(liveUrl({ protocol: 'http:', host: '127.0.0.1:8080' }, 'a b', 3), 'ws://127.0.0.1:8080/api/models/a%20b/versions/3/live/ws');
  assert.equal(liveUrl({ protocol: 'https:', host: 'x.example' }, 'id', 1), 'wss://x.example/api/models/id/versions/1/live/ws');
  assert.deepEqual(liveProtocols(''), ['cad2mo.live']);
  assert.deepEqual(liveProtocols('abc'), ['cad2mo.live', 'bearer.abc']);
});

test('decodeFrame reads a frame in place, grows once, refuses partial frames', () => {
  const f = newFrame(1);
  const arr = f.poses;
  const one = frame({ run: 9, seq: 4, time: 1.25, flags: FINAL, poses: [1, 2, 3, 0, 0, 0.5, 0.75] });
  assert.equal(decodeFrame(one, f), f);
  assert.deepEqual([f.run, f.seq, f.time, f.n, f.flags], [9, 4, 1.25, 1, FINAL]);
  assert.deepEqual([...f.poses], [1, 2, 3, 0, 0, 0.5, 0.75]);
  assert.equal(f.poses, arr, 'the same array is reused');
  const two = frame({ time: 2, poses: [1, 1, 1, 0, 0, 0, 1, 2, 2, 2, 0, 0, 0, 1] });
  decodeFrame(two, f);
  assert.equal(f.n, 2);
  assert.equal(f.poses.length, 14);
  const grown = f.poses;
  decodeFrame(one, f);
  assert.equal(f.poses, grown, 'no new array for fewer bodies');
  assert.equal(f.n, 1);
  assert.equal(decodeFrame(two.slice(0, 30), f), null);
  assert.equal(decodeFrame(new ArrayBuffer(8), f), null);
  assert.equal(decodeFrame('text', f), null);
  assert.equal(f.time, 1.25, 'a refused message leaves the frame as it was');
  const g = copyFrame(f, newFrame());
  assert.deepEqual([g.run, g.time, g.n, [...g.poses]], [9, 1.25, 1, [1, 2, 3, 0, 0, 0.5, 0.75]]);
});

test('parseMessage keeps the contract messages only', () => {
  assert.deepEqual(parseMessage('{"type":"hello","model":"m","version":1,"bodies":["A"]}').bodies, ['A']);
  assert.equal(parseMessage('{"type":"stats","run":3,"frames":10}').frames, 10);
  assert.equal(parseMessage('{"type":"end","run":3,"time":2}').time, 2);
  assert.equal(parseMessage('{"type":"hello"}'), null);
  assert.equal(parseMessage('{"type":"other","run":1}'), null);
  assert.equal(parseMessage('not json'), null);
  assert.equal(parseMessage('null'), null);
});

test('RateMeter counts the frames of the last second', () => {
  const r = new RateMeter(1, 16);
  assert.equal(r.rate(0), 0);
  for (let i = 0; i < 10; i++) r.tick(i * 0.02);
  assert.equal(r.rate(0.2), 10);
  assert.equal(r.rate(1.1), 5, 'the frames older than a second are gone');
  const full = new RateMeter(1, 4);
  for (let i = 0; i < 10; i++) full.tick(i * 0.01);
  assert.ok(Math.abs(full.rate(0.09) - 4 / 0.03) < 1e-9, `${full.rate(0.09)}: a full ring measures its own span`);
  full.reset();
  assert.equal(full.rate(1), 0);
});

test('LiveRuns follows the newest run, its stats and its end', () => {
  const runs = new LiveRuns({ silence: 2 });
  assert.ok(runs.accept(1, 0));
  runs.frame({ time: 0.5, flags: 0 }, 0);
  assert.equal(runs.frames, 1);
  assert.ok(runs.accept(2, 0.1), 'a new run takes over');
  runs.frame({ time: 0.02, flags: 0 }, 0.1);
  assert.equal(runs.run, 2);
  assert.equal(runs.frames, 1, 'counted afresh');
  assert.ok(!runs.accept(1, 0.2), 'the older run is ignored while the new one is live');
  assert.ok(!runs.message({ type: 'stats', run: 1, frames: 99 }));
  assert.ok(runs.message({ type: 'stats', run: 2, frames: 5, lost: 1 }));
  assert.equal(runs.stats.lost, 1);
  assert.ok(!runs.ended);
  assert.ok(runs.message({ type: 'end', run: 2, time: 3 }));
  assert.ok(runs.ended);
  assert.equal(runs.endTime, 3);
  assert.ok(runs.accept(1, 0.3), 'after its end an older run may be followed again');
  assert.equal(runs.run, 1);
  assert.ok(!runs.ended);
  runs.frame({ time: 1, flags: FINAL }, 0.3);
  assert.ok(runs.ended, 'the final flag ends the run too');
  const quiet = new LiveRuns({ silence: 2 });
  quiet.accept(1, 0);
  quiet.frame({ time: 0, flags: 0 }, 0);
  quiet.accept(2, 0.1);
  quiet.frame({ time: 0, flags: 0 }, 0.1);
  assert.ok(quiet.accept(1, 5), 'a silent run gives way');
});

test('backoff doubles up to its maximum, with bounded jitter', () => {
  const fixed = { random: () => 1, jitter: 0.2 };
  assert.equal(backoff(0, fixed), 500);
  assert.equal(backoff(1, fixed), 1000);
  assert.equal(backoff(3, fixed), 4000);
  assert.equal(backoff(10, fixed), 10000);
  assert.equal(backoff(1000, fixed), 10000);
  assert.equal(backoff(0, { random: () => 0, jitter: 0.2 }), 400);
});

test('splitHostPort and startModifier', () => {
  assert.deepEqual(splitHostPort('127.0.0.1:7878'), { host: '127.0.0.1', port: 7878 });
  assert.deepEqual(splitHostPort('[::1]:9000'), { host: '::1', port: 9000 });
  assert.equal(splitHostPort('nohost'), null);
  assert.equal(startModifier({ udp: '127.0.0.1:7878', auth_required: false }), 'Mechatronics(liveView=true, liveHost="127.0.0.1", livePort=7878)');
  assert.equal(
    startModifier({ udp: '0.0.0.0:7000', auth_required: true }, 'cad.example'),
    'Mechatronics(liveView=true, liveHost="cad.example", livePort=7000, liveToken="<an API token>")',
  );
});

/** A decoded frame of `n` bodies at time t: body k at (t, k, 0), unit quaternions. */
function posed(t, n = 2) {
  const f = newFrame(n);
  f.time = t;
  f.n = n;
  for (let k = 0; k < n; k++) f.poses.set([t, k, 0, 0, 0, 0, 1], k * 7);
  return f;
}

test('FrameRecorder keeps the last seconds in time order, exactly as received', () => {
  const r = new FrameRecorder({ seconds: 1 });
  assert.equal(r.count, 0);
  for (let i = 0; i <= 150; i++) assert.ok(r.push(posed(i / 50)));
  assert.equal(r.stop, 3);
  assert.ok(Math.abs(r.start - 2) < 1e-12, `the last second: from ${r.start}`);
  assert.equal(r.count, 51);
  assert.ok(!r.push(posed(2.5)), 'a frame older than the newest is not recorded');
  assert.ok(!r.push(posed(3)), 'nor one at the same time');
  const ts = r.times;
  for (let i = 1; i < ts.length; i++) assert.ok(ts[i] > ts[i - 1], 'ascending');
  // Interpolated between frames by the results' posesAt; exact at a frame.
  const s = r.stream(['a', 'b']);
  const at = posesAt(s, 2.5);
  assert.deepEqual(Array.from(at.subarray(0, 3)), [Math.fround(2.5), 0, 0]);
  const mid = posesAt(s, 2.51);
  assert.ok(Math.abs(mid[0] - 2.51) < 1e-6 && mid[7 + 1] === 1, 'between two frames, lerped');
});

test('FrameRecorder stays within its byte bound, dropping the oldest frames', () => {
  const n = 10;
  const bytes = 64 * 1024;
  const r = new FrameRecorder({ seconds: 1e9, bytes });
  for (let i = 0; i < 5000; i++) r.push(posed(i * 0.001, n));
  assert.ok(r.size <= bytes, `${r.size} bytes of ${bytes}`);
  assert.equal(r.count, r.limit, 'as many frames as the bound holds');
  assert.ok(r.limit > 100, `${r.limit} frames of ${n} bodies in 64 KiB`);
  assert.equal(r.stop, 4.999);
  assert.ok(Math.abs(r.start - (5000 - r.limit) * 0.001) < 1e-12, 'the newest frames kept');
  // Each kept frame still holds its own poses after the compactions.
  const s = r.stream(Array.from({ length: n }, (_, k) => `b${k}`));
  for (const i of [0, 17, r.count - 1]) {
    const t = s.times[i];
    assert.equal(s.poses[i * n * 7], Math.fround(t));
    assert.equal(s.poses[i * n * 7 + 7 + 1], 1);
  }
});

test('FrameRecorder starts again with another body count; the default bound is 60 s or 64 MB', () => {
  const r = new FrameRecorder();
  r.push(posed(0, 2));
  r.push(posed(0.1, 2));
  assert.ok(r.push(posed(0.05, 3)), 'another body count: a new recording');
  assert.equal(r.count, 1);
  assert.equal(RECORD_SECONDS, 60);
  assert.equal(RECORD_BYTES, 64 * 1024 * 1024);
  // 29 bodies (LEGS) at 1 kHz for 60 s fit in the bound.
  const legs = new FrameRecorder();
  legs.reset(29);
  assert.ok(legs.limit >= 60_000, `${legs.limit} frames`);
});
