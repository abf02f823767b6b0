// Small DOM helpers shared by the screens: an element builder, the status line, error boxes,
// confirmation dialogs, tabs with arrow-key navigation and number formatting.

import { ApiError } from './api.js';

/** h('button', {class: 'x', onclick}, 'text', child...) */
export function h(tag, attrs = {}, ...children) {
  const el = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (v === undefined || v === null || v === false) continue;
    if (k.startsWith('on') && typeof v === 'function') el.addEventListener(k.slice(2), v);
    else if (k === 'class') el.className = v;
    else if (k === 'dataset') Object.assign(el.dataset, v);
    else if (k in el && typeof v !== 'string') el[k] = v;
    else el.setAttribute(k, v === true ? '' : String(v));
  }
  append(el, children);
  return el;
}

function append(el, children) {
  for (const c of children.flat(Infinity)) {
    if (c === null || c === undefined || c === false) continue;
    el.append(c instanceof Node ? c : document.createTextNode(String(c)));
  }
}

/** Replaces an element's children. */
export function fill(el, ...children) {
  el.replaceChildren();
  append(el, children);
  return el;
}

let statusTimer = null;
/** The polite live region under the header. */
export function say(message, kind = 'info') {
  const el = document.getElementById('status');
  if (!el) return;
  el.textContent = message;
  el.dataset.kind = kind;
  clearTimeout(statusTimer);
  if (kind !== 'error') statusTimer = setTimeout(() => (el.textContent = ''), 6000);
}

/** Clears a lasting (error) message of the status line: it belongs to the page that said it. */
export function clearStaleStatus() {
  const el = document.getElementById('status');
  if (el && el.dataset.kind === 'error') {
    el.textContent = '';
    delete el.dataset.kind;
  }
}

/** A visible, announced error box for `err` (an ApiError or any Error). */
export function errorBox(err, title) {
  const lines = err instanceof ApiError ? err.lines() : [err?.message || String(err)];
  return h(
    'div',
    { class: 'error', role: 'alert' },
    h('strong', {}, title || (err instanceof ApiError ? err.title : 'Error')),
    lines.length === 1 ? h('p', {}, lines[0]) : h('ul', {}, lines.map((l) => h('li', {}, l))),
  );
}

/** Asks before a destructive action, in a modal dialog (Escape cancels). */
export function confirmAction(question, action = 'Delete') {
  return new Promise((resolve) => {
    const dlg = h(
      'dialog',
      { class: 'confirm', 'aria-label': question },
      h('p', {}, question),
      h(
        'form',
        { method: 'dialog', class: 'row' },
        h('button', { value: 'cancel', autofocus: true }, 'Cancel'),
        h('button', { value: 'ok', class: 'danger' }, action),
      ),
    );
    dlg.addEventListener('close', () => {
      resolve(dlg.returnValue === 'ok');
      dlg.remove();
    });
    document.body.append(dlg);
    dlg.showModal();
  });
}

/** An accessible tab bar; `tabs` = [{id, label, render(panel)}]. Returns {el, select(id)}. */
export function tabs(tabsSpec, { initial, onChange, label = 'Sections' } = {}) {
  const list = h('div', { role: 'tablist', 'aria-label': label, class: 'tabs' });
  const panels = h('div', { class: 'tabpanels' });
  const buttons = new Map();
  const panelEls = new Map();
  let current = null;
  const select = (id, focus = false) => {
    current = id;
    for (const t of tabsSpec) {
      const on = t.id === id;
      const b = buttons.get(t.id);
      b.setAttribute('aria-selected', String(on));
      b.tabIndex = on ? 0 : -1;
      panelEls.get(t.id).hidden = !on;
      if (on && focus) b.focus();
    }
    const spec = tabsSpec.find((t) => t.id === id);
    if (spec && !panelEls.get(id).dataset.rendered) {
      panelEls.get(id).dataset.rendered = '1';
      spec.render(panelEls.get(id));
    }
    onChange?.(id);
  };
  for (const t of tabsSpec) {
    const b = h('button', { role: 'tab', id: `tab-${t.id}`, 'aria-controls': `panel-${t.id}`, type: 'button', onclick: () => select(t.id) }, t.label);
    b.addEventListener('keydown', (e) => {
      const i = tabsSpec.findIndex((x) => x.id === current);
      const n = tabsSpec.length;
      const go = { ArrowRight: (i + 1) % n, ArrowLeft: (i - 1 + n) % n, Home: 0, End: n - 1 }[e.key];
      if (go !== undefined) {
        e.preventDefault();
        select(tabsSpec[go].id, true);
      }
    });
    buttons.set(t.id, b);
    list.append(b);
    const p = h('div', { role: 'tabpanel', id: `panel-${t.id}`, 'aria-labelledby': `tab-${t.id}`, tabindex: '0', hidden: true });
    panelEls.set(t.id, p);
    panels.append(p);
  }
  select(initial || tabsSpec[0].id);
  return { el: h('div', { class: 'tabbed' }, list, panels), select, panel: (id) => panelEls.get(id) };
}

