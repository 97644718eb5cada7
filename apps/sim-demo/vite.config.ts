import { defineConfig } from 'vite';

// The demo runs the workspace packages from source (the "@hal/source" export condition), so
// `pnpm start` works on a fresh clone with no build step.
export default defineConfig({
  resolve: { conditions: ['@hal/source'] },
  server: { host: '127.0.0.1', port: 5173, strictPort: false },
  preview: { host: '127.0.0.1', port: 4173 },
  build: { target: 'es2022', chunkSizeWarningLimit: 1500 },
});
