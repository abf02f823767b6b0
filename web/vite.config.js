// Production builds are made by server/build.rs (into the cargo OUT_DIR, embedded in the binary).
// `npm run dev` serves the UI with hot reload and forwards the API to a running `cad2mo serve`.
import { defineConfig } from 'vite';

const api = process.env.CAD2MO_URL || 'http://127.0.0.1:8080';

export default defineConfig({
  base: '/',
  build: { target: 'es2022', chunkSizeWarningLimit: 1024, sourcemap: false },
  // The service answers only to its own host and origin (see README, Security): the proxy
  // rewrites both to the service's.
  server: {
    proxy: Object.fromEntries(
      ['/api', '/openapi.yaml'].map((p) => [
        p,
        { target: api, changeOrigin: true, configure: (proxy) => proxy.on('proxyReq', (req) => req.getHeader('origin') && req.setHeader('origin', new URL(api).origin)) },
      ]),
    ),
  },
});
