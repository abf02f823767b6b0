import test from 'node:test';
import assert from 'node:assert/strict';
import { newObject, freshName, rotationFromAngles, anglesFromRotation, withPose, errorsByObject, describe } from './scene-data.js';

test('new objects get free names and default shapes', () => {
  assert.equal(freshName('box', ['box1', 'box2', 'arm']), 'box3');
  const o = newObject('cylinder', []);
  assert.deepEqual(o.shape, { kind: 'cylinder', radius: 0.1, length: 0.2 });
  assert.equal(o.name, 'cylinder1');
  assert.throws(() => newObject('cone', []));
});

test('rotations from typed angles are orthonormal and read back', () => {
  const angles = [30, -45, 120];
  const r = rotationFromAngles(angles);
  for (let i = 0; i < 3; i += 1) {
    for (let j = 0; j < 3; j += 1) {
      const dot = r[0][i] * r[0][j] + r[1][i] * r[1][j] + r[2][i] * r[2][j];
      assert.ok(Math.abs(dot - (i === j ? 1 : 0)) < 1e-12);
    }
  }
  // 90° about z turns x into y: the first column is (0, 1, 0).
  const z = rotationFromAngles([0, 0, 90]);
  assert.ok(Math.abs(z[1][0] - 1) < 1e-12 && Math.abs(z[0][1] + 1) < 1e-12);
  anglesFromRotation(r).forEach((a, k) => assert.ok(Math.abs(a - angles[k]) < 1e-9));
});

test('typed poses are checked and errors are named', () => {
  const o = newObject('box', []);
  assert.deepEqual(withPose(o, ['1', '2', '3'], ['0', '0', '0']).object.position, [1, 2, 3]);
  assert.match(withPose(o, ['1', '', '3'], ['0', '0', '0']).error, /^position/);
  assert.match(withPose(o, ['1', '2', '3'], ['x', '0', '0']).error, /^rotation/);
  const byObj = errorsByObject([{ field: 'objects[1].shape.size', message: 'bad' }, { field: 'scene', message: 'not JSON' }]);
  assert.deepEqual(byObj.get(1), ['shape.size: bad']);
  assert.deepEqual(byObj.get(-1), ['scene: not JSON']);
  assert.equal(describe({ ...o, kind: 'free' }), 'box (0.2 × 0.2 × 0.2 m), free');
});

test('duplicates get a free name and an offset; mesh files give names and objects', async () => {
  const { duplicateObject, meshNameFromFile, meshObject, sceneInterferences } = await import('./scene-data.js');
  const o = { ...newObject('box', []), color: [1, 0, 0] };
  const d = duplicateObject(o, ['box1', 'box2'], [0.3, 0, 0]);
  assert.equal(d.name, 'box3');
  assert.deepEqual(d.position, [0.3, 0, 0]);
  assert.deepEqual(d.color, [1, 0, 0]);
  d.shape.size[0] = 9;
  assert.equal(o.shape.size[0], 0.2, 'the copy shares nothing with the original');
  assert.equal(duplicateObject({ ...o, name: 'table' }, ['table']).name, 'table1');
  assert.deepEqual(meshNameFromFile('C:\\parts\\2-pallet v3.STL'), { name: 'm2_pallet_v3' });
  assert.deepEqual(meshNameFromFile('fixture.obj'), { name: 'fixture' });
  assert.deepEqual(meshNameFromFile('cell.WRL'), { name: 'cell' });
  assert.deepEqual(meshNameFromFile('tool.dae'), { name: 'tool', unit: 'm' }, 'COLLADA states its unit');
  assert.match(meshNameFromFile('fixture.3ds').error, /^file: /);
  const m = meshObject('fixture', 'mm', ['fixture1']);
  assert.deepEqual([m.name, m.shape], ['fixture2', { kind: 'mesh', mesh: 'fixture', unit: 'mm' }]);
  assert.throws(() => meshObject('fixture', 'furlong', []));
  assert.equal(describe(m), 'mesh (fixture, mm), static');
  const inter = [{ a: 'ARM', b: 'box1', depth: 0.01 }, { a: 'ARM', b: 'BASE', depth: 0.02 }, { a: 'box1', b: 'LINK', depth: 0.03 }];
  assert.deepEqual(sceneInterferences(inter, [o]), [{ object: 'box1', other: 'ARM', depth: 0.01 }, { object: 'box1', other: 'LINK', depth: 0.03 }]);
});

