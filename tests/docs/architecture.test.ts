import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { drawnArrows, packageNames, section, tableRows } from './doc-graph.js';
import { findCircle, reachable, readPackageGraph } from './package-graph.js';
import type { PackageGraph } from './package-graph.js';

// The README's package drawing and docs/architecture.md's drawing and package table against the
// packages' own package.json dependencies, so the docs cannot drift from the code: every package
// under packages/ is in each of them, every arrow drawn is a real dependency, and every real one
// is drawn (directly, or through the packages it depends on: the drawings leave out what a
// dependency already brings).

const root = fileURLToPath(new URL('../../', import.meta.url));
const read = (file: string) => readFileSync(`${root}${file}`, 'utf8');
const code = readPackageGraph(root);
const packages = [...code.keys()].sort();

function expectDrawingFollowsCode(drawing: PackageGraph): void {
  expect([...drawing.keys()].sort(), 'the packages drawn').toStrictEqual(packages);
  for (const [name, deps] of drawing) {
    for (const dep of deps) {
      expect(code.get(name)?.has(dep), `${name} -> ${dep}: not a dependency of ${name}`).toBe(true);
    }
    expect(
      [...reachable(drawing, name)].sort(),
      `what ${name} reaches in the drawing`,
    ).toStrictEqual([...reachable(code, name)].sort());
  }
}

describe('the packages', () => {
  it('depend on one another without a circle', () => {
    expect(packages.length).toBeGreaterThan(1);
    expect(findCircle(code)).toBeUndefined();
  });
});

describe("the README's Packages section", () => {
  const lines = section(read('README.md'), 'Packages');

  it('draws every package and exactly the dependencies the code has', () => {
    expectDrawingFollowsCode(drawnArrows(lines));
  });

  it('has a table row for every package', () => {
    const rows = tableRows(lines, ['package', 'what it gives you']);
    expect(rows.map((row) => packageNames(row[0] ?? '')[0]).sort()).toStrictEqual(packages);
  });
});

describe("docs/architecture.md's Packages section", () => {
  const lines = section(read('docs/architecture.md'), 'Packages');

  it('draws every package and exactly the dependencies the code has', () => {
    expectDrawingFollowsCode(drawnArrows(lines));
  });

  it('lists every package with each of its dependencies on another package, and no other', () => {
    const rows = tableRows(lines, ['package', 'owns', 'depends on']);
    const listed = new Map(
      rows.map((row) => [
        packageNames(row[0] ?? '')[0] ?? row[0],
        new Set(packageNames(row[2] ?? '')),
      ]),
    );
    expect([...listed.keys()].sort(), 'the packages in the table').toStrictEqual(packages);
    for (const [name, deps] of code) {
      expect([...(listed.get(name) ?? [])].sort(), `${name}'s "depends on"`).toStrictEqual(
        [...deps].sort(),
      );
    }
  });
});
