// Global setup of the tests project: an empty temporary folder for the run, where the test files
// that need the packed tarballs and the app with every tarball make them, once for all of them
// (shared.ts); removed when the run ends. A rerun in watch mode gets a fresh folder, so it packs
// the sources as they are then.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import type { TestProject } from 'vitest/node';

declare module 'vitest' {
  export interface ProvidedContext {
    /** The folder the publish tests share for the run. */
    publishWork: string;
  }
}

export default function publishWork(project: TestProject): () => void {
  const folders: string[] = [];
  const fresh = () => {
    const work = mkdtempSync(join(tmpdir(), 'hal-published-'));
    folders.push(work);
    project.provide('publishWork', work);
  };
  fresh();
  project.onTestsRerun(fresh);
  return () => {
    for (const work of folders) rmSync(work, { recursive: true, force: true });
  };
}
