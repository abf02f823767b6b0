import test from 'node:test';
import assert from 'node:assert/strict';
import { PlayerClock, advance, stepTime, SPEEDS } from './player-data.js';

test('advance plays at the speed, stops at the end or loops', () => {
  const o = { speed: 2, start: 1, stop: 3, loop: false };
  assert.deepEqual(advance(1, 0.25, o), { t: 1.5, ended: false });
  assert.deepEqual(advance(2.9, 0.25, o), { t: 3, ended: true });
  const l = advance(2.9, 0.25, { ...o, loop: true });
  assert.ok(Math.abs(l.t - 1.4) < 1e-12 && !l.ended);
  assert.deepEqual(advance(1, 0.5, { ...o, speed: 0.1 }), { t: 1.05, ended: false });
});

test('stepTime goes to the next or previous sample, and stays at the ends', () => {
  const ts = [0, 0.02, 0.04, 0.04, 0.1];
  const o = { start: 0, stop: 0.1 };
  assert.equal(stepTime(ts, 0, 1, o), 0.02);
  assert.equal(stepTime(ts, 0.03, 1, o), 0.04);
  assert.equal(stepTime(ts, 0.04, 1, o), 0.1, 'repeated instants are one step');
  assert.equal(stepTime(ts, 0.1, 1, o), 0.1, 'stays at the last sample');
  assert.equal(stepTime(ts, 0.1, -1, o), 0.04);
  assert.equal(stepTime(ts, 0.03, -1, o), 0.02);
  assert.equal(stepTime(ts, 0, -1, o), 0, 'stays at the first sample');
  assert.equal(stepTime([], 0.5, 1, { start: 0, stop: 2 }), 0.52, 'a hundredth of the span without samples');
  assert.equal(stepTime(undefined, 2, 1, { start: 0, stop: 2 }), 2);
});

test('the speeds offered span 0.1× to 4×', () => {
  for (const s of [0.1, 0.25, 0.5, 1, 2, 4]) assert.ok(SPEEDS.includes(s), `${s}× offered`);
});

test('a clock plays at its speed and stops at the end; Play at the end starts again', () => {
  const c = new PlayerClock();
  c.load({ start: 0, stop: 2, dt: 0.01 });
  assert.equal(c.time, 0);
  assert.equal(c.setSpeed(0.5), 0.5);
  assert.equal(c.setSpeed(3), 0.5, 'a speed not offered is ignored');
  c.play();
  assert.ok(c.playing && c.running);
  assert.equal(c.tick(1), false);
  assert.equal(c.time, 0.5);
  c.setSpeed(4);
  assert.equal(c.tick(1), true, 'ended');
  assert.equal(c.time, 2);
  assert.ok(!c.playing && !c.following);
  c.play();
  assert.equal(c.time, 0, 'Play at the end plays from the start');
  c.tick(0.25);
  assert.equal(c.time, 1);
});

test('a looping clock wraps to the start and keeps playing', () => {
  const c = new PlayerClock({ loop: true, speed: 2 });
  c.load({ start: 1, stop: 3 });
  c.seek(2.9);
  c.play();
  assert.equal(c.tick(0.25), false);
  assert.ok(Math.abs(c.time - 1.4) < 1e-12 && c.playing);
  c.loop = false;
  c.seek(3);
  c.play();
  assert.equal(c.time, 1, 'without loop, Play at the end starts again');
});

test('step moves by the fixed step or to the neighbouring sample, stays in range and pauses', () => {
  const c = new PlayerClock();
  c.load({ start: 0, stop: 0.05, dt: 0.01 });
  c.play();
  c.tick(0.012);
  assert.ok(Math.abs(c.step(1) - 0.022) < 1e-12, 'a fixed step from where it paused');
  assert.ok(!c.playing, 'stepping pauses');
  c.step(-1);
  c.step(-1);
  c.step(-1);
  assert.equal(c.time, 0, 'not before the start');
  const s = new PlayerClock();
  s.load({ start: 0, stop: 0.1, times: [0, 0.02, 0.04, 0.04, 0.1], at: 0.03 });
  assert.equal(s.time, 0.03, 'loaded at a given time');
  assert.equal(s.step(1), 0.04);
  assert.equal(s.step(1), 0.1);
  assert.equal(s.step(1), 0.1, 'stays at the last sample');
  assert.equal(s.step(-1), 0.04);
  assert.equal(s.seek(7), 0.1, 'seek clamps');
  assert.equal(s.seek(NaN), 0.1, 'a bad time keeps the time');
});

test('a live clock follows the newest frame, pauses on a recorded one, replays and catches up', () => {
  const c = new PlayerClock({ live: true });
  c.load({ start: 0, stop: 0 });
  assert.ok(c.following && c.running && !c.playing);
  c.extend(0, 1.5);
  assert.equal(c.time, 1.5, 'following: at the newest frame');
  c.pause();
  assert.ok(!c.following && !c.running);
  c.extend(0, 2);
  assert.equal(c.time, 1.5, 'paused: the time holds while frames arrive');
  c.step(-1);
  assert.ok(Math.abs(c.time - 1.48) < 1e-12, 'no samples: a hundredth of the span back');
  c.load({ start: 0, stop: 2, times: [0, 0.5, 1, 1.5, 2], at: 1.5 });
  assert.ok(!c.following, 'loaded at a time: paused there');
  assert.equal(c.step(-1), 1, 'one recorded frame back');
  c.extend(1.2, 2);
  assert.equal(c.time, 1.2, 'the oldest frames were dropped: the time moves into the recording');
  c.setSpeed(0.1);
  c.play();
  c.tick(1);
  assert.ok(Math.abs(c.time - 1.3) < 1e-12 && c.playing, 'replays at 0.1×');
  c.setSpeed(4);
  assert.equal(c.tick(1), true, 'caught up with the newest frame');
  assert.ok(c.following && !c.playing && c.time === 2, 'following again');
  c.extend(1.2, 2.5);
  assert.equal(c.time, 2.5);
  c.pause();
  c.goLive();
  assert.ok(c.following);
  c.pause();
  c.play();
  assert.ok(c.following, 'Play at the newest frame goes live');
  const plain = new PlayerClock();
  plain.load({ start: 0, stop: 1 });
  plain.goLive();
  assert.ok(!plain.following, 'only a live clock follows');
});
