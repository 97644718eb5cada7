// scripts/hal.js, the `hal` of a checkout (`pnpm hal`): it runs one bundled file, rebuilt only when
// a file it was built from is newer than the bundle.
import { spawnSync } from 'node:child_process';
import {
  copyFileSync,
  mkdirSync,
  mkdtempSync,
  readFileSync,
  rmSync,
  statSync,
  symlinkSync,
  utimesSync,
} from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

const root = fileURLToPath(new URL('../../', import.meta.url));
const bundle = `${root}packages/cli/.bundle/hal.js`;
const source = `${root}packages/cli/src/io.ts`;

function hal(...args: string[]): { status: number | null; stdout: string; stderr: string } {
  return spawnSync(process.execPath, ['scripts/hal.js', ...args], {
    cwd: root,
    encoding: 'utf8',
    timeout: 60_000,
  });
}

/**
 * A fresh clone as the launcher sees one: its own scripts/hal.js and a packages/cli with no
 * bundle yet, the CLI's sources and the installed dependencies linked from this checkout.
 */
function freshClone(): string {
  const clone = mkdtempSync(join(tmpdir(), 'hal-clone-'));
  mkdirSync(join(clone, 'scripts'));
  copyFileSync(`${root}scripts/hal.js`, join(clone, 'scripts', 'hal.js'));
  mkdirSync(join(clone, 'packages', 'cli'), { recursive: true });
  for (const entry of ['src', 'package.json', 'node_modules']) {
    symlinkSync(`${root}packages/cli/${entry}`, join(clone, 'packages', 'cli', entry));
  }
  symlinkSync(`${root}node_modules`, join(clone, 'node_modules'));
  return clone;
}

describe('the checkout launcher (scripts/hal.js)', () => {
  it('is what the root "pnpm hal" script runs', () => {
    const manifest = JSON.parse(readFileSync(`${root}package.json`, 'utf8')) as {
      scripts: Record<string, string>;
    };
    expect(manifest.scripts['hal']).toBe('node scripts/hal.js');
  });

  it('runs the CLI with its arguments and exit code', () => {
    const help = hal('--help');
    expect(help.status, help.stderr).toBe(0);
    expect(help.stdout).toContain('Usage: hal');
    const status = hal('--json', 'status', '--sim');
    expect(status.status, status.stderr).toBe(0);
    expect(JSON.parse(status.stdout.split('\n')[0]!)).toMatchObject({
      device: { mode: 'simulation' },
    });
    expect(hal('drive', 'forward', 'far', '--sim').status).toBe(2);
  });

  it("says a fresh clone's first run is the first build, and bundles only then", () => {
    const clone = freshClone();
    try {
      const run = () =>
        spawnSync(process.execPath, [join(clone, 'scripts', 'hal.js'), '--version'], {
          encoding: 'utf8',
          timeout: 60_000,
        });
      const first = run();
      expect(first.status, first.stderr).toBe(0);
      expect(first.stderr).toBe(
        'hal: bundling packages/cli (the first build: there is no bundle yet)\n',
      );
      const second = run();
      expect(second.status, second.stderr).toBe(0);
      expect(second.stderr).toBe('');
      expect(second.stdout).toBe(first.stdout);
    } finally {
      rmSync(clone, { recursive: true, force: true });
    }
  });

  it('says to install first in a clone with no node_modules, in one line, instead of a stack trace', () => {
    const clone = mkdtempSync(join(tmpdir(), 'hal-bare-clone-'));
    try {
      mkdirSync(join(clone, 'scripts'));
      copyFileSync(`${root}scripts/hal.js`, join(clone, 'scripts', 'hal.js'));
      const run = spawnSync(process.execPath, [join(clone, 'scripts', 'hal.js'), '--version'], {
        encoding: 'utf8',
        timeout: 60_000,
      });
      expect(run.status).toBe(1);
      expect(run.stderr).toBe(
        'hal: bundling packages/cli (the first build: there is no bundle yet)\n' +
          'hal: FAILED: this checkout has no node_modules (esbuild is missing): run `bash scripts/setup.sh` (or `pnpm install`) first\n',
      );
    } finally {
      rmSync(clone, { recursive: true, force: true });
    }
  });

  it('reuses a fresh bundle and rebuilds it once a source is newer', () => {
    expect(hal('--version').status).toBe(0);
    const before = statSync(bundle).mtimeMs;
    const again = hal('--version');
    expect(again.stderr).not.toContain('bundling');
    expect(statSync(bundle).mtimeMs).toBe(before);

    const original = statSync(source);
    const now = Date.now() / 1000;
    utimesSync(bundle, now - 20, now - 20);
    utimesSync(source, original.atime, now - 10);
    try {
      const rebuilt = hal('--version');
      expect(rebuilt.status, rebuilt.stderr).toBe(0);
      // io.ts, or a source someone saved meanwhile: the reason names the file
      expect(rebuilt.stderr).toMatch(
        /^hal: bundling packages\/cli \(packages\/\S+ changed since the last build\)$/m,
      );
      expect(statSync(bundle).mtimeMs).toBeGreaterThan((now - 10) * 1000);
    } finally {
      utimesSync(source, original.atime, original.mtime);
    }
  });
});
