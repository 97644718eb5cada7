// CONTRIBUTING.md and tests/README.md, held to the repository the way tests/docs holds README.md
// and docs/*.md: their shell blocks run as written from the repository root, or carry a
// `<!-- not run: REASON -->` marker (a "covered by" reason names test files that exist; one
// covered by tests/docs/doc-commands.test.ts is made of lines a doc block runs), every path they
// name in code exists, each recipe names the test in tests/contributing/ that walks it through
// (and every test there is named), and the README links CONTRIBUTING.md.
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { blockScript } from '../docs/block-script.js';
import { fences } from '../docs/fences.js';
import { commandLines, shellBlocks } from '../docs/shell-blocks.js';
import type { ShellBlock } from '../docs/shell-blocks.js';
import { runProcess } from '../helpers/run-process.js';

const root = fileURLToPath(new URL('../../', import.meta.url));
const read = (path: string): string => readFileSync(`${root}${path}`, 'utf8');
const DOCS = ['CONTRIBUTING.md', 'tests/README.md'] as const;

const scanned = DOCS.map((file) => shellBlocks(read(file), file));
const blocks = scanned.flatMap((s) => s.blocks);
const runnable = blocks.filter((b) => b.notRun === undefined);
const notRun = blocks.filter((b) => b.notRun !== undefined);

/** The command lines README.md's and docs/*.md's runnable blocks run. */
function docCommandLines(): Set<string> {
  const files = [
    'README.md',
    ...readdirSync(`${root}docs`)
      .filter((f) => f.endsWith('.md'))
      .map((f) => `docs/${f}`),
  ];
  return new Set(
    files
      .flatMap((file) => shellBlocks(read(file), file).blocks)
      .filter((b) => b.notRun === undefined)
      .flatMap((b) => commandLines(b)),
  );
}

/** The paths a Markdown file names in inline code outside its fenced blocks. */
function namedPaths(markdown: string): string[] {
  const lines = markdown.split('\n');
  const fenced = new Set<number>();
  for (const { open, end } of fences(lines)) for (let i = open; i <= end; i += 1) fenced.add(i);
  const paths = new Set<string>();
  lines.forEach((line, i) => {
    if (fenced.has(i)) return;
    for (const match of line.matchAll(/`([^`\s]+)`/g)) {
      const token = match[1]!;
      // a path of the repository: folders and a file, not a package name (@hal/...) or a glob
      if (/^(?:[\w.-]+\/)+[\w.-]*$/.test(token) && !token.startsWith('@')) paths.add(token);
    }
  });
  return [...paths];
}

/** The recipes: CONTRIBUTING.md's `## Add ...` sections, with their text. */
function recipes(): { title: string; text: string }[] {
  const sections = read('CONTRIBUTING.md').split(/^## /m).slice(1);
  return sections
    .map((s) => ({ title: s.split('\n', 1)[0]!, text: s }))
    .filter((s) => s.title.startsWith('Add '));
}

describe('the shell blocks of CONTRIBUTING.md and tests/README.md', () => {
  it('are found, and every marker is on the line before a shell fence', () => {
    expect(blocks.length).toBeGreaterThan(5);
    expect(runnable.length).toBeGreaterThan(1);
    expect(scanned.flatMap((s) => s.misplaced)).toEqual([]);
  });

  describe.each(notRun)('$file:$line', (block: ShellBlock) => {
    it(`is not run: ${block.notRun}`, () => {
      const reason = block.notRun ?? '';
      expect(reason.length, 'the reason says why').toBeGreaterThan(10);
      if (!/\bcovered by\b/i.test(reason)) return;
      const named = [...reason.matchAll(/[\w.-]+(?:\/[\w.*-]+)+/g)].map((m) => m[0]);
      expect(named, 'a "covered by" marker names the test file').not.toEqual([]);
      for (const path of named) expect(existsSync(`${root}${path}`), `${path} exists`).toBe(true);
      if (named.includes('tests/docs/doc-commands.test.ts')) {
        const run = docCommandLines();
        for (const line of commandLines(block)) {
          expect(run.has(line), `a runnable block of README.md or docs/*.md runs: ${line}`).toBe(
            true,
          );
        }
      }
      // a block covered by the test files it runs: its command runs exactly those files
      for (const line of commandLines(block).filter((l) => l.startsWith('npx vitest run '))) {
        for (const file of line.replace(/\\\n/g, ' ').split(/\s+/).slice(3)) {
          expect(existsSync(`${root}${file}`), `${file}, which the block runs, exists`).toBe(true);
        }
      }
    });
  });

  // one at a time: a block may run vitest, and the machine's cores are shared
  it.each(runnable)(
    'run as written: $file:$line',
    async (block) => {
      const env: NodeJS.ProcessEnv = { NO_COLOR: '1' };
      for (const [name, value] of Object.entries(process.env)) {
        // the block runs as a contributor's shell would: not inside this test's vitest worker
        if (!/^(VITEST|TINYPOOL|NODE_OPTIONS$|HAL_|OPENAI_)/.test(name)) env[name] = value;
      }
      const run = await runProcess('bash', ['-c', blockScript(block)], {
        cwd: root,
        env,
        timeoutMs: 240_000,
      });
      expect(
        run.status,
        `${block.file}:${block.line} failed:\n${block.text}\n--- output ---\n${(run.stdout + run.stderr).slice(-6000)}`,
      ).toBe(0);
    },
    250_000,
  );
});

describe('CONTRIBUTING.md and tests/README.md name what exists', () => {
  it.each(DOCS)('every path %s names in code is in the repository', (file) => {
    const paths = namedPaths(read(file));
    expect(paths.length).toBeGreaterThan(5);
    const missing = paths.filter((path) => !existsSync(`${root}${path}`));
    expect(missing, `${file} names paths that do not exist`).toEqual([]);
  });

  it('each recipe names the test that walks it through, and every such test is named', () => {
    const list = recipes();
    expect(list.map((r) => r.title)).toEqual([
      'Add a HAL call',
      'Add a transport',
      'Add a skill',
      'Add an eval task',
      'Add a firmware command',
      'Add a robot setting',
    ]);
    const named = new Set<string>();
    for (const recipe of list) {
      const tests = [...recipe.text.matchAll(/`(tests\/contributing\/[\w-]+\.test\.ts)`/g)].map(
        (m) => m[1]!,
      );
      expect(tests, `"${recipe.title}" names its test in tests/contributing/`).not.toEqual([]);
      for (const test of tests) named.add(test);
    }
    const present = readdirSync(`${root}tests/contributing`)
      .filter((f) => f.endsWith('.test.ts') && f !== 'contributing-doc.test.ts')
      .map((f) => `tests/contributing/${f}`);
    expect([...named].sort()).toEqual(present.sort());
  });

  it("is linked from the README's documentation list", () => {
    const list =
      read('README.md')
        .split(/^## Documentation$/m)[1]
        ?.split(/^## /m)[0] ?? '';
    expect(list).toMatch(/^- \[[^\]]+\]\(CONTRIBUTING\.md\)/m);
  });
});
