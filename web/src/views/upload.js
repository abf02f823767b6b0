// The bundle drop zone: drag and drop or choose a file, upload with a progress bar, then follow
// the conversion job until it finishes. Used for new models and for new versions of a model.

import { upload, waitForJob, describeJob, ApiError } from '../api.js';
import { h, fill, errorBox, bytes, newId } from '../ui.js';

/**
 * @param {object} o
 * @param {string} o.url         POST target (multipart, part `bundle`)
 * @param {string} o.label       what the zone says
 * @param {boolean} [o.askName]  whether to offer a model name field
 * @param {(created) => void} [o.onAccepted]  called when the service took the bundle (202)
 * @param {(created, job) => void} o.onDone  called after the job finished (either way)
 */
export function uploadZone({ url, label, askName = false, onAccepted, onDone }) {
  const inputId = newId('bundle');
  const input = h('input', { type: 'file', id: inputId, accept: '.zip,application/zip', class: 'visually-hidden' });
  const name = askName ? h('input', { type: 'text', id: newId('name'), placeholder: 'from the bundle' }) : null;
  const bar = h('progress', { max: 1, value: 0, id: newId('upload'), class: 'upload-progress' });
  const jobBar = h('progress', { max: 1, id: newId('job'), class: 'job-progress' });
  const bars = h(
    'div',
    { class: 'bars', hidden: true },
    h('label', { for: bar.id }, 'Upload'),
    bar,
    h('label', { for: jobBar.id }, 'Conversion'),
    jobBar,
  );
  const state = h('p', { class: 'upload-state', 'aria-live': 'polite' });
  const out = h('div');
  const zone = h(
    'label',
    { for: inputId, class: 'dropzone', tabindex: '-1' },
    h('span', { class: 'dropzone-main' }, label),
    h('span', { class: 'muted' }, 'Drop a .zip here, or press to choose one: a SimMechanics XML with its STL or VRML files, a Simscape Multibody XML, or a URDF with its meshes.'),
  );
  let busy = false;

  async function send(file) {
    if (busy || !file) return;
    busy = true;
    fill(out);
    zone.classList.add('busy');
    const form = new FormData();
    form.append('bundle', file, file.name);
    if (name?.value.trim()) form.append('name', name.value.trim());
    bars.hidden = false;
    bar.value = 0;
    jobBar.value = 0;
    state.textContent = `Uploading ${file.name} (${bytes(file.size)})…`;
    try {
      const created = await upload(url, form, (f) => {
        bar.value = f;
        state.textContent = `Uploading ${file.name}: ${Math.round(f * 100)} %`;
      });
      bar.value = 1;
      onAccepted?.(created);
      jobBar.removeAttribute('value'); // indeterminate until the job reports a stage
      const started = performance.now();
      const job = await waitForJob(created.job_id, (j) => {
        const s = ((performance.now() - started) / 1000).toFixed(1);
        state.textContent = `Version ${created.version}: ${describeJob(j)} (${s} s)`;
        if (j.progress) jobBar.value = j.progress.fraction;
      });
      jobBar.value = 1;
      if (job.status === 'failed') {
        state.textContent = `Version ${created.version}: conversion failed`;
        fill(out, errorBox(new ApiError(job.error?.status || 422, job.error || { detail: 'the conversion failed' }), 'Conversion failed'));
      } else {
        state.textContent = `Version ${created.version} converted.`;
      }
      onDone?.(created, job);
    } catch (e) {
      state.textContent = 'Upload refused.';
      fill(out, errorBox(e, 'The bundle was not accepted'));
    } finally {
      busy = false;
      zone.classList.remove('busy');
      input.value = '';
    }
  }

  input.addEventListener('change', () => send(input.files[0]));
  zone.addEventListener('dragover', (e) => {
    e.preventDefault();
    zone.classList.add('over');
  });
  zone.addEventListener('dragleave', () => zone.classList.remove('over'));
  zone.addEventListener('drop', (e) => {
    e.preventDefault();
    zone.classList.remove('over');
    send(e.dataTransfer?.files?.[0]);
  });
  // The visually hidden input keeps the keyboard focus; show it on the zone.
  input.addEventListener('focus', () => zone.classList.add('focus'));
  input.addEventListener('blur', () => zone.classList.remove('focus'));

  return h(
    'section',
    { class: 'card upload', 'aria-label': label },
    name ? h('div', { class: 'field' }, h('label', { for: name.id }, 'Model name (optional)'), name) : null,
    input,
    zone,
    bars,
    state,
    out,
  );
}
