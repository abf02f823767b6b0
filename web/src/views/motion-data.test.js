import test from 'node:test';
import assert from 'node:assert/strict';
import { sampleAt, nearestIndex, keyframeProblems, throttle, applyAlternative, torqueSpeedData, freshName } from './motion-data.js';

const traj = { joints: ['J1', 'J2'], t: [0, 0.5, 1], q: [[0, 1, 3], [10, 10, 0]] };

test('sampleAt interpolates between samples and clamps at the ends', () => {
  assert.deepEqual(sampleAt(traj, 0), { J1: 0, J2: 10 });
  assert.deepEqual(sampleAt(traj, 0.25), { J1: 0.5, J2: 10 });
  assert.deepEqual(sampleAt(traj, 0.75), { J1: 2, J2: 5 });
  assert.deepEqual(sampleAt(traj, -1), { J1: 0, J2: 10 });
  assert.deepEqual(sampleAt(traj, 9), { J1: 3, J2: 0 });
});

test('nearestIndex', () => {
  assert.equal(nearestIndex([0, 1, 2, 3], 1.4), 1);
  assert.equal(nearestIndex([0, 1, 2, 3], 1.6), 2);
  assert.equal(nearestIndex([0, 1, 2, 3], 7), 3);
  assert.equal(nearestIndex([], 7), -1);
});

test('keyframeProblems reads field errors, else the detail', () => {
  const p = keyframeProblems({ detail: 'keyframe 2: IK failed', errors: [{ field: 'keyframes[2]', message: 'IK failed' }, { field: 'name', message: 'x' }] });
  assert.deepEqual([...p], [[2, ['IK failed']]]);
  const d = keyframeProblems({ detail: 'keyframe 3: J2 = 3.5 rad is outside its position limits' });
  assert.deepEqual([...d], [[3, ['J2 = 3.5 rad is outside its position limits']]]);
  assert.equal(keyframeProblems({ detail: 'no keyframe here' }).size, 0);
  assert.equal(keyframeProblems(null).size, 0);
});

test('throttle delivers the latest call, one at a time', async () => {
  let clock = 0;
  const timers = [];
  const got = [];
  const f = throttle((x) => got.push(x), 100, { now: () => clock, later: (fn, d) => timers.push([clock + d, fn]) });
  f(1);
  await null;
  f(2);
  f(3);
  assert.deepEqual(got, [1]);
  clock = 100;
  const [[, fn]] = timers.splice(0);
  await fn();
  assert.deepEqual(got, [1, 3]);
});

test('applyAlternative keeps the controller and reference, sets the ratio', () => {
  const drive = { joint: 'J1', motor_instance: 'm', gear_instance: 'g', controller_instance: 'c', overrides: { gear: { ratio: 5 }, controller: { kp: 3 } }, reference: { kind: 'constant', value: 1 } };
  const body = applyAlternative(drive, { motor: { id: 'm2' }, gear: { id: 'g2' }, ratio: 100 });
  assert.deepEqual(body, { motor_instance: 'm2', gear_instance: 'g2', controller_instance: 'c', overrides: { controller: { kp: 3 }, gear: { ratio: 100 } }, reference: { kind: 'constant', value: 1 } });
  const same = applyAlternative(drive, { motor: { id: 'm2' }, gear: { id: 'g2' }, ratio: 74 }, 74);
  assert.deepEqual(same.overrides, { controller: { kp: 3 } });
  const plain = applyAlternative({ ...drive, overrides: {}, reference: undefined }, { motor: { id: 'm2' }, gear: { id: 'g2' }, ratio: null });
  assert.deepEqual(plain, { motor_instance: 'm2', gear_instance: 'g2', controller_instance: 'c', overrides: {} });
});

test('torqueSpeedData sorts by speed and spans the max speed', () => {
  const { data, order } = torqueSpeedData({ t: [0, 1, 2], speed: [3, -1, 2], torque: [0.3, -0.1, 0.2] }, { continuous_torque: 1, peak_torque: 2, max_speed: 10 });
  assert.deepEqual(order, [1, 2, 0]);
  assert.deepEqual(data[0], [-11, -1, 2, 3, 11]);
  assert.deepEqual(data[1], [null, -0.1, 0.2, 0.3, null]);
  assert.deepEqual(data[2], [1, 1, 1, 1, 1]);
  assert.deepEqual(data[5], [-2, -2, -2, -2, -2]);
});

test('freshName', () => {
  assert.equal(freshName('motion', []), 'motion');
  assert.equal(freshName('motion', ['motion', 'motion 2']), 'motion 3');
});

test('bodyDepths and defaultToolFrame pick the end of the chain', async () => {
  const { bodyDepths, defaultToolFrame } = await import('./motion-data.js');
  const rev = { kind: 'revolute' };
  const report = {
    bodies: [{ modelica_name: 'A' }, { modelica_name: 'B' }, { modelica_name: 'C' }],
    joints: [
      { base_body: 'world', follower_body: 'A', in_tree: true, elements: [] },
      { base_body: 'A', follower_body: 'B', in_tree: true, elements: [rev] },
      { base_body: 'C', follower_body: 'B', in_tree: true, elements: [rev, rev] },
    ],
  };
  const d = bodyDepths(report);
  assert.deepEqual([d.get('A'), d.get('B'), d.get('C')], [0, 1, 3]);
  const frames = [
    { node_id: '1', body: 'B', name: 'TIP' },
    { node_id: '2', body: 'C', name: 'CS1' },
    { node_id: '3', body: 'C', name: 'CG' },
  ];
  assert.equal(defaultToolFrame(frames, d).node_id, '3');
  assert.equal(defaultToolFrame([], d), null);
});

test('tick labels tell small ticks apart (the acceleration axis showed only "0")', async () => {
  const { tickLabels } = await import('./motion-data.js');
  assert.deepEqual(tickLabels([0, 0.0002, 0.0004]), ['0', '0.0002', '0.0004']);
  assert.deepEqual(tickLabels([-0.5, 0, 0.5, 1]), ['-0.5', '0', '0.5', '1.0']);
  assert.deepEqual(tickLabels([0, 50, 100]), ['0', '50', '100']);
  assert.deepEqual(tickLabels([1e-6, 2e-6, 3e-6]), ['1e-6', '2e-6', '3e-6']);
  assert.deepEqual(tickLabels([2e6, 4e6]), ['2e6', '4e6']);
  assert.deepEqual(tickLabels([0.1, 0.2, 0.30000000000000004]), ['0.1', '0.2', '0.3']);
  assert.deepEqual(tickLabels([null, 1]), ['', '1']);
});