test('moving objects: pose at a time by velocity or along the pose table', async () => {
  const { poseAt, quatOf, rotationOfQuat } = await import('./scene-data.js');
  const o = { ...newObject('box', []), position: [1, 0, 0] };
  assert.deepEqual(poseAt(o, 5).position, [1, 0, 0], 'static objects stay');
  const conveyor = { ...o, kind: 'moving', motion: { velocity: [0.5, 0, -0.1] } };
  assert.deepEqual(poseAt(conveyor, 2).position, [2, 0, -0.2]);
  const z90 = rotationFromAngles([0, 0, 90]);
  const table = { ...o, kind: 'moving', motion: { poses: [{ time: 1, position: [0, 0, 0] }, { time: 3, position: [2, 4, 0], rotation: z90 }] } };
  assert.deepEqual(poseAt(table, 0).position, [0, 0, 0], 'held before the first row');
  assert.deepEqual(poseAt(table, 9).position, [2, 4, 0], 'held after the last');
  const mid = poseAt(table, 2);
  assert.deepEqual(mid.position, [1, 2, 0]);
  anglesFromRotation(mid.rotation).forEach((a, k) => assert.ok(Math.abs(a - [0, 0, 45][k]) < 1e-9, `45° about z halfway: ${anglesFromRotation(mid.rotation)}`));
  const r = rotationFromAngles([170, -30, 100]);
  rotationOfQuat(quatOf(r)).forEach((row, i) => row.forEach((x, j) => assert.ok(Math.abs(x - r[i][j]) < 1e-12)));
});

test('primitive dimensions by typed numbers, checked like the API', async () => {
  const { shapeFields, withShape } = await import('./scene-data.js');
  const box = newObject('box', []);
  assert.deepEqual(shapeFields(box.shape).map((f) => f.field), ['size[0]', 'size[1]', 'size[2]']);
  assert.deepEqual(withShape(box, ['1', '0.5', '0.04']).object.shape.size, [1, 0.5, 0.04]);
  assert.deepEqual(box.shape.size, [0.2, 0.2, 0.2], 'the original is unchanged');
  assert.match(withShape(box, ['1', '0', '1']).error, /^shape\.size\[1\]: "0" must be/);
  assert.match(withShape(box, ['1', '1', '2000']).error, /^shape\.size\[2\]/);
  const cyl = newObject('cylinder', []);
  assert.deepEqual(withShape(cyl, ['0.05', '0.3']).object.shape, { kind: 'cylinder', radius: 0.05, length: 0.3 });
  assert.match(withShape(cyl, ['x', '0.3']).error, /^shape\.radius/);
  assert.deepEqual(shapeFields(newObject('plane', []).shape), []);
});

test('the kind form: static, moving by velocity or poses, free with mass and inertia', async () => {
  const { kindForm, withKind, kindControl, newObject: make } = await import('./scene-data.js');
  const box = make('box', []);
  const f = kindForm(box);
  assert.equal(f.kind, 'static');
  const moving = withKind(box, { ...f, kind: 'moving', motion: 'velocity', velocity: ['0.5', '0', '-0.1'] }).object;
  assert.deepEqual([moving.kind, moving.motion], ['moving', { velocity: [0.5, 0, -0.1] }]);
  assert.deepEqual(kindForm(moving).velocity, ['0.5', '0', '-0.1'], 'the form shows what the object holds');
  assert.match(withKind(box, { ...f, kind: 'moving', motion: 'velocity', velocity: ['x', '0', '0'] }).error, /^motion\.velocity: /);
  const table = withKind(box, { ...f, kind: 'moving', motion: 'poses', poses: '0 0 0 0\n2, 1, 0, 0, 0, 0, 90' }).object;
  assert.equal(table.motion.poses.length, 2);
  assert.deepEqual(table.motion.poses[1].position, [1, 0, 0]);
  assert.ok(Math.abs(table.motion.poses[1].rotation[0][1] + 1) < 1e-12, '90° about z');
  assert.equal(kindForm(table).poses.split('\n')[1], '2 1 0 0 0 0 90');
  assert.match(withKind(box, { ...f, kind: 'moving', motion: 'poses', poses: '0 0 0\n' }).error, /^motion\.poses\[0\]: /);
  const free = withKind(moving, { ...f, kind: 'free', mass: '3', inertia: ['', '', ''] }).object;
  assert.deepEqual([free.kind, free.mass, free.motion, free.inertia], ['free', 3, undefined, undefined]);
  assert.deepEqual(withKind(box, { ...f, kind: 'free', mass: '2', inertia: ['1', '1', '1.5'] }).object.inertia, [1, 1, 1.5]);
  assert.match(withKind(box, { ...f, kind: 'free', mass: '' }).error, /^mass: /);
  const back = withKind(free, { ...kindForm(free), kind: 'static' }).object;
  assert.deepEqual(Object.keys(back).sort(), Object.keys(box).sort(), 'static drops kind, motion, mass, inertia');
  assert.match(withKind({ ...box, attached_to: 'ARM' }, { ...f, kind: 'moving' }).error, /^kind: /);
  assert.equal(kindControl('objects[2].motion.velocity', 2), 'velocity');
  assert.equal(kindControl('objects[2].motion.poses[1].time', 2), 'poses');
  assert.equal(kindControl('objects[2].mass', 2), 'mass');
  assert.equal(kindControl('objects[1].mass', 2), null, 'another object');
  assert.equal(kindControl('objects[2].position', 2), null);
});
