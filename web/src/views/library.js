// Motor library: the library's classes (motor, gear, controller models) with their instances
// (concrete motors, gears and controller settings). Instances can be created, edited and
// deleted; every numeric value is checked against the class limits before anything is sent,
// and the server's own refusals are shown next to the fields they concern. The whole library
// can be exported to and imported from XML.
//
// One form is open at a time: an edit form inside its instance's card, or a "new instance" form
// under its class heading. Re-rendering the list (after a filter change, a save or a delete)
// puts the open form's element back in its slot, so typed values survive.

import './library.css';
import { api, download, enc } from '../api.js';
import { h, fill, say, errorBox, confirmAction, num, unitLabel, limits, checkValue, field, newId } from '../ui.js';
import { valueSource } from './sizing-data.js';

/** Domains listed first, in this order; any other domain follows alphabetically. */
const DOMAIN_ORDER = ['motor', 'gear', 'controller'];
/** Sources longer than this are shown shortened, with the full text one click away. */
const SOURCE_PREVIEW = 140;

/** The domain filter survives leaving and re-entering the screen (within this page load). */
let lastDomain = '';

export async function renderLibrary(main) {
  let alive = true;
  // The router only learns our cleanup once this function returns, so after every await we
  // also check that the library is still the screen being shown.
  const here = () => alive && /^#\/library\/?$/.test(location.hash);

  let classes = [];
  let instances = [];
  /** The open form: {key, form, isDirty(), title}; key = "edit:<instance id>" | "new:<class id>". */
  let open = null;
  let importing = false;
  let exporting = false;

  const heading = h('h1', {}, 'Motor library');
  fill(main, heading, h('p', { class: 'muted' }, 'Loading…'));
  try {
    [classes, instances] = await Promise.all([api('/api/library/classes'), api('/api/library/instances')]);
  } catch (err) {
    if (here()) {
      fill(
        main,
        heading,
        errorBox(err, 'Could not load the motor library'),
        h('button', { type: 'button', onclick: () => renderLibrary(main) }, 'Try again'),
      );
    }
    return () => (alive = false);
  }
  if (!here()) return () => (alive = false);

  // ---- Toolbar: export, import, domain filter.
  const exportButton = h('button', { type: 'button', id: 'library-export', onclick: exportXml }, 'Export XML');
  const importInput = h('input', {
    type: 'file',
    id: 'library-import',
    name: 'library-import',
    accept: '.xml,application/xml,text/xml',
    onchange: importFile,
  });
  const domainSelect = h('select', {
    id: 'library-domain',
    name: 'domain',
    onchange: () => {
      lastDomain = domainSelect.value;
      renderList();
    },
  });
  const toolbar = h(
    'div',
    { class: 'toolbar lib-toolbar', role: 'group', 'aria-label': 'Library actions' },
    exportButton,
    h('span', { class: 'lib-tool' }, h('label', { for: 'library-import' }, 'Import XML'), importInput),
    h('span', { class: 'lib-tool' }, h('label', { for: 'library-domain' }, 'Domain'), domainSelect),
  );
  const notice = h('div', { class: 'lib-notice' }); // page-level errors (import, export, reload)
  const summary = h('p', { class: 'muted lib-summary' });
  const listBox = h('div', { class: 'lib-list' });

  renderDomainOptions();
  renderList();
  fill(main, heading, toolbar, notice, summary, listBox);
  return () => (alive = false);

  // ---------------------------------------------------------------------------------------------
  // Rendering

  function renderDomainOptions() {
    const domains = [...new Set(classes.map((c) => c.domain))].sort(byDomain);
    if (!domains.includes(lastDomain)) lastDomain = '';
    fill(
      domainSelect,
      h('option', { value: '' }, 'All'),
      domains.map((d) => h('option', { value: d }, capitalize(d))),
    );
    domainSelect.value = lastDomain;
  }

  /** Rebuilds the class sections from `classes` and `instances`, keeping the open form. */
  function renderList() {
    const domain = domainSelect.value;
    const shown = [...classes]
      .sort((a, b) => byDomain(a.domain, b.domain) || a.name.localeCompare(b.name))
      .filter((c) => !domain || c.domain === domain);
    const byClass = new Map();
    for (const i of instances) {
      if (!byClass.has(i.class_id)) byClass.set(i.class_id, []);
      byClass.get(i.class_id).push(i);
    }
    const slots = new Map(); // form key -> the element an open form goes into
    const sections = shown.map((c) => classSection(c, byClass.get(c.id) || [], slots));
    const count = shown.reduce((n, c) => n + (byClass.get(c.id)?.length || 0), 0);
    summary.textContent = `${plural(count, 'instance')} in ${plural(shown.length, 'class', 'classes')}`;
    fill(listBox, sections.length ? sections : h('p', { class: 'muted' }, 'No classes in this domain.'));

    if (open) {
      const slot = slots.get(open.key);
      if (slot) slot.append(open.form);
      else {
        // Its class is filtered out (or its instance is gone): the form cannot stay.
        const title = open.title;
        closeForm({ focus: false });
        say(`Closed the form "${title}"`);
      }
    }
    syncExpanded();
  }

  function classSection(c, list, slots) {
    const headId = newId('lib-class');
    const newKey = `new:${c.id}`;
    const newSlot = h('div', { class: 'lib-form-slot' });
    slots.set(newKey, newSlot);
    list.sort((a, b) => a.name.localeCompare(b.name));
    return h(
      'section',
      { class: 'lib-class', 'aria-labelledby': headId, 'data-class-id': c.id },
      h(
        'div',
        { class: 'lib-class-head' },
        h(
          'div',
          { class: 'lib-class-title' },
          h('h2', { id: headId }, c.name),
          c.description ? h('p', { class: 'muted lib-small' }, c.description) : null,
          h('p', { class: 'muted lib-small' }, `${capitalize(c.domain)} · Modelica class `, h('code', { class: 'lib-path' }, c.modelica_class)),
        ),
        h(
          'button',
          {
            type: 'button',
            class: 'lib-new',
            'aria-label': `New ${c.name} instance`,
            'data-opens': newKey,
            onclick: () => openForm(c, null),
          },
          'New instance',
        ),
      ),
      newSlot,
      list.length
        ? h('ul', { class: 'lib-instances', role: 'list' }, list.map((i) => instanceCard(c, i, list, slots)))
        : h('p', { class: 'muted' }, 'No instances yet.'),
    );
  }

  function instanceCard(c, inst, siblings, slots) {
    const key = `edit:${inst.id}`;
    const slot = h('div', { class: 'lib-form-slot' });
    slots.set(key, slot);
    const msg = h('div', { class: 'lib-card-msg' }); // a refused delete shows up here
    return h(
      'li',
      { class: 'card lib-instance', 'data-instance-id': inst.id, 'data-instance-name': inst.name },
      h('h3', {}, inst.name),
      sourceView(inst.source),
      valuesView(c, inst),
      h(
        'div',
        { class: 'row' },
        h(
          'button',
          { type: 'button', 'aria-label': `Edit ${inst.name}`, 'data-opens': key, onclick: () => openForm(c, inst) },
          'Edit',
        ),
        h(
          'button',
          { type: 'button', class: 'danger', 'aria-label': `Delete ${inst.name}`, onclick: () => remove(c, inst, siblings, msg) },
          'Delete',
        ),
      ),
      msg,
      slot,
    );
  }

  /** Where the values come from: short ones in full, long ones shortened in a disclosure. */
  function sourceView(source) {
    const text = String(source || '').trim();
    if (!text) return h('p', { class: 'muted lib-small' }, 'No source given.');
    if (text.length <= SOURCE_PREVIEW) return h('p', { class: 'lib-source lib-small' }, h('span', { class: 'muted' }, 'Source: '), text);
    // Cut at a word boundary; the preview hides when the details are open (CSS).
    const preview = text.slice(0, SOURCE_PREVIEW).replace(/\s+\S*$/, '');
    return h(
      'details',
      { class: 'lib-source lib-small' },
      h('summary', { title: text }, h('span', { class: 'muted' }, 'Source: '), h('span', { class: 'lib-preview' }, `${preview}…`)),
      h('p', {}, text),
    );
  }

  /** The instance's values in class order; each value's text starts with the number. */
  function valuesView(c, inst) {
    const values = inst.values || {};
    const known = new Set(c.parameters.map((p) => p.name));
    // Values the class does not declare (should not happen) are still shown, not hidden.
    const extra = Object.keys(values)
      .filter((k) => !known.has(k))
      .map((name) => ({ name, type: typeof values[name] === 'number' ? 'Real' : 'String', unit: '', editable: true }));
    return h(
      'dl',
      { class: 'lib-values' },
      [...c.parameters, ...extra].map((p) => {
        const unit = unitLabel(p.unit);
        return h(
          'div',
          { class: p.editable ? 'lib-value' : 'lib-value nameplate', title: p.comment || null },
          h('dt', {}, p.name),
          h(
            'dd',
            { 'data-param': p.name },
            formatValue(p, values[p.name]),
            unit ? h('span', { class: 'muted' }, ` ${unit}`) : null,
            // Where this value comes from, as the instance's source says for it.
            values[p.name] !== undefined && valueSource(inst.source, p.name) ? h('small', { class: 'muted value-source' }, `source: ${valueSource(inst.source, p.name)}`) : null,
          ),
        );
      }),
    );
  }

  /** Marks the "New instance"/"Edit" button whose form is open (a disclosure). */
  function syncExpanded() {
    for (const b of listBox.querySelectorAll('button[data-opens]')) {
      const on = open?.key === b.dataset.opens;
      b.setAttribute('aria-expanded', String(on));
      if (on) b.setAttribute('aria-controls', open.form.id);
      else b.removeAttribute('aria-controls');
    }
  }

  /** Focuses the button that opens the form `key` (the list may have been rebuilt meanwhile). */
  function focusOpener(key) {
    const b = listBox.querySelector(`button[data-opens="${CSS.escape(key)}"]`);
    if (b) b.focus();
    return !!b;
  }

  // ---------------------------------------------------------------------------------------------
  // The instance form

  async function openForm(c, inst) {
    const key = inst ? `edit:${inst.id}` : `new:${c.id}`;
    if (open?.key === key) {
      focusFirst(open.form);
      return;
    }
    if (open?.isDirty()) {
      const discard = await confirmAction(`Discard your changes in "${open.title}"?`, 'Discard');
      if (!here()) return;
      if (!discard) {
        if (open) focusFirst(open.form);
        return;
      }
    }
    if (open) closeForm({ focus: false });
    const built = buildForm(c, inst, key);
    open = { key, ...built };
    renderList(); // puts the form into its slot and marks its opener
    focusFirst(built.form);
  }

  function closeForm({ focus = true } = {}) {
    if (!open) return;
    const { key, form } = open;
    open = null;
    form.remove();
    syncExpanded();
    if (focus) focusOpener(key);
  }

  function focusFirst(form) {
    form.querySelector('input:not([readonly]), textarea')?.focus();
  }

  /**
   * Builds the create/edit form. On create every parameter is an input (class defaults
   * prefilled); on edit nameplate values are shown read-only and sent back unchanged.
   */
  function buildForm(c, inst, key) {
    const creating = !inst;
    const title = creating ? `New ${c.name} instance` : `Edit ${inst.name}`;
    const out = h('div', { class: 'lib-form-errors' });
    /**
     * Every control with a message slot: {name (the server's field name), input, msg,
     * check() -> message|null}. check() also clears an earlier server message.
     */
    const controls = [];
    /** Parameter name -> () => the value to send. */
    const readers = new Map();

    const nameInput = h('input', { type: 'text', name: '__name', autocomplete: 'off', required: true, value: inst?.name ?? '' });
    const nameField = field('Name', nameInput);
    const nameMsg = nameField.querySelector('.field-msg');
    const checkName = () => showMsg(nameInput, nameMsg, nameInput.value.trim() ? null : 'Name needs a value');
    nameInput.addEventListener('input', checkName);
    controls.push({ name: 'name', input: nameInput, msg: nameMsg, check: checkName });

    const sourceInput = h('textarea', { name: '__source', rows: 3 });
    sourceInput.value = inst?.source ?? '';
    const sourceField = field('Source', sourceInput, 'Where the values come from: datasheet, catalog, measurement…');
    describeBy(sourceField, sourceInput);
    const sourceMsg = sourceField.querySelector('.field-msg');
    controls.push({ name: 'source', input: sourceInput, msg: sourceMsg, check: () => showMsg(sourceInput, sourceMsg, null) });

    const params = c.parameters.map((p) => paramField(p, creating ? undefined : inst.values?.[p.name], creating, controls, readers));

    const saveButton = h('button', { type: 'submit' }, 'Save');
    const form = h(
      'form',
      {
        class: 'instance-form card',
        id: newId('lib-form'),
        'aria-label': title,
        novalidate: true,
        onsubmit: submit,
        onkeydown: (e) => {
          if (e.key === 'Escape' && !e.defaultPrevented) {
            e.preventDefault();
            closeForm();
          }
        },
      },
      h(creating ? 'h3' : 'h4', { class: 'lib-form-title' }, title),
      out,
      nameField,
      sourceField,
      params.length
        ? h('fieldset', { class: 'lib-params' }, h('legend', {}, 'Parameters'), h('div', { class: 'params' }, params))
        : null,
      h(
        'div',
        { class: 'row' },
        saveButton,
        h('button', { type: 'button', class: 'lib-cancel', onclick: () => closeForm() }, 'Cancel'),
        h('small', { class: 'muted' }, 'Escape also cancels.'),
      ),
    );

    const snapshot = () => JSON.stringify([...form.elements].map((el) => (el.type === 'checkbox' ? el.checked : el.value)));
    const initial = snapshot();
    let saving = false;

    async function submit(e) {
      e.preventDefault();
      if (saving) return;
      fill(out);
      // Client-side checks first; nothing is sent while any field has a message.
      const problems = [];
      let firstBad = null;
      for (const ctl of controls) {
        const m = ctl.check();
        if (m) {
          problems.push(m);
          firstBad ??= ctl.input;
        }
      }
      if (problems.length) {
        fill(
          out,
          h(
            'div',
            { class: 'error', role: 'alert' },
            h('strong', {}, problems.length === 1 ? 'Not saved: one field needs a fix' : `Not saved: ${problems.length} fields need a fix`),
            h('ul', {}, problems.map((m) => h('li', {}, m))),
          ),
        );
        firstBad.focus();
        return;
      }

      const values = {};
      for (const [name, read] of readers) values[name] = read();
      const body = { name: nameInput.value.trim(), source: sourceInput.value.trim(), values };
      if (creating) body.class_id = c.id;

      saving = true;
      form.setAttribute('aria-busy', 'true');
      saveButton.setAttribute('aria-disabled', 'true'); // not `disabled`: that would drop focus
      try {
        const saved = creating
          ? await api('/api/library/instances', { method: 'POST', body })
          : await api(`/api/library/instances/${enc(inst.id)}`, { method: 'PUT', body });
        if (!here()) return;
        say(`Saved ${saved?.name || body.name}`, 'ok');
        if (open?.form === form) open = null;
        // The list shows the saved instance in the same step as the form closes (no moment
        // where the form is gone but the old values are still shown).
        if (saved?.id) {
          instances = [...instances.filter((i) => i.id !== saved.id), saved];
          renderList();
          form.remove();
        } else {
          await refresh();
          form.remove();
        }
        focusOpener(key);
      } catch (err) {
        if (!here()) return;
        showServerErrors(err);
      } finally {
        saving = false;
        form.removeAttribute('aria-busy');
        saveButton.removeAttribute('aria-disabled');
      }
    }

    /** A refusal: its field errors next to the fields, and all of it at the top of the form. */
    function showServerErrors(err) {
      fill(out, errorBox(err, 'Not saved'));
      let first = null;
      const byName = new Map(controls.map((ctl) => [ctl.name, ctl]));
      for (const fe of err.errors || []) {
        // "values.R" -> the R input; "name" and "source" -> Name and Source.
        const ctl = byName.get(fe.field);
        if (!ctl) continue;
        const prev = ctl.msg.textContent;
        showMsg(ctl.input, ctl.msg, prev && prev !== fe.message ? `${prev}; ${fe.message}` : fe.message);
        first ??= ctl.input;
      }
      // 409 on create/update means the class already has an instance with this name.
      if (err.status === 409 && !(err.errors || []).length) {
        showMsg(nameInput, nameMsg, err.detail || err.message);
        first ??= nameInput;
      }
      (first || saveButton).focus();
    }

    return { form, title, isDirty: () => snapshot() !== initial };
  }

  /**
   * One parameter's field. `value` is the instance's value (edit) or undefined (create: the
   * class default is used). Registers its validator in `controls` and its reader in `readers`.
   */
  function paramField(p, value, creating, controls, readers) {
    const unit = unitLabel(p.unit);
    const numeric = p.type === 'Real' || p.type === 'Integer';
    // A nameplate value cannot change after creation; a datasheet value the instance lacks may
    // still be added (datasheet values are optional: left empty, none is sent).
    const absent = value === null || value === undefined;
    const fixed = !creating && !p.editable && !(p.datasheet && absent);
    const start = creating ? p.default : value;
    const lim = limits(p);
    const hint = [
      p.comment,
      numeric ? `limits ${lim}${unit && lim !== 'any' ? ` ${unit}` : ''}` : null,
      p.editable ? 'editable' : fixed ? 'nameplate value, fixed for this instance' : 'nameplate value (fixed once created)',
      p.datasheet ? 'datasheet value for the drive sizing, optional, not a Modelica parameter' : null,
    ]
      .filter(Boolean)
      .join(' · ');
    const cls = `lib-param ${p.editable ? 'editable' : 'nameplate'}`;

    if (fixed) {
      // Shown read-only (still focusable and readable); the stored value goes back unchanged.
      const input = h('input', { type: 'text', name: p.name, readonly: true, class: 'lib-readonly', value: displayRaw(p, value) });
      readers.set(p.name, () => value);
      const f = withUnit(field(p.name, input, hint), input, unit);
      f.classList.add(...cls.split(' '));
      const msg = f.querySelector('.field-msg');
      controls.push({ name: `values.${p.name}`, input, msg, check: () => showMsg(input, msg, null) });
      return f;
    }

    if (p.type === 'Boolean') {
      const input = h('input', { type: 'checkbox', name: p.name, id: newId(), checked: start === true || start === 'true' });
      readers.set(p.name, () => input.checked);
      const msg = h('div', { class: 'field-msg', id: `${input.id}-msg`, 'aria-live': 'polite' });
      const hintEl = h('small', { id: `${input.id}-hint` }, hint);
      input.setAttribute('aria-describedby', `${hintEl.id} ${msg.id}`);
      controls.push({ name: `values.${p.name}`, input, msg, check: () => showMsg(input, msg, null) });
      return h('div', { class: `field ${cls}` }, h('label', { class: 'check', for: input.id }, input, p.name), hintEl, msg);
    }

    const input = h('input', {
      type: 'text',
      name: p.name,
      autocomplete: 'off',
      spellcheck: 'false',
      inputmode: numeric ? 'decimal' : null,
      value: start === null || start === undefined ? '' : String(start),
    });
    const f = withUnit(field(p.name, input, hint), input, unit);
    f.classList.add(...cls.split(' '));
    const msg = f.querySelector('.field-msg');
    if (numeric) {
      const empty = () => p.datasheet && input.value.trim() === '';
      const check = () => showMsg(input, msg, empty() ? null : checkValue(p, input.value));
      input.addEventListener('input', check);
      controls.push({ name: `values.${p.name}`, input, msg, check });
      readers.set(p.name, () => (empty() ? undefined : Number(input.value.trim())));
    } else {
      // Strings: anything goes here; a server message is cleared once the text changes.
      const clear = () => showMsg(input, msg, null);
      input.addEventListener('input', clear);
      controls.push({ name: `values.${p.name}`, input, msg, check: clear });
      readers.set(p.name, () => input.value);
    }
    return f;
  }

  // ---------------------------------------------------------------------------------------------
  // Actions

  async function remove(c, inst, siblings, msgBox) {
    fill(msgBox);
    if (!(await confirmAction(`Delete instance "${inst.name}"?`))) return;
    try {
      await api(`/api/library/instances/${enc(inst.id)}`, { method: 'DELETE' });
    } catch (err) {
      if (!here()) return;
      // 409 while a drive uses it: the server says which one.
      fill(msgBox, errorBox(err, `"${inst.name}" was not deleted`));
      say(`"${inst.name}" was not deleted: ${err.message}`, 'error');
      return;
    }
    if (!here()) return;
    if (open?.key === `edit:${inst.id}`) closeForm({ focus: false });
    say(`Deleted ${inst.name}`, 'ok');
    // Focus moves to the next instance of the class (or the previous, or "New instance").
    const at = siblings.indexOf(inst);
    const next = siblings[at + 1] || siblings[at - 1];
    await refresh();
    if (!(next && focusOpener(`edit:${next.id}`))) focusOpener(`new:${c.id}`);
  }

  async function importFile() {
    const file = importInput.files?.[0];
    if (!file || importing) return;
    importing = true;
    toolbar.setAttribute('aria-busy', 'true');
    fill(notice);
    say(`Importing ${file.name}…`);
    try {
      const text = await file.text();
      const counts = await api('/api/library/import', { method: 'POST', body: text });
      if (!here()) return;
      // An open form shows values from before the import: drop it.
      if (open) closeForm({ focus: false });
      await refresh({ withClasses: true });
      say(`Library imported: ${describeCounts(counts)}`, 'ok');
    } catch (err) {
      if (!here()) return;
      fill(notice, errorBox(err, `${file.name} was not imported`));
      say(`${file.name} was not imported`, 'error');
    } finally {
      importing = false;
      toolbar.removeAttribute('aria-busy');
      importInput.value = ''; // choosing the same file again imports it again
    }
  }

  async function exportXml() {
    if (exporting) return;
    exporting = true;
    exportButton.setAttribute('aria-busy', 'true');
    fill(notice);
    try {
      await download('/api/library/export', 'motor-library.xml');
      say('Library exported', 'ok');
    } catch (err) {
      if (!here()) return;
      fill(notice, errorBox(err, 'The library could not be exported'));
      say('The library could not be exported', 'error');
    } finally {
      exporting = false;
      exportButton.removeAttribute('aria-busy');
    }
  }

  /** Reloads the instances (and the classes when asked) and re-renders. */
  async function refresh({ withClasses = false } = {}) {
    try {
      const [cls, inst] = await Promise.all([
        withClasses ? api('/api/library/classes') : classes,
        api('/api/library/instances'),
      ]);
      if (!here()) return;
      classes = cls;
      instances = inst;
      if (withClasses) renderDomainOptions();
      renderList();
    } catch (err) {
      if (here()) fill(notice, errorBox(err, 'Could not reload the library'));
    }
  }
}

