import test from 'node:test';
import assert from 'node:assert/strict';
import { History, HISTORY_LIMIT, historyKey } from './scene-history.js';

const at = (x) => [{ name: 'box1', position: [x, 0, 0] }];

test('undo and redo walk the edits back and forth', () => {
  const h = new History();
  let state = at(0);
  for (const x of [1, 2, 3]) {
    h.record(state, `move to ${x}`);
    state = at(x);
  }
  assert.equal(h.undoLabel, 'move to 3');
  state = h.undo(state).state;
  assert.deepEqual(state, at(2));
  state = h.undo(state).state;
  assert.deepEqual(state, at(1));
  assert.equal(h.redoLabel, 'move to 2');
  state = h.redo(state).state;
  assert.deepEqual(state, at(2));
  state = h.redo(state).state;
  assert.deepEqual(state, at(3));
  assert.equal(h.redo(state), null, 'nothing more to redo');
  // A new edit after an undo drops the redo branch.
  state = h.undo(state).state;
  h.record(state, 'delete');
  state = [];
  assert.equal(h.canRedo, false);
  assert.deepEqual(h.undo(state).state, at(2));
});

test('snapshots are copies: editing the live state does not change the past', () => {
  const h = new History();
  const live = at(5);
  h.record(live, 'move');
  live[0].position[0] = 9;
  assert.deepEqual(h.undo(live).state, at(5));
  assert.deepEqual(h.redo(at(5)).state[0].position, [9, 0, 0]);
});

test('at least 50 edits can be undone, the oldest beyond the limit are forgotten', () => {
  assert.ok(HISTORY_LIMIT >= 50);
  const h = new History();
  let state = at(0);
  for (let x = 1; x <= HISTORY_LIMIT + 20; x += 1) {
    h.record(state, `move ${x}`);
    state = at(x);
  }
  let n = 0;
  while (h.canUndo) {
    state = h.undo(state).state;
    n += 1;
  }
  assert.equal(n, HISTORY_LIMIT);
  assert.deepEqual(state, at(20), 'the first 20 edits are beyond the limit');
  for (let k = 0; k < HISTORY_LIMIT; k += 1) state = h.redo(state).state;
  assert.deepEqual(state, at(HISTORY_LIMIT + 20));
  assert.throws(() => new History(0));
});

test('keys: Ctrl+Z undoes, Ctrl+Shift+Z and Ctrl+Y redo, text fields keep their own', () => {
  assert.equal(historyKey({ key: 'z', ctrlKey: true }), 'undo');
  assert.equal(historyKey({ key: 'Z', ctrlKey: true, shiftKey: true }), 'redo');
  assert.equal(historyKey({ key: 'y', ctrlKey: true }), 'redo');
  assert.equal(historyKey({ key: 'z', metaKey: true }), 'undo');
  assert.equal(historyKey({ key: 'z' }), null);
  assert.equal(historyKey({ key: 'z', ctrlKey: true, altKey: true }), null);
  assert.equal(historyKey({ key: 'z', ctrlKey: true }, true), null);
  assert.equal(historyKey({ key: 'x', ctrlKey: true }), null);
});
