import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { importCircles, readImportGraph } from './import-graph.js';

// No package's source imports itself in a circle (a circle makes the order modules load in
// decide whether a value is there yet, and ties files that should change apart). Type-only
// imports count too: they tie the files as much for a reader.

const root = fileURLToPath(new URL('../../', import.meta.url));

describe('the source files of the packages', () => {
  const graph = readImportGraph(root);

  it('are read with their imports', () => {
    // the walk finds the files and resolves their imports, or finding no circle would mean nothing
    expect(graph.size).toBeGreaterThan(100);
    expect(graph.get('packages/navigation/src/grid/occupancy-grid.ts')).toContain(
      'packages/navigation/src/grid/map-seeding.ts',
    );
  });

  it('import one another without a circle', () => {
    expect(importCircles(graph).map((circle) => circle.join(' <-> '))).toStrictEqual([]);
  });
});

describe('importCircles', () => {
  it('finds a circle of three files and a file that imports itself, and nothing in a chain', () => {
    const graph = new Map([
      ['a.ts', ['b.ts']],
      ['b.ts', ['c.ts']],
      ['c.ts', ['a.ts', 'd.ts']],
      ['d.ts', ['e.ts']],
      ['e.ts', []],
      ['f.ts', ['f.ts']],
    ]);
    expect(importCircles(graph)).toStrictEqual([['a.ts', 'b.ts', 'c.ts'], ['f.ts']]);
  });
});