// -----------------------------------------------------------------------------------------------
// Helpers

/** Shows (or clears) a field's message and marks the control invalid; returns the message. */
function showMsg(input, msgEl, message) {
  msgEl.textContent = message || '';
  if (message) input.setAttribute('aria-invalid', 'true');
  else input.removeAttribute('aria-invalid');
  return message || null;
}

/** Gives a field's hint an id and adds it to the control's description. */
function describeBy(fieldEl, input) {
  const hint = fieldEl.querySelector('small');
  const ids = [];
  if (hint) {
    hint.id = `${input.id}-hint`;
    ids.push(hint.id);
  }
  ids.push(`${input.id}-msg`);
  input.setAttribute('aria-describedby', ids.join(' '));
}

/** Puts the unit next to the input (and into its description). */
function withUnit(fieldEl, input, unit) {
  describeBy(fieldEl, input);
  if (!unit) return fieldEl;
  const u = h('span', { class: 'lib-unit', id: `${input.id}-unit` }, unit);
  const wrap = h('div', { class: 'lib-with-unit' });
  input.replaceWith(wrap);
  wrap.append(input, u);
  input.setAttribute('aria-describedby', `${u.id} ${input.getAttribute('aria-describedby')}`);
  return fieldEl;
}

/** A stored value for reading (list): numbers formatted, booleans as yes/no. */
function formatValue(p, v) {
  if (v && typeof v === 'object' && 'value' in v) v = v.value; // {value, unit} form, just in case
  if (v === null || v === undefined || v === '') return '—';
  if (typeof v === 'number') return num(v);
  if (typeof v === 'boolean') return v ? 'yes' : 'no';
  return String(v);
}

/** A stored value for a read-only input: exact, not rounded. */
function displayRaw(p, v) {
  if (v && typeof v === 'object' && 'value' in v) v = v.value;
  if (v === null || v === undefined) return '';
  if (typeof v === 'boolean') return v ? 'yes' : 'no';
  return String(v);
}

/** The import result, e.g. {classes_created: 0, ...} -> "classes created 0, ...". */
function describeCounts(counts) {
  if (!counts || typeof counts !== 'object') return String(counts ?? 'done');
  const parts = Object.entries(counts).map(([k, v]) => `${k.replace(/_/g, ' ')} ${v}`);
  return parts.length ? parts.join(', ') : 'nothing to do';
}

function byDomain(a, b) {
  const rank = (d) => {
    const i = DOMAIN_ORDER.indexOf(d);
    return i < 0 ? DOMAIN_ORDER.length : i;
  };
  return rank(a) - rank(b) || String(a).localeCompare(String(b));
}

function capitalize(s) {
  const t = String(s || '');
  return t ? t[0].toUpperCase() + t.slice(1) : t;
}

function plural(n, one, many = `${one}s`) {
  return `${n} ${n === 1 ? one : many}`;
}
