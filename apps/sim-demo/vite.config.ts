import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';

// The demo runs the workspace packages from source (the "@hal/source" export condition), so
// `pnpm start` works on a fresh clone with no build step. @hal/recorder's zstd (a Node-only
// WebAssembly build) is replaced by a browser reader of zstd: see src/recording/zstd-browser.ts.
export default defineConfig({
  resolve: {
    conditions: ['@hal/source'],
    alias: {
      '@foxglove/wasm-zstd': fileURLToPath(
        new URL('./src/recording/zstd-browser.ts', import.meta.url),
      ),
    },
  },
  server: { host: '127.0.0.1', port: 5173, strictPort: false },
  preview: { host: '127.0.0.1', port: 4173 },
  build: { target: 'es2022', chunkSizeWarningLimit: 1500 },
});
