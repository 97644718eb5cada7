// Global setup of the e2e project: the browser demo built and served once (demo-server.ts), for
// every browser test of the run. Each test opens its own Chromium profile on it
// (demo-browser.ts), so the tests share the build and the server but nothing a page can change.
import type { TestProject } from 'vitest/node';
import { serveBuiltDemo } from './demo-server.js';

declare module 'vitest' {
  export interface ProvidedContext {
    /** The served demo's URL, e.g. `http://127.0.0.1:4173/`. */
    demoUrl: string;
  }
}

export default async function serveDemo(project: TestProject): Promise<() => Promise<void>> {
  const demo = await serveBuiltDemo();
  project.provide('demoUrl', demo.url);
  return demo.close;
}
