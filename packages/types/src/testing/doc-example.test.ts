import { describe, expect, it } from 'vitest';
import { fencedBlocks, runDocExample } from './doc-example.js';

describe('runDocExample', () => {
  it('binds named imports to the given modules and puts the scope in reach', async () => {
    const seen: unknown[] = [];
    await runDocExample(
      "import { double, half } from 'maths';\nlog(double(21), half(8));",
      { maths: { double: (n: number) => n * 2, half: (n: number) => n / 2 } },
      { log: (...values: unknown[]) => seen.push(...values) },
    );
    expect(seen).toEqual([42, 4]);
  });

  it('refuses an import of an unknown module or one it cannot bind, before running', async () => {
    const ran: string[] = [];
    const scope = { mark: (s: string) => ran.push(s) };
    await expect(
      runDocExample("import { x } from 'nowhere';\nmark('ran');", {}, scope),
    ).rejects.toThrow('the example imports nowhere, unknown to this test');
    await expect(
      runDocExample("import { triple } from 'maths';\nmark('ran');", { maths: { half: 1 } }, scope),
    ).rejects.toThrow('the example imports triple from maths, which does not export it');
    await expect(
      runDocExample("import * as m from 'maths';\nmark('ran');", { maths: {} }, scope),
    ).rejects.toThrow('cannot bind: import * as m');
    expect(ran).toEqual([]);
  });

  it('passes the example’s own failure through', async () => {
    await expect(runDocExample("throw new Error('broken example');", {})).rejects.toThrow(
      'broken example',
    );
  });
});

describe('fencedBlocks', () => {
  it('finds the blocks of one language, in order', () => {
    const markdown = '```ts\nconst a = 1;\n```\n\n```text\nout\n```\n\n```ts\nconst b = 2;\n```\n';
    expect(fencedBlocks(markdown, 'ts')).toEqual(['const a = 1;\n', 'const b = 2;\n']);
    expect(fencedBlocks(markdown, 'text')).toEqual(['out\n']);
  });
});
