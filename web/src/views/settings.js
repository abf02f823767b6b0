// Settings: the API token (needed when the service listens beyond loopback), kept in this browser.

import { token, setToken, api } from '../api.js';
import { h, fill, field, say, errorBox } from '../ui.js';

export async function renderSettings(main) {
  const input = h('input', { type: 'password', name: 'token', autocomplete: 'off', value: token() });
  const out = h('div');
  const form = h(
    'form',
    {
      class: 'card narrow',
      'aria-label': 'API token',
      onsubmit: async (e) => {
        e.preventDefault();
        setToken(input.value.trim());
        fill(out);
        try {
          await api('/api/models');
          say('Token saved; the service accepts it.', 'ok');
        } catch (err) {
          fill(out, errorBox(err, 'The service refused the token'));
        }
      },
    },
    field('API token', input, 'Create one on the server with: cad2mo token create. Stored in this browser only.'),
    h('div', { class: 'row' }, h('button', { type: 'submit' }, 'Save token'), h('button', { type: 'button', onclick: () => { input.value = ''; setToken(''); say('Token removed'); } }, 'Remove')),
    out,
  );
  fill(main, h('h1', {}, 'Settings'), form);
}
