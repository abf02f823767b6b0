// Production builds are made by server/build.rs (into the cargo OUT_DIR, embedded in the binary).
// `npm run dev` serves the UI with hot reload and forwards the API to a running `cad2mo serve`.
import { defineConfig } from 'vite';

const api = process.env.CAD2MO_URL || 'http://127.0.0.1:8080';

export default defineConfig({
  base: '/',
  build: { target: 'es2022', chunkSizeWarningLimit: 1024, sourcemap: false },
  server: { proxy: { '/api': api, '/openapi.yaml': api } },
});
