// What the publish tests share in a run, each made once (run-once.ts) in the run's folder
// (published.global.ts): the tarballs of every package, packed from its dist/, and one app with
// every tarball installed as docs/cli.md tells a user to (given together, no overrides), with
// what a user's app adds beside them: three for the scene binding, TypeScript and the types the
// strict compile needs.
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { inject } from 'vitest';
import { runOnce } from './run-once.js';
import { installApp, workspaceVersion } from './temp-app.js';
import type { PackedPackage } from './workspace-packages.js';
import { build, packAll, staleBuilds, workspacePackages } from './workspace-packages.js';

/** The run's shared folder. */
export function publishWork(): string {
  return inject('publishWork');
}

/**
 * Every public package under packages/, packed. `pnpm test` builds every package before vitest
 * runs; a stale or missing dist (a lone run of a file) is rebuilt first.
 */
export function packedOnce(repoRoot: string): Promise<PackedPackage[]> {
  const work = publishWork();
  return runOnce(work, 'tarballs', async () => {
    // A package marked private is not published (none is today).
    const sources = workspacePackages(repoRoot).filter((p) => p.manifest.private !== true);
    await build(repoRoot, staleBuilds(sources));
    return packAll(repoRoot, join(work, 'tarballs'));
  });
}

/** The folder of the app with every tarball, installed once for the run. */
export function everythingAppOnce(
  repoRoot: string,
  packed: readonly PackedPackage[],
): Promise<string> {
  const work = publishWork();
  return runOnce(work, 'everything-app', async () => {
    const appDir = join(work, 'everything-app');
    mkdirSync(appDir);
    await installApp(
      appDir,
      packed,
      {
        three: workspaceVersion(repoRoot, 'three', 'packages/simulation'),
        '@types/three': workspaceVersion(repoRoot, '@types/three', 'packages/simulation'),
        '@types/node': workspaceVersion(repoRoot, '@types/node'),
        typescript: workspaceVersion(repoRoot, 'typescript'),
      },
      { overrides: false },
    );
    return appDir;
  });
}
