// Global setup of the publish project: a temporary folder for the run, where the test files that
// need the packed tarballs and the app with every tarball find them, made once (shared.ts), and
// which is removed when the run ends.
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
  const work = mkdtempSync(join(tmpdir(), 'hal-published-'));
  project.provide('publishWork', work);
  return () => rmSync(work, { recursive: true, force: true });
}
