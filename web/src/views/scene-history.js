// Undo/redo of the Scene tab (issue 29), the pure part: a bounded history of snapshots of the
// scene's objects. Every edit records the state before it (add, delete, duplicate, a typed pose,
// a gizmo drag, a snap, visibility); undo returns that state and keeps the current one for redo;
// a new edit after an undo drops what could have been redone. Snapshots are deep copies, so later
// edits of the live objects never change a recorded state.

/** How many edits can be undone (the issue asks for at least 50). */
export const HISTORY_LIMIT = 100;

const copy = (state) => structuredClone(state);

export class History {
  /** @param {number} limit  most edits kept; the oldest are forgotten first */
  constructor(limit = HISTORY_LIMIT) {
    if (!(limit >= 1)) throw new Error(`a history keeps at least one edit, not ${limit}`);
    this.limit = limit;
    this.past = [];
    this.future = [];
  }

  /** Records an edit: `before` is the state before it, `label` says what it did ("move box1"). */
  record(before, label) {
    this.past.push({ state: copy(before), label });
    if (this.past.length > this.limit) this.past.shift();
    this.future = [];
  }

  get canUndo() {
    return this.past.length > 0;
  }

  get canRedo() {
    return this.future.length > 0;
  }

  /** The label of the edit undo would take back (null when none). */
  get undoLabel() {
    return this.past.at(-1)?.label ?? null;
  }

  get redoLabel() {
    return this.future.at(-1)?.label ?? null;
  }

  /** Takes back the last edit: its state before, or null; `current` is kept for redo. */
  undo(current) {
    const e = this.past.pop();
    if (!e) return null;
    this.future.push({ state: copy(current), label: e.label });
    return { state: copy(e.state), label: e.label };
  }

  /** Does again the last undone edit: the state after it, or null; `current` is kept for undo. */
  redo(current) {
    const e = this.future.pop();
    if (!e) return null;
    this.past.push({ state: copy(current), label: e.label });
    return { state: copy(e.state), label: e.label };
  }

  clear() {
    this.past = [];
    this.future = [];
  }
}

/**
 * What a key press asks of the history: 'undo' (Ctrl+Z, ⌘Z), 'redo' (Ctrl+Shift+Z, Ctrl+Y,
 * ⌘⇧Z) or null. Presses in text fields are left to the field's own undo.
 * @param {{key: string, ctrlKey?: boolean, metaKey?: boolean, shiftKey?: boolean, altKey?: boolean}} e
 * @param {boolean} inTextField
 */
export function historyKey(e, inTextField = false) {
  if (inTextField || e.altKey || !(e.ctrlKey || e.metaKey)) return null;
  const k = e.key.toLowerCase();
  if (k === 'z') return e.shiftKey ? 'redo' : 'undo';
  if (k === 'y' && !e.shiftKey) return 'redo';
  return null;
}
