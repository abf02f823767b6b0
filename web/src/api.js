// The API client: the UI's only data source. Errors become ApiError with the problem document's
// title, detail and field errors, so every screen can show the server's own message.

const TOKEN_KEY = 'cad2mo.token';

export function token() {
  return localStorage.getItem(TOKEN_KEY) || '';
}

export function setToken(t) {
  if (t) localStorage.setItem(TOKEN_KEY, t);
  else localStorage.removeItem(TOKEN_KEY);
}

export class ApiError extends Error {
  constructor(status, problem) {
    const p = problem || {};
    super(p.detail || p.title || `HTTP ${status}`);
    this.status = status;
    this.title = p.title || `HTTP ${status}`;
    this.detail = p.detail || '';
    this.errors = p.errors || [];
    this.diagnostics = p.diagnostics || [];
  }

  /** Every line a user should see: the detail, then field errors and file positions not in it. */
  lines() {
    const head = this.detail || this.title;
    const out = [head];
    for (const e of this.errors) if (!head.includes(e.message)) out.push(`${e.field}: ${e.message}`);
    for (const d of this.diagnostics) {
      const at = [d.file, d.line, d.column].filter((x) => x !== undefined && x !== null).join(':');
      const line = at ? `${at}: ${d.message}` : d.message;
      if (!head.includes(line)) out.push(line);
    }
    if (this.status === 401) out.push('This service needs an API token: set one under Settings.');
    return out;
  }
}

// Sent with every request: without a token the service refuses requests that change data unless
// they carry it (a cross-site page cannot send it without a CORS preflight the service never grants).
const CLIENT_HEADER = { 'X-Requested-With': 'cad2mo' };

function headers(extra = {}) {
  const h = { Accept: 'application/json', ...CLIENT_HEADER, ...extra };
  const t = token();
  if (t) h.Authorization = `Bearer ${t}`;
  return h;
}

async function failure(resp) {
  let problem = null;
  try {
    problem = await resp.json();
  } catch {
    /* not JSON */
  }
  return new ApiError(resp.status, problem);
}

/** JSON request. `body` is sent as JSON unless it is FormData or a string. */
export async function api(path, { method = 'GET', body, accept } = {}) {
  const init = { method, headers: headers(accept ? { Accept: accept } : {}) };
  if (body instanceof ArrayBuffer || ArrayBuffer.isView(body) || (typeof Blob !== 'undefined' && body instanceof Blob)) {
    // A file as it is (e.g. a scene mesh).
    init.body = body;
    init.headers['Content-Type'] = 'application/octet-stream';
  } else if (body instanceof FormData || typeof body === 'string') {
    init.body = body;
    if (typeof body === 'string') init.headers['Content-Type'] = 'application/xml';
  } else if (body !== undefined) {
    init.body = JSON.stringify(body);
    init.headers['Content-Type'] = 'application/json';
  }
  let resp;
  try {
    resp = await fetch(path, init);
  } catch (e) {
    throw new ApiError(0, { title: 'Network error', detail: `cannot reach the service (${e.message})` });
  }
  if (!resp.ok) throw await failure(resp);
  if (resp.status === 204) return null;
  const type = resp.headers.get('Content-Type') || '';
  if (type.includes('json')) return resp.json();
  if (type.includes('zip') || type.includes('octet-stream') || type.includes('stl')) return resp.arrayBuffer();
  return resp.text();
}

/** Multipart upload with progress (fetch cannot report upload progress; XHR can). */
export function upload(path, form, onProgress) {
  return new Promise((resolve, reject) => {
    const xhr = new XMLHttpRequest();
    xhr.open('POST', path);
    for (const [k, v] of Object.entries(headers())) xhr.setRequestHeader(k, v);
    xhr.upload.onprogress = (e) => {
      if (e.lengthComputable) onProgress(e.loaded / e.total);
    };
    xhr.onload = () => {
      let body = null;
      try {
        body = JSON.parse(xhr.responseText);
      } catch {
        /* not JSON */
      }
      if (xhr.status >= 200 && xhr.status < 300) resolve(body);
      else reject(new ApiError(xhr.status, body));
    };
    xhr.onerror = () => reject(new ApiError(0, { title: 'Network error', detail: 'the upload did not reach the service' }));
    xhr.send(form);
  });
}

/** Polls a job until it finishes; `onUpdate` sees every state. Resolves with the final job. */
export async function waitForJob(jobId, onUpdate, { interval = 250, signal } = {}) {
  for (;;) {
    const job = await api(`/api/jobs/${encodeURIComponent(jobId)}`);
    onUpdate?.(job);
    if (job.status === 'succeeded' || job.status === 'failed') return job;
    if (signal?.aborted) return job;
    await new Promise((r) => setTimeout(r, interval));
  }
}

/** A job's state in words: its place in the queue, or its stage and how far it is. */
export function describeJob(job) {
  if (job.status === 'queued' && job.queue) {
    const { ahead, running } = job.queue;
    const busy = running ? `, ${running} converting now` : '';
    return ahead ? `queued behind ${ahead} ${ahead === 1 ? 'job' : 'jobs'}${busy}` : `queued, next in line${busy}`;
  }
  if (job.status === 'running' && job.progress) {
    const p = job.progress;
    const count = p.total > 1 ? ` ${Math.min(p.done + 1, p.total)} of ${p.total}` : '';
    return `${p.label}${count} · ${Math.round(p.fraction * 100)} %`;
  }
  return job.status;
}

/** Downloads a URL with the auth header and hands it to the browser as a file. */
export async function download(path, fallbackName) {
  const resp = await fetch(path, { headers: headers() });
  if (!resp.ok) throw await failure(resp);
  const blob = await resp.blob();
  const cd = resp.headers.get('Content-Disposition') || '';
  const m = /filename="?([^";]+)"?/.exec(cd);
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = m ? m[1] : fallbackName;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 10_000);
}

export const enc = encodeURIComponent;