/** A number for people: up to 6 significant digits, no float noise. */
export function num(x) {
  if (x === null || x === undefined || Number.isNaN(x)) return '—';
  if (x === 0) return '0';
  const a = Math.abs(x);
  if (a >= 1e6 || a < 1e-4) return x.toExponential(4).replace(/\.?0+e/, 'e');
  return String(Number(x.toPrecision(6)));
}

export function when(iso) {
  if (!iso) return '';
  const d = new Date(iso);
  return Number.isNaN(d.getTime()) ? iso : d.toLocaleString();
}

export function bytes(n) {
  if (n < 1024) return `${n} B`;
  if (n < 1024 * 1024) return `${(n / 1024).toFixed(1)} KiB`;
  return `${(n / 1024 / 1024).toFixed(1)} MiB`;
}

/** The unit as shown next to a value ('1' means dimensionless and is not shown). */
export function unitLabel(u) {
  return !u || u === '1' ? '' : u;
}

/** The limits of a parameter as text, e.g. "0 … 1" or "≥ 0". */
export function limits(p) {
  const lo = p.min ?? null;
  const hi = p.max ?? null;
  if (lo !== null && hi !== null) return `${num(lo)} … ${num(hi)}`;
  if (lo !== null) return `≥ ${num(lo)}`;
  if (hi !== null) return `≤ ${num(hi)}`;
  return 'any';
}

/** Checks a typed value against a class parameter; returns an error message or null. */
export function checkValue(p, raw) {
  const text = String(raw ?? '').trim();
  const unit = unitLabel(p.unit);
  const name = p.label || p.name;
  if (text === '') return `${name} needs a value`;
  const x = Number(text);
  if (!Number.isFinite(x)) return `${name}: "${text}" is not a number`;
  if (p.type === 'Integer' && !Number.isInteger(x)) return `${name} must be a whole number`;
  if (p.min !== null && p.min !== undefined && x < p.min)
    return `${name} = ${num(x)}${unit ? ' ' + unit : ''} is below the minimum ${num(p.min)}${unit ? ' ' + unit : ''}`;
  if (p.max !== null && p.max !== undefined && x > p.max)
    return `${name} = ${num(x)}${unit ? ' ' + unit : ''} is above the maximum ${num(p.max)}${unit ? ' ' + unit : ''}`;
  return null;
}

let uid = 0;
/** A fresh element id for label/for pairs. */
export function newId(prefix = 'f') {
  uid += 1;
  return `${prefix}-${uid}`;
}

/** A labelled field: <label for>…</label> + control + optional hint and message slot. */
export function field(label, control, hint) {
  if (!control.id) control.id = newId();
  const msg = h('div', { class: 'field-msg', id: `${control.id}-msg`, 'aria-live': 'polite' });
  control.setAttribute('aria-describedby', `${control.id}-msg`);
  return h('div', { class: 'field' }, h('label', { for: control.id }, label), control, hint ? h('small', {}, hint) : null, msg);
}

/** `3 bodies`, `1 joint`: a count with its noun. */
export const plural = (n, one, many = `${one}s`) => `${n} ${n === 1 ? one : many}`;
