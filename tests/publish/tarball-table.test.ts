// docs/cli.md tells a user which tarballs each package needs: installing a package's tarball
// without those of the @hal packages it depends on fails with E404 (npm looks them up on the
// registry). The table must list, for every package under packages/, exactly the @hal packages
// its package.json makes it need, directly or through another.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { halDependencyClosure, TARBALL_TABLE_HEADER, tarballTable } from './tarball-table.js';
import { workspacePackages } from './workspace-packages.js';

const repoRoot = fileURLToPath(new URL('../..', import.meta.url));

describe("docs/cli.md's table of the tarballs each package needs", () => {
  const packages = workspacePackages(repoRoot).filter((p) => p.manifest.private !== true);
  const needed = halDependencyClosure(packages);
  const table = tarballTable(readFileSync(`${repoRoot}/docs/cli.md`, 'utf8'), TARBALL_TABLE_HEADER);

  it('has a row for every package under packages/', () => {
    expect([...table.keys()].sort()).toEqual([...needed.keys()].sort());
  });

  it('names, for each, the @hal packages its package.json makes it need (and no other)', () => {
    for (const [name, packagesNeeded] of needed) {
      expect(table.get(name), name).toEqual(packagesNeeded);
    }
  });
});
